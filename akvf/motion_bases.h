#pragma once
// The motions a preconditioner projects out of its directions (§5.1): the
// null space of an unconstrained problem's P (rigid motions for the Killing
// operator and projected Newton, translations for the Laplacian and SLIM),
// or nothing when constraint terms or a shift make P definite. All bases
// here, for both dimensions, act on interleaved dofs (x0 y0 [z0] x1 ...).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <vector>

namespace akvf {

enum class MotionProjection { kNone, kTranslations, kRigidMotions };

// Orthonormal basis (D|V| by k) of those motions at x.
Eigen::MatrixXd motion_basis(int dimension, MotionProjection projection, const Eigen::VectorXd& x);

// The planar rigid motions: translations and the rotation about the
// centroid (2|V| by 3, orthonormal).
Eigen::MatrixXd rigid_motion_basis_2d(const Eigen::VectorXd& x);
// The planar similarities: the rigid motions and the dilation about the
// centroid (2|V| by 4, orthonormal).
Eigen::MatrixXd similarity_motion_basis_2d(const Eigen::VectorXd& x);
// The rigid motions in space: translations and the rotations about the
// centroid (3|V| by 6, orthonormalized); the null space of K of Eq. (9)-(10).
Eigen::MatrixXd rigid_motion_basis_3d(const Eigen::VectorXd& x);
// The translations alone (D|V| by D, orthonormal).
Eigen::MatrixXd translation_basis(int dimension, int num_vertices);
inline Eigen::MatrixXd translation_basis_2d(int num_vertices) { return translation_basis(2, num_vertices); }

// The motions to project out of a mesh with several connected components
// (the charts of a cut mesh): each component moves on its own, so the basis
// is the per-component bases side by side, kept as blocks (a dense basis
// would grow with vertices x components).
class ComponentMotions {
 public:
  ComponentMotions() = default;
  // One basis for the whole of x (a connected mesh).
  explicit ComponentMotions(Eigen::MatrixXd basis) : whole_(std::move(basis)) {}
  // basis_of(x restricted to the component's vertices) per component.
  ComponentMotions(int dimension, std::shared_ptr<const std::vector<std::vector<int>>> component_vertices,
                   const Eigen::VectorXd& x, const std::function<Eigen::MatrixXd(const Eigen::VectorXd&)>& basis_of);
  // v -= B (B^T v): v's component in the motions removed.
  void project_out(Eigen::VectorXd* v) const;
  // Keeps of each basis the motions that the symmetric PSD matrix C (its
  // upper triangle, on the same dofs) does not stiffen: those on which
  // B^T C B has an eigenvalue within the rounding of the sum that forms it
  // (its m terms' magnitudes times m epsilon), which is what a C invariant
  // under the motions leaves. A basis that keeps them all is left as it is,
  // bit for bit. For P + C where the motions span P's null space: the result
  // spans P + C's.
  void keep_unstiffened_by(const Eigen::SparseMatrix<double>& upper_C);

 private:
  Eigen::MatrixXd whole_;
  int dimension_ = 0;
  std::shared_ptr<const std::vector<std::vector<int>>> component_vertices_;
  std::vector<Eigen::MatrixXd> blocks_;
};

}  // namespace akvf
