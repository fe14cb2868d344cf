#include "framework/optimization/conformal_map.h"

#include <Eigen/SparseCholesky>
#include <array>

#include "framework/optimization/element_matrix.h"

namespace akvf {

namespace {

// The vertex of the loop farthest at rest from `point`.
int farthest_on_loop(const TriMesh& mesh, const std::vector<int>& loop, const Eigen::RowVector3d& point) {
  int farthest = loop.front();
  double distance = -1;
  for (int v : loop) {
    const double d = (mesh.V.row(v) - point).squaredNorm();
    if (d > distance) {
      distance = d;
      farthest = v;
    }
  }
  return farthest;
}

// The loop's centroid as a curve (each vertex weighted by half its two
// edges' lengths): it does not depend on where the loop starts.
Eigen::RowVector3d loop_centroid(const TriMesh& mesh, const std::vector<int>& loop) {
  Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
  double length = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Eigen::RowVector3d p = mesh.V.row(loop[i]), q = mesh.V.row(loop[(i + 1) % loop.size()]);
    const double edge = (q - p).norm();
    sum += 0.5 * edge * (p + q);
    length += edge;
  }
  return length > 0 ? Eigen::RowVector3d(sum / length) : Eigen::RowVector3d(mesh.V.row(loop.front()));
}

// A_f M^T M with M z = grad v - R grad u (z = u0 v0 u1 v1 u2 v2): the
// Hessian of face f's conformal energy.
void conformal_local(const RestTriangles& rest, int f, ElementMatrix2D::Local* local) {
  // Hat gradients: grad u = Dm^-T [u1 - u0, u2 - u0].
  const Eigen::Matrix2d T = rest.Dm_inv[f].transpose();
  const std::array<Eigen::Vector2d, 3> hat = {-T.col(0) - T.col(1), T.col(0), T.col(1)};
  Eigen::Matrix<double, 2, 6> M;
  for (int k = 0; k < 3; ++k) {
    M.col(2 * k) << hat[k].y(), -hat[k].x();  // -R hat: R (x, y) = (-y, x)
    M.col(2 * k + 1) = hat[k];
  }
  *local = rest.area[f] * M.transpose() * M;
}

bool solve_by_eigen(const Eigen::SparseMatrix<double>& upper, const Eigen::VectorXd& b, Eigen::VectorXd* x) {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper> ldlt(upper);
  if (ldlt.info() != Eigen::Success) return false;
  *x = ldlt.solve(b);
  return ldlt.info() == Eigen::Success && (ldlt.vectorD().array() > 0).all();
}

}  // namespace

Eigen::MatrixXd conformal_map(const TriMesh& mesh, const RestTriangles& rest, const std::vector<int>& boundary_loop,
                              const BlockSpdSolver& solver) {
  const int n = mesh.num_vertices();
  ElementMatrix2D matrix(mesh.F, n);
  matrix.assemble([&](int f, ElementMatrix2D::Local* local) { conformal_local(rest, f, local); });

  // The pins remove the similarities (the energy's null space): their rows
  // and columns become the identity, their values move to the right side.
  const int first = farthest_on_loop(mesh, boundary_loop, loop_centroid(mesh, boundary_loop));
  const int second = farthest_on_loop(mesh, boundary_loop, mesh.V.row(first));
  Eigen::VectorXd pinned = Eigen::VectorXd::Zero(2 * n);
  std::vector<bool> is_pinned(2 * n, false);
  for (int dof : {2 * first, 2 * first + 1, 2 * second, 2 * second + 1}) is_pinned[dof] = true;
  pinned[2 * second] = (mesh.V.row(second) - mesh.V.row(first)).norm();

  Eigen::SparseMatrix<double> A = matrix.upper();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * n);
  for (int column = 0; column < A.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, column); it; ++it) {
      const int row = static_cast<int>(it.row());
      if (!is_pinned[row] && !is_pinned[column]) continue;
      if (row == column) {
        it.valueRef() = 1;
        b[row] = pinned[row];
        continue;
      }
      if (!is_pinned[row]) b[row] -= it.value() * pinned[column];
      if (!is_pinned[column]) b[column] -= it.value() * pinned[row];
      it.valueRef() = 0;
    }
  Eigen::VectorXd x;
  if (!(solver ? solver(A, b, &x) : solve_by_eigen(A, b, &x))) return {};
  Eigen::MatrixXd UV(n, 2);
  for (int v = 0; v < n; ++v) UV.row(v) << x[2 * v], x[2 * v + 1];
  return UV;
}

}  // namespace akvf
