#pragma once
// The motions a preconditioner projects out of its directions (§5.1): the
// null space of an unconstrained problem's P (rigid motions for the Killing
// operator and projected Newton, translations for the Laplacian and SLIM),
// or nothing when constraint terms or a shift make P definite. All bases
// here, for both dimensions, act on interleaved dofs (x0 y0 [z0] x1 ...).
#include <Eigen/Core>

namespace akvf {

enum class MotionProjection { kNone, kTranslations, kRigidMotions };

// Orthonormal basis (D|V| by k) of those motions at x.
Eigen::MatrixXd motion_basis(int dimension, MotionProjection projection, const Eigen::VectorXd& x);

// The planar rigid motions: translations and the rotation about the
// centroid (2|V| by 3, orthonormal).
Eigen::MatrixXd rigid_motion_basis_2d(const Eigen::VectorXd& x);
// The rigid motions in space: translations and the rotations about the
// centroid (3|V| by 6, orthonormalized); the null space of K of Eq. (9)-(10).
Eigen::MatrixXd rigid_motion_basis_3d(const Eigen::VectorXd& x);
// The translations alone (D|V| by D, orthonormal).
Eigen::MatrixXd translation_basis(int dimension, int num_vertices);
inline Eigen::MatrixXd translation_basis_2d(int num_vertices) { return translation_basis(2, num_vertices); }

}  // namespace akvf
