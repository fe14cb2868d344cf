#include "framework/optimization/boundary_first_map.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <optional>

namespace akvf {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The cotangent Laplacian L (L_ij = -(cot alpha_ij + cot beta_ij) / 2, rows
// summing to 0) and each vertex's sum of corner angles, from the rest
// positions.
void cotangent_laplacian(const TriMesh& mesh, Eigen::SparseMatrix<double>* L, Eigen::VectorXd* angle_sum) {
  const int n = mesh.num_vertices();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(mesh.F.rows()) * 12);
  *angle_sum = Eigen::VectorXd::Zero(n);
  for (int f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3), c = mesh.F(f, (k + 2) % 3);
      const Eigen::Vector3d e1 = mesh.V.row(b) - mesh.V.row(a), e2 = mesh.V.row(c) - mesh.V.row(a);
      const double cross = e1.cross(e2).norm(), dot = e1.dot(e2);
      (*angle_sum)[a] += std::atan2(cross, dot);
      const double w = 0.5 * dot / cross;  // half the cotangent of the corner at a, on edge (b, c)
      entries.emplace_back(b, c, -w);
      entries.emplace_back(c, b, -w);
      entries.emplace_back(b, b, w);
      entries.emplace_back(c, c, w);
    }
  L->resize(n, n);
  L->setFromTriplets(entries.begin(), entries.end());
}

}  // namespace

Eigen::MatrixXd boundary_first_map(const TriMesh& mesh, const std::vector<int>& boundary_loop,
                                   const SpdSolver& solver) {
  const int n = mesh.num_vertices();
  const int m = static_cast<int>(boundary_loop.size());
  if (m < 3) return {};
  Eigen::SparseMatrix<double> L;
  Eigen::VectorXd angle_sum;
  cotangent_laplacian(mesh, &L, &angle_sum);

  // Interior vertices numbered 0.. in order; boundary ones -1.
  std::vector<int> interior(static_cast<std::size_t>(n), 0);
  for (int v : boundary_loop) interior[static_cast<std::size_t>(v)] = -1;
  int count = 0;
  for (int& i : interior)
    if (i == 0) i = count++;
  std::vector<Eigen::Triplet<double>> inner;
  for (int column = 0; column < L.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator it(L, column); it; ++it) {
      const int r = interior[static_cast<std::size_t>(it.row())], c = interior[static_cast<std::size_t>(column)];
      if (r >= 0 && c >= 0) inner.emplace_back(r, c, it.value());
    }
  Eigen::SparseMatrix<double> L_II(count, count);
  L_II.setFromTriplets(inner.begin(), inner.end());
  std::vector<int> interior_vertices;
  interior_vertices.reserve(static_cast<std::size_t>(count));
  for (int v = 0; v < n; ++v)
    if (interior[static_cast<std::size_t>(v)] >= 0) interior_vertices.push_back(v);
  // L_II X = B by the caller's solver, else (or where it fails) Eigen's
  // simplicial L D L^T, as the Tutte solve does, factored once for both
  // systems.
  std::optional<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> ldlt;
  const auto solve = [&](const Eigen::MatrixXd& B, Eigen::MatrixXd* X) {
    if (!ldlt && solver && solver(L_II, B, interior_vertices, X)) return true;
    if (!ldlt) ldlt.emplace(L_II);
    if (ldlt->info() != Eigen::Success || !(ldlt->vectorD().array() > 0).all()) return false;
    *X = ldlt->solve(B);
    return true;
  };

  // 1. u: L_II u_I = -K_I, K = 2 pi - the angle sum.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  if (count > 0) {
    Eigen::MatrixXd defect(count, 1), u_interior;
    for (int i = 0; i < count; ++i) defect(i, 0) = angle_sum[interior_vertices[static_cast<std::size_t>(i)]] - 2 * kPi;
    if (!solve(defect, &u_interior)) return {};
    for (int i = 0; i < count; ++i) u[interior_vertices[static_cast<std::size_t>(i)]] = u_interior(i, 0);
  }
  const Eigen::VectorXd Lu = L * u;

  // 2-3. The curve: edge i from loop[i] to loop[i + 1], turning by kappa~ at
  // each vertex after the first.
  Eigen::VectorXd length(m);
  Eigen::Matrix2Xd tangent(2, m);
  double heading = 0;
  for (int i = 0; i < m; ++i) {
    const int v = boundary_loop[static_cast<std::size_t>(i)];
    const int next = boundary_loop[static_cast<std::size_t>((i + 1) % m)];
    if (i > 0) heading += (kPi - angle_sum[v]) + Lu[v];
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
  if (count > 0) {
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(count, 2), inside;
    for (int column = 0; column < L.outerSize(); ++column) {
      if (interior[static_cast<std::size_t>(column)] >= 0) continue;
      for (Eigen::SparseMatrix<double>::InnerIterator it(L, column); it; ++it)
        if (const int r = interior[static_cast<std::size_t>(it.row())]; r >= 0)
          rhs.row(r) -= it.value() * UV.row(column);
    }
    if (!solve(rhs, &inside)) return {};
    for (int i = 0; i < count; ++i) UV.row(interior_vertices[static_cast<std::size_t>(i)]) = inside.row(i);
  }

  // The faces' orientation: a loop run clockwise round them gives the
  // mirror image.
  double signed_area = 0;
  for (int f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::RowVector2d a = UV.row(mesh.F(f, 0)), b = UV.row(mesh.F(f, 1)), c = UV.row(mesh.F(f, 2));
    signed_area += (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  }
  if (signed_area < 0) UV.col(0) = -UV.col(0);
  if (!UV.allFinite()) return {};  // a degenerate rest triangle's cotangent, or a curve with no closing
  return UV;
}

}  // namespace akvf
