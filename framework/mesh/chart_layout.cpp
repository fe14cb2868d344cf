#include "framework/mesh/chart_layout.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace akvf {

namespace {

// Vertex lists of the charts, each in increasing order.
std::vector<std::vector<int>> chart_vertices(const Eigen::MatrixXi& F, const std::vector<int>& face_chart,
                                             int num_charts, int num_vertices) {
  std::vector<int> chart_of(num_vertices, -1);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) chart_of[F(f, k)] = face_chart[f];
  std::vector<std::vector<int>> vertices(num_charts);
  for (int v = 0; v < num_vertices; ++v)
    if (chart_of[v] >= 0) vertices[chart_of[v]].push_back(v);
  return vertices;
}

}  // namespace

Eigen::MatrixXd tutte_embedding_charts(const TriMesh& mesh, const std::vector<std::vector<int>>& boundary_loops,
                                       const std::vector<int>& face_chart, TutteWeights weights, Warnings* warnings,
                                       const SpdSolver& solver) {
  const int charts = static_cast<int>(boundary_loops.size());
  if (charts == 1) return tutte_embedding(mesh, boundary_loops[0], weights, warnings, solver);
  const std::vector<std::vector<int>> vertices = chart_vertices(mesh.F, face_chart, charts, mesh.num_vertices());
  std::vector<std::vector<int>> faces(charts);
  for (int f = 0; f < mesh.num_faces(); ++f) faces[face_chart[f]].push_back(f);
  Eigen::MatrixXd UV = Eigen::MatrixXd::Zero(mesh.num_vertices(), 2);
  std::vector<int> local(mesh.num_vertices(), -1);
  for (int c = 0; c < charts; ++c) {
    TriMesh chart;
    chart.V.resize(static_cast<Eigen::Index>(vertices[c].size()), 3);
    for (std::size_t i = 0; i < vertices[c].size(); ++i) {
      local[vertices[c][i]] = static_cast<int>(i);
      chart.V.row(i) = mesh.V.row(vertices[c][i]);
    }
    chart.F.resize(static_cast<Eigen::Index>(faces[c].size()), 3);
    for (std::size_t row = 0; row < faces[c].size(); ++row)
      chart.F.row(row) = mesh.F.row(faces[c][row]).unaryExpr([&](int v) { return local[v]; });
    std::vector<int> loop(boundary_loops[c].size());
    std::transform(boundary_loops[c].begin(), boundary_loops[c].end(), loop.begin(), [&](int v) { return local[v]; });
    // The solver sees the whole mesh's vertices (an ordering may be of those).
    const SpdSolver chart_solver = !solver ? SpdSolver{}
                                           : [&](const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B,
                                                 const std::vector<int>& chart_vertices, Eigen::MatrixXd* X) {
                                               std::vector<int> mesh_vertices(chart_vertices.size());
                                               for (std::size_t i = 0; i < chart_vertices.size(); ++i)
                                                 mesh_vertices[i] = vertices[c][chart_vertices[i]];
                                               return solver(A, B, mesh_vertices, X);
                                             };
    const Eigen::MatrixXd chart_uv = tutte_embedding(chart, loop, weights, warnings, chart_solver);
    for (std::size_t i = 0; i < vertices[c].size(); ++i) UV.row(vertices[c][i]) = chart_uv.row(i);
  }
  pack_charts(mesh.F, face_chart, charts, &UV);
  return UV;
}

void pack_charts(const Eigen::MatrixXi& F, const std::vector<int>& face_chart, int num_charts, Eigen::MatrixXd* UV) {
  if (num_charts <= 1) return;
  const std::vector<std::vector<int>> vertices =
      chart_vertices(F, face_chart, num_charts, static_cast<int>(UV->rows()));
  std::vector<Eigen::RowVector2d> low(num_charts), size(num_charts);
  double box_area = 0;
  for (int c = 0; c < num_charts; ++c) {
    Eigen::RowVector2d lo = UV->row(vertices[c].front()), hi = lo;
    for (int v : vertices[c]) {
      lo = lo.cwiseMin(UV->row(v));
      hi = hi.cwiseMax(UV->row(v));
    }
    low[c] = lo;
    size[c] = hi - lo;
    box_area += size[c].x() * size[c].y();
  }
  double row_width = std::sqrt(box_area);
  for (int c = 0; c < num_charts; ++c) row_width = std::max(row_width, size[c].x());
  const double gap = 0.02 * std::sqrt(box_area);
  std::vector<int> order(num_charts);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return size[a].y() > size[b].y(); });
  double x = 0, y = 0, row_height = 0;
  for (int c : order) {
    if (x > 0 && x + size[c].x() > row_width) {  // start a new row above
      x = 0;
      y += row_height + gap;
      row_height = 0;
    }
    const Eigen::RowVector2d shift = Eigen::RowVector2d(x, y) - low[c];
    for (int v : vertices[c]) UV->row(v) += shift;
    x += size[c].x() + gap;
    row_height = std::max(row_height, size[c].y());
  }
}

}  // namespace akvf
