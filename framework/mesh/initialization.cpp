#include "framework/mesh/initialization.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <utility>

#include "akvf/error.h"
#include "akvf/rest_geometry.h"
#include "framework/mesh/plane_geometry.h"

namespace akvf {

std::vector<Eigen::Triplet<double>> laplacian_edge_weights(const TriMesh& mesh, TutteWeights weights) {
  std::vector<Eigen::Triplet<double>> w;
  w.reserve(6 * mesh.num_faces());
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = mesh.F(f, k), j = mesh.F(f, (k + 1) % 3), o = mesh.F(f, (k + 2) % 3);
      double value = 0.5;  // each interior edge is seen from two faces: sums to 1
      if (weights == TutteWeights::kCotangent) {
        const Eigen::Vector3d a = mesh.V.row(i) - mesh.V.row(o), b = mesh.V.row(j) - mesh.V.row(o);
        value = 0.5 * a.dot(b) / a.cross(b).norm();
      }
      w.emplace_back(i, j, value);
      w.emplace_back(j, i, value);
    }
  return w;
}

Eigen::VectorXd vertex_angle_sums(const TriMesh& mesh) {
  Eigen::VectorXd angle_sum = Eigen::VectorXd::Zero(mesh.num_vertices());
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector3d p = mesh.V.row(mesh.F(f, k));
      const Eigen::RowVector3d u = mesh.V.row(mesh.F(f, (k + 1) % 3)) - p;
      const Eigen::RowVector3d v = mesh.V.row(mesh.F(f, (k + 2) % 3)) - p;
      angle_sum[mesh.F(f, k)] += std::atan2(u.cross(v).norm(), u.dot(v));
    }
  return angle_sum;
}

InteriorLaplacian::InteriorLaplacian(const TriMesh& mesh, const std::vector<int>& loop, TutteWeights weights,
                                     SpdSolver solver)
    : weights_(laplacian_edge_weights(mesh, weights)),
      interior_index_(mesh.num_vertices(), 0),
      solver_(std::move(solver)) {
  for (int v : loop) interior_index_[v] = -1;
  int m = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (interior_index_[v] == 0) {
      interior_index_[v] = m++;
      interior_vertex_.push_back(v);
    }
  std::vector<Eigen::Triplet<double>> lhs;
  for (const auto& t : weights_) {
    const int i = interior_index_[t.row()];
    if (i < 0) continue;
    lhs.emplace_back(i, i, t.value());
    const int j = interior_index_[t.col()];
    if (j >= 0) lhs.emplace_back(i, j, -t.value());
  }
  interior_.resize(m, m);
  interior_.setFromTriplets(lhs.begin(), lhs.end());
}

bool InteriorLaplacian::solve(const Eigen::MatrixXd& source, Eigen::MatrixXd* X) {
  const auto m = static_cast<int>(interior_vertex_.size());
  if (m == 0) return X->allFinite();
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m, X->cols());
  if (source.size() > 0)
    for (int i = 0; i < m; ++i) rhs.row(i) = source.row(interior_vertex_[i]);
  for (const auto& t : weights_) {
    const int i = interior_index_[t.row()];
    if (i >= 0 && interior_index_[t.col()] < 0) rhs.row(i) += t.value() * X->row(t.col());
  }
  Eigen::MatrixXd interior;
  if (ldlt_ || !solver_ || !solver_(interior_, rhs, interior_vertex_, &interior)) {
    // Also for cotangent weights whose system is not positive definite: a
    // nonsingular one still has an L D L^T (whose map is checked for folds).
    if (!ldlt_) ldlt_ = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>(interior_);
    if (ldlt_->info() != Eigen::Success) return false;
    interior = ldlt_->solve(rhs);
  }
  for (int i = 0; i < m; ++i) X->row(interior_vertex_[i]) = interior.row(i);
  return X->allFinite();
}

Eigen::MatrixXd InteriorLaplacian::apply(const Eigen::MatrixXd& X) const {
  Eigen::MatrixXd LX = Eigen::MatrixXd::Zero(X.rows(), X.cols());
  for (const auto& t : weights_) LX.row(t.row()) += t.value() * (X.row(t.row()) - X.row(t.col()));
  return LX;
}

namespace {

Eigen::MatrixXd solve_tutte(const TriMesh& mesh, const std::vector<int>& loop, TutteWeights weights,
                            const SpdSolver& solver, bool* ok) {
  Eigen::MatrixXd UV = Eigen::MatrixXd::Zero(mesh.num_vertices(), 2);
  std::vector<double> arc(loop.size() + 1, 0.0);
  for (std::size_t i = 0; i < loop.size(); ++i)
    arc[i + 1] = arc[i] + (mesh.V.row(loop[(i + 1) % loop.size()]) - mesh.V.row(loop[i])).norm();
  const double radius = std::sqrt(surface_area(mesh) / std::numbers::pi);
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const double angle = 2 * std::numbers::pi * arc[i] / arc.back();
    UV.row(loop[i]) << radius * std::cos(angle), radius * std::sin(angle);
  }
  *ok = InteriorLaplacian(mesh, loop, weights, solver).solve({}, &UV);
  return UV;
}

}  // namespace

Eigen::MatrixXd tutte_embedding(const TriMesh& mesh, const std::vector<int>& boundary_loop, TutteWeights weights,
                                Warnings* warnings, const SpdSolver& solver) {
  bool ok = false;
  if (weights == TutteWeights::kCotangent) {
    Eigen::MatrixXd UV = solve_tutte(mesh, boundary_loop, TutteWeights::kCotangent, solver, &ok);
    const int inverted = ok ? count_inverted_triangles(mesh.F, UV) : -1;
    if (inverted == 0) return UV;
    if (warnings)
      warnings->push_back(inverted > 0 ? "cotangent Tutte map inverts " + std::to_string(inverted) +
                                             " triangles; using uniform weights instead"
                                       : "cotangent Tutte system is singular; using uniform weights instead");
  }
  Eigen::MatrixXd UV = solve_tutte(mesh, boundary_loop, TutteWeights::kUniform, solver, &ok);
  if (!ok) throw ValidationError("the Tutte system could not be solved (is the mesh connected?)");
  return UV;
}

int optimize_flaps(const TriMesh& mesh, Eigen::MatrixXd* UV) {
  std::vector<int> face_count(mesh.num_vertices(), 0), face_of(mesh.num_vertices(), -1);
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      ++face_count[mesh.F(f, k)];
      face_of[mesh.F(f, k)] = f;
    }
  int moved = 0;
  for (int p = 0; p < mesh.num_vertices(); ++p) {
    if (face_count[p] != 1) continue;
    const int f = face_of[p];
    int k = 0;
    while (mesh.F(f, k) != p) ++k;
    const int a = mesh.F(f, (k + 1) % 3), b = mesh.F(f, (k + 2) % 3);
    if (face_count[a] == 1 || face_count[b] == 1) continue;  // an isolated triangle has no fixed edge
    const Eigen::Vector3d Xp = mesh.V.row(p), Xa = mesh.V.row(a), Xb = mesh.V.row(b);
    const double beta = (Xp - Xa).dot(Xb - Xa) / (Xb - Xa).squaredNorm();
    const double gamma = (Xp - Xa - beta * (Xb - Xa)).norm();
    const Eigen::RowVector2d xa = UV->row(a), xb = UV->row(b);
    const Eigen::RowVector2d edge = xb - xa;
    // The left normal of a -> b keeps the triangle (p, a, b) counter-clockwise.
    const Eigen::RowVector2d left(-edge.y(), edge.x());
    UV->row(p) = (1 - beta) * xa + beta * xb + gamma / edge.norm() * left;
    ++moved;
  }
  return moved;
}

int count_inverted_triangles(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV) {
  int inverted = 0;
  for (int f = 0; f < F.rows(); ++f) inverted += !(twice_signed_area(F, UV, f) > 0);
  return inverted;
}

}  // namespace akvf
