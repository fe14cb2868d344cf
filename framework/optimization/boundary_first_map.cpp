#include "framework/optimization/boundary_first_map.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <numbers>

#include "framework/mesh/plane_geometry.h"

namespace akvf {

Eigen::MatrixXd boundary_first_map(const TriMesh& mesh, const std::vector<int>& boundary_loop,
                                   const SpdSolver& solver) {
  constexpr double pi = std::numbers::pi;
  const int n = mesh.num_vertices();
  const int m = static_cast<int>(boundary_loop.size());
  if (m < 3) return {};
  const Eigen::VectorXd angle_sum = vertex_angle_sums(mesh);

  // 1. u: L_II u_I = -K_I (K = 2 pi - the angle sum), u_B = 0.
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(n, 1), defect = (angle_sum.array() - 2 * pi).matrix();
  InteriorLaplacian laplacian(mesh, boundary_loop, TutteWeights::kCotangent, solver);
  if (!laplacian.solve(defect, &u)) return {};
  const Eigen::VectorXd Lu = laplacian.apply(u).col(0);

  // 2-3. The curve: edge i from loop[i] to loop[i + 1], turning by kappa~ at
  // each vertex after the first.
  Eigen::VectorXd length(m);
  Eigen::Matrix2Xd tangent(2, m);
  double heading = 0;
  for (int i = 0; i < m; ++i) {
    const int v = boundary_loop[static_cast<std::size_t>(i)];
    const int next = boundary_loop[static_cast<std::size_t>((i + 1) % m)];
    if (i > 0) heading += (pi - angle_sum[v]) + Lu[v];
    length[i] = (mesh.V.row(next) - mesh.V.row(v)).norm();
    tangent.col(i) << std::cos(heading), std::sin(heading);
  }
  // Closed by l~ = l - diag(l) T^T lambda, (T diag(l) T^T) lambda = T l.
  const Eigen::Matrix2d gram = tangent * length.asDiagonal() * tangent.transpose();
  const Eigen::Vector2d lambda = gram.ldlt().solve(tangent * length);
  const Eigen::VectorXd closed = length - length.cwiseProduct(tangent.transpose() * lambda);
  if (!(closed.array() > 0).all()) return {};

  Eigen::MatrixXd UV = Eigen::MatrixXd::Zero(n, 2);
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  for (int i = 0; i < m; ++i) {
    UV.row(boundary_loop[static_cast<std::size_t>(i)]) = point.transpose();
    point += closed[i] * tangent.col(i);
  }

  // 4. The interior: L_II X_I = -L_IB X_B.
  if (!laplacian.solve({}, &UV)) return {};

  // The faces' orientation: a loop run clockwise round them gives the
  // mirror image.
  double signed_area = 0;
  for (int f = 0; f < mesh.num_faces(); ++f) signed_area += twice_signed_area(mesh.F, UV, f);
  if (signed_area < 0) UV.col(0) = -UV.col(0);
  return UV;
}

}  // namespace akvf
