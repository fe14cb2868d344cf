#pragma once
// Several charts (the components of a cut mesh, cut_to_disk.h) in one UV
// plane: per-chart Tutte maps, and the charts placed side by side.
#include <Eigen/Core>
#include <vector>

#include "akvf/mesh.h"
#include "framework/mesh/initialization.h"

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
// layout), with a gap of 2 % of that width between boxes. The charts keep
// their scale and orientation. No-op for one chart.
void pack_charts(const Eigen::MatrixXi& F, const std::vector<int>& face_chart, int num_charts, Eigen::MatrixXd* UV);

}  // namespace akvf
