#pragma once
// Charts split for packing: a chart that branches (legs, fingers) leaves
// most of its bounding square empty, which no rigid packing fills. A
// straight cut across it, along the map's own edges, gives pieces that pack
// closer; the map itself, and so every triangle's distortion, is unchanged.
#include <Eigen/Core>
#include <functional>
#include <vector>

namespace akvf {

// Per chart, the area of its convex hull in UV less its own: what it leaves
// empty however it is packed.
std::vector<double> chart_waste(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, const std::vector<int>& face_chart,
                                int num_charts);

// Per chart, its area in UV.
std::vector<double> chart_areas(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, const std::vector<int>& face_chart,
                                int num_charts);

// A refinement of face_chart: chart `chart` in pieces, the others kept
// (numbered as before; new pieces after them).
struct ChartSplit {
  std::vector<int> face_chart;
  int num_charts = 0;
  double waste = 0;  // the pieces' chart_waste, summed
  double rank = 0;   // what straight_splits ranked it by: less is better
};

// How straight_splits ranks the cuts: by the pieces' waste alone, or by
// their waste plus the difference between the largest and the smallest
// piece's area (both areas), so that among cuts of a convex chart, which
// all waste nothing, the one through its middle comes first.
enum class SplitRank { kLeastWaste, kEvenPieces };

// Of the straight lines across chart `chart` (16 directions, 15 offsets
// each between the extremes of its faces' centroids), the `count` that rank
// first, best first: the faces on each side (by centroid),
// each connected set of them across shared edges a piece. Only splits whose
// pieces are all disks (Euler characteristic 1) and that `accept` takes
// count. F is the cut mesh's (charts share no vertex), UV one row per
// vertex.
std::vector<ChartSplit> straight_splits(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV,
                                        const std::vector<int>& face_chart, int num_charts, int chart, int count,
                                        const std::function<bool(const ChartSplit&)>& accept,
                                        SplitRank rank = SplitRank::kLeastWaste);

}  // namespace akvf
