#pragma once
// Charts packed on a grid of square cells so that they interlock where their
// shapes allow (the brute-force placement xatlas and Blender use): each
// chart takes every cell its triangles touch, and goes where those cells
// grown by a ring of cells (the gap between charts) are free; largest chart
// first, each goes to the first free
// place in row-major order (lowest row, then leftmost) of an atlas of a
// fixed width, or, in a last trial, inside the square around the charts
// placed so far if it fits, else where it grows that square least; turned
// by whichever of its candidate angles keeps the square smallest, then ends
// lowest. Of five atlas widths and the growing square, the smallest square
// wins.
#include <Eigen/Core>
#include <vector>

namespace akvf {

// How one chart moves: uv -> R(angle) uv + offset.
struct ChartPlacement {
  double angle = 0;
  Eigen::RowVector2d offset = Eigen::RowVector2d::Zero();
};

// The grid's cells: kFine, about 1024 per chart (32 across, so that a ring
// of cells around it costs a chart about an eighth of its area), at least
// 2^18 and at most 2^19 in all; kCoarse, a quarter as many (several times
// faster, to compare layouts).
enum class PackingGrid { kCoarse, kFine };

// chart_faces[c]: the rows of F in chart c; UV: the charts as they are (their
// scale is kept); angles[c]: the turns chart c may take (at least one). The gap grows to more cells where one cell
// would leave charts closer than least_gap (UV's units). Returns the side of the square the placed charts fit in, each
// chart's placement and, if asked, the least distance between charts the grid guarantees.
double raster_pack(const Eigen::MatrixXi& F, const std::vector<std::vector<int>>& chart_faces,
                   const Eigen::MatrixXd& UV, const std::vector<std::vector<double>>& angles, double least_gap,
                   std::vector<ChartPlacement>* placement, double* gap = nullptr,
                   PackingGrid grid = PackingGrid::kFine);

// UV after `placement` (the vertices of chart c are those of its faces).
void apply_placement(const Eigen::MatrixXi& F, const std::vector<std::vector<int>>& chart_faces,
                     const std::vector<ChartPlacement>& placement, Eigen::MatrixXd* UV);

}  // namespace akvf
