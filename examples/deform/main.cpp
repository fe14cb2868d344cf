// Deform a tet grid: bottom fixed, top lifted by 20 % and turned, with soft
// positional constraints (w = 1e5), through akvf::deform.
#include <akvf/akvf.h>

#include <Eigen/Geometry>
#include <iostream>

namespace {

// The unit cube in n^3 cells of 6 positively oriented tets each.
void tet_grid(int n, Eigen::MatrixXd* V, Eigen::MatrixXi* T) {
  const int m = n + 1;
  V->resize(m * m * m, 3);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) V->row((k * m + j) * m + i) << double(i) / n, double(j) / n, double(k) / n;
  T->resize(6 * n * n * n, 4);
  const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  int t = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& path : paths) {  // Kuhn triangulation: a path from corner 000 to 111
          int c[3] = {i, j, k}, corners[4];
          corners[0] = (c[2] * m + c[1]) * m + c[0];
          for (int s = 0; s < 3; ++s) {
            ++c[path[s]];
            corners[s + 1] = (c[2] * m + c[1]) * m + c[0];
          }
          T->row(t) << corners[0], corners[1], corners[2], corners[3];
          const Eigen::Vector3d a = V->row(corners[0]), b = V->row(corners[1]), d = V->row(corners[2]),
                                e = V->row(corners[3]);
          if ((b - a).dot((d - a).cross(e - a)) < 0) T->row(t) << corners[0], corners[2], corners[1], corners[3];
          ++t;
        }
}

}  // namespace

int main() try {
  Eigen::MatrixXd V;
  Eigen::MatrixXi T;
  tet_grid(4, &V, &T);
  akvf::PositionConstraints constraints;
  std::vector<Eigen::RowVector3d> targets;
  for (int v = 0; v < V.rows(); ++v) {
    const double z = V(v, 2);
    if (z != 0 && z != 1) continue;
    const Eigen::Vector3d centred(V(v, 0) - 0.5, V(v, 1) - 0.5, 0);
    constraints.vertices.push_back(v);
    targets.push_back((Eigen::AngleAxisd(0.4 * z, Eigen::Vector3d::UnitZ()) * centred).transpose() +
                      Eigen::RowVector3d(0.5, 0.5, 1.2 * z));
  }
  constraints.targets.resize(static_cast<Eigen::Index>(targets.size()), 3);
  for (std::size_t c = 0; c < targets.size(); ++c) constraints.targets.row(c) = targets[c];

  akvf::DeformOptions options;
  options.max_iters = 50;
  const akvf::DeformResult result = akvf::deform(V, T, constraints, options);
  int max_flips = 0;
  for (const akvf::IterationSummary& row : result.trace) max_flips = std::max(max_flips, row.flips);
  std::cout << akvf::to_string(result.status) << " after " << result.iterations() << " iterations: energy "
            << result.trace.front().energy << " -> " << result.energy()
            << ", top centre at z = " << result.x.col(2).maxCoeff() << ", " << max_flips
            << " inverted tets at any iterate\n";
  return akvf::is_normal_termination(result.status) && max_flips == 0 && result.energy() < result.trace.front().energy
             ? 0
             : 1;
} catch (const akvf::Error& e) {
  std::cerr << "error: " << e.what() << '\n';
  return 1;
}
