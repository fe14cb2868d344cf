#pragma once
// Several charts (the components of a cut mesh, cut_to_disk.h) in one UV
// plane: per-chart Tutte maps, and the charts placed side by side.
#include <Eigen/Core>
#include <vector>

#include "akvf/mesh.h"
#include "framework/mesh/initialization.h"
#include "framework/mesh/raster_packing.h"

namespace akvf {

// The Tutte embedding of every chart (faces with face_chart[f] == c, whose
// boundary loop is boundary_loops[c]) on a circle of the chart's area, the
// charts then packed side by side (pack_charts). One chart: tutte_embedding.
// `solver` as there.
Eigen::MatrixXd tutte_embedding_charts(const TriMesh& mesh, const std::vector<std::vector<int>>& boundary_loops,
                                       const std::vector<int>& face_chart, TutteWeights weights, Warnings* warnings,
                                       const SpdSolver& solver = {});

// Translates every chart of UV (#V by 2) so that their bounding boxes do not
// overlap: rows of charts, tallest first, each row at most as wide as the
// square root of the charts' total bounding-box area (a roughly square
// layout), with a gap of 2 % of that width between boxes. With
// `rotate_to_boxes` (the outputs), the gap is the gutter alone, each chart
// is first turned (a rotation, never a mirror) to its smallest bounding
// rectangle, lying flat (wider than tall), and the row width is the one, of
// 33 from the widest chart to all in one row, whose layout fits the
// smallest square; then, if charts that
// interlock (raster_packing.h; every chart flat or every chart turned to its
// smallest bounding square, each then by any number of quarter turns; on
// `grid`'s cells) fit a smaller square,
// they are placed so instead; on the fine grid, if they then cover less
// than `min_coverage` of the square, also the flat charts by any number of
// eighth turns. Charts end at least `gutter` times the side of
// the square around them apart (the texture's gutter: texels over its size).
// The charts keep their scale. One chart is only turned, to its smallest
// bounding square (with `rotate_to_boxes`).
void pack_charts(const Eigen::MatrixXi& F, const std::vector<int>& face_chart, int num_charts, Eigen::MatrixXd* UV,
                 bool rotate_to_boxes = false, double gutter = 0, PackingGrid grid = PackingGrid::kFine,
                 double min_coverage = 0);

// The fraction of the square around UV's bounding box (side: its longer
// extent; the unit square once the map is scaled into it) that the triangles
// F cover.
double square_coverage(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV);

}  // namespace akvf
