#include "akvf/motion_bases.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/QR>
#include <cmath>
#include <limits>

#include "akvf/error.h"

namespace akvf {

Eigen::MatrixXd rigid_motion_basis_2d(const Eigen::VectorXd& x) {
  const Eigen::Index n = x.size() / 2;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(x.size(), 3);
  double cx = 0, cy = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    cx += x[2 * i];
    cy += x[2 * i + 1];
  }
  cx /= static_cast<double>(n);
  cy /= static_cast<double>(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    B(2 * i, 0) = 1;
    B(2 * i + 1, 1) = 1;
    // Velocity of a rotation about the centroid: (-(y - cy), x - cx).
    B(2 * i, 2) = -(x[2 * i + 1] - cy);
    B(2 * i + 1, 2) = x[2 * i] - cx;
  }
  // The three columns are mutually orthogonal by construction (centred rotation).
  for (int c = 0; c < 3; ++c) B.col(c).normalize();
  return B;
}

Eigen::MatrixXd similarity_motion_basis_2d(const Eigen::VectorXd& x) {
  Eigen::MatrixXd B(x.size(), 4);
  B.leftCols<3>() = rigid_motion_basis_2d(x);
  // The dilation about the centroid, x - c: orthogonal to the translations
  // (centred) and to the rotation (r . perp(r) = 0).
  const Eigen::Index n = x.size() / 2;
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (Eigen::Index i = 0; i < n; ++i) c += x.segment<2>(2 * i);
  c /= static_cast<double>(n);
  for (Eigen::Index i = 0; i < n; ++i) B.block<2, 1>(2 * i, 3) = x.segment<2>(2 * i) - c;
  B.col(3).normalize();
  return B;
}

Eigen::MatrixXd translation_basis(int dimension, int num_vertices) {
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(dimension) * num_vertices, dimension);
  for (int i = 0; i < num_vertices; ++i)
    for (int c = 0; c < dimension; ++c) B(dimension * i + c, c) = 1;
  return B / std::sqrt(static_cast<double>(num_vertices));
}

Eigen::MatrixXd motion_basis(int dimension, MotionProjection projection, const Eigen::VectorXd& x) {
  const int num_vertices = static_cast<int>(x.size()) / dimension;
  switch (projection) {
    case MotionProjection::kNone:
      return Eigen::MatrixXd(x.size(), 0);
    case MotionProjection::kTranslations:
      return translation_basis(dimension, num_vertices);
    case MotionProjection::kRigidMotions:
      return dimension == 2 ? rigid_motion_basis_2d(x) : rigid_motion_basis_3d(x);
  }
  throw OptionsError("unknown motion projection");
}

Eigen::MatrixXd rigid_motion_basis_3d(const Eigen::VectorXd& x) {
  const Eigen::Index n = x.size() / 3;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < n; ++i) centroid += x.segment<3>(3 * i);
  centroid /= static_cast<double>(n);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(x.size(), 6);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d r = x.segment<3>(3 * i) - centroid;
    B.block<3, 3>(3 * i, 0).setIdentity();
    for (int axis = 0; axis < 3; ++axis) B.block<3, 1>(3 * i, 3 + axis) = Eigen::Vector3d::Unit(axis).cross(r);
  }
  // Orthonormalize (the rotations about different axes are not orthogonal in general).
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(B);
  return qr.householderQ() * Eigen::MatrixXd::Identity(x.size(), 6);
}

ComponentMotions::ComponentMotions(int dimension,
                                   std::shared_ptr<const std::vector<std::vector<int>>> component_vertices,
                                   const Eigen::VectorXd& x,
                                   const std::function<Eigen::MatrixXd(const Eigen::VectorXd&)>& basis_of)
    : dimension_(dimension), component_vertices_(std::move(component_vertices)) {
  for (const std::vector<int>& vertices : *component_vertices_) {
    Eigen::VectorXd part(static_cast<Eigen::Index>(dimension) * static_cast<Eigen::Index>(vertices.size()));
    for (std::size_t i = 0; i < vertices.size(); ++i)
      part.segment(dimension * i, dimension) = x.segment(static_cast<Eigen::Index>(dimension) * vertices[i], dimension);
    blocks_.push_back(basis_of(part));
  }
}

namespace {

// v -= B (B^T v) with the bits of Eigen's `v -= B * (B.transpose() * v)`,
// without its temporary vector: B^T v by Eigen, then for each row Eigen's
// matrix-vector kernel, a sum over B's columns in order from 0, added to
// the zeroed temporary (the + 0.0: it turns a -0 into +0) and subtracted.
void subtract_projection(const Eigen::MatrixXd& B, Eigen::VectorXd* v) {
  const Eigen::VectorXd c = B.transpose() * *v;
  const Eigen::Index rows = B.rows(), columns = B.cols();
  const double* b = B.data();
  double* out = v->data();
  for (Eigen::Index i = 0; i < rows; ++i) {
    double sum = 0;
    for (Eigen::Index j = 0; j < columns; ++j) sum = b[j * rows + i] * c[j] + sum;
    out[i] -= sum + 0.0;
  }
}

}  // namespace

void ComponentMotions::keep_unstiffened_by(const Eigen::SparseMatrix<double>& upper_C) {
  // Where a dof is: its block and row there (a block's rows are the dofs of
  // its component's vertices, in order). Looked up per vertex: a whole
  // basis's row is the dof itself.
  const auto blocks = static_cast<int>(component_vertices_ ? blocks_.size() : 1);
  std::vector<int> component_of, index_in;
  if (component_vertices_) {
    const auto vertices = static_cast<std::size_t>(upper_C.rows() / dimension_);
    component_of.assign(vertices, -1);
    index_in.resize(vertices);
    for (int c = 0; c < blocks; ++c)
      for (std::size_t i = 0; i < (*component_vertices_)[c].size(); ++i) {
        component_of[(*component_vertices_)[c][i]] = c;
        index_in[(*component_vertices_)[c][i]] = static_cast<int>(i);
      }
  }
  const auto block_of = [&](Eigen::Index dof) { return component_vertices_ ? component_of[dof / dimension_] : 0; };
  const auto row_of = [&](Eigen::Index dof) {
    return component_vertices_ ? Eigen::Index{dimension_} * index_in[dof / dimension_] + dof % dimension_ : dof;
  };
  const auto basis = [&](int c) -> Eigen::MatrixXd& { return component_vertices_ ? blocks_[c] : whole_; };
  // B^T C B per block, from C's entries (C couples dofs of one component).
  std::vector<Eigen::MatrixXd> stiffness(blocks);
  // The sum of the magnitudes of B^T C B's terms, and their number.
  std::vector<double> magnitude(blocks, 0), terms(blocks, 0);
  for (int c = 0; c < blocks; ++c) stiffness[c] = Eigen::MatrixXd::Zero(basis(c).cols(), basis(c).cols());
  for (Eigen::Index j = 0; j < upper_C.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(upper_C, j); it; ++it) {
      const Eigen::Index i = it.row();
      const int c = block_of(j);
      if (c < 0 || block_of(i) != c || basis(c).cols() == 0) continue;
      const Eigen::MatrixXd& B = basis(c);
      const auto bi = B.row(row_of(i)), bj = B.row(row_of(j));
      Eigen::MatrixXd& M = stiffness[c];
      // M += value bi^T bj (and bj^T bi), entry by entry: a basis has a few
      // columns, where a dynamic-size outer product costs more than its flops.
      const double value = it.value();
      const Eigen::Index n = M.rows();
      for (Eigen::Index b = 0; b < n; ++b)
        for (Eigen::Index a = 0; a < n; ++a) M(a, b) += bj(b) * (value * bi(a));
      if (i != j)
        for (Eigen::Index b = 0; b < n; ++b)
          for (Eigen::Index a = 0; a < n; ++a) M(a, b) += bi(b) * (value * bj(a));
      magnitude[c] += (i != j ? 2 : 1) * std::abs(it.value()) * bi.norm() * bj.norm();
      terms[c] += i != j ? 2 : 1;
    }
  for (int c = 0; c < blocks; ++c) {
    if (!(magnitude[c] > 0)) continue;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(stiffness[c]);
    const Eigen::VectorXd& values = eigen.eigenvalues();  // increasing
    Eigen::Index kept = 0;
    // A sum of m terms is exact to about m epsilon times their magnitudes.
    const double rounding = terms[c] * std::numeric_limits<double>::epsilon() * magnitude[c];
    while (kept < values.size() && values[kept] <= rounding) ++kept;
    if (kept == values.size()) continue;
    basis(c) = basis(c) * eigen.eigenvectors().leftCols(kept);
  }
}

void ComponentMotions::project_out(Eigen::VectorXd* v) const {
  if (!component_vertices_) {
    if (whole_.cols() > 0) subtract_projection(whole_, v);
    return;
  }
  for (std::size_t c = 0; c < blocks_.size(); ++c) {
    const std::vector<int>& vertices = (*component_vertices_)[c];
    Eigen::VectorXd part(blocks_[c].rows());
    for (std::size_t i = 0; i < vertices.size(); ++i)
      part.segment(dimension_ * i, dimension_) =
          v->segment(static_cast<Eigen::Index>(dimension_) * vertices[i], dimension_);
    subtract_projection(blocks_[c], &part);
    for (std::size_t i = 0; i < vertices.size(); ++i)
      v->segment(static_cast<Eigen::Index>(dimension_) * vertices[i], dimension_) =
          part.segment(dimension_ * i, dimension_);
  }
}

}  // namespace akvf
