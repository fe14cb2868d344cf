#pragma once
// The boundary barrier's curvature as a sparse matrix, for a factored
// preconditioner to add to P (global injectivity; boundary_contact.h):
//   C(x) = sum_k c_k (dq_k/dx)(dq_k/dx)^T
// over the barrier's active terms k (BoundaryContact::ActiveTerm), each
// coupling three vertices as a triangle does; or, for a preconditioner that
// models the energy's curvature (projected Newton), each term's whole
// Hessian projected to be positive semi-definite, or unprojected where
// Newton's model is exact (ContactModel). Factored
// with P, C costs one factorization however many terms are active, where
// ContactPreconditioner's low-rank update costs a solve per term (and a
// term left out of P stalls the descent: its vertices run into the barrier
// and the line search shortens every step).
//
// The pattern. C is stored on every vertex pair that a term has coupled
// (explicit zeros where none does now) since the pattern was last built, so
// a factorization's symbolic analysis is redone only when a new pair comes
// within reach or the pattern shrinks (below), which the version number
// tells. Each new analysis costs
// several factorizations (horse_b: 20 ms against 6; 1.7 s at 16 times its
// faces), and where a boundary closes in on itself the active pairs alone
// bring a new one at most iterations (cow_b: 30 of 45, horse_b: 19 of 25).
// So a pattern that grows also takes the pairs of every term within twice
// its reach: a vertex must then cover a whole reach toward an edge (at most
// half the edge's rest length) before the pattern grows again.
//
// And it shrinks. Far from the minimum a compressed boundary brings many
// terms at once (hilbert_b's Tutte map, its long boundary on a circle: 35 696
// terms, 55 312 pairs), and a few iterations later a few dozen remain; every
// pair kept costs fill in each factorization and an entry here at each
// call. When the terms within twice their reach couple fewer than a quarter
// of the pattern's pairs (each term at most 6), the pattern is rebuilt from
// them: a new analysis, after which at least three quarters of the pattern
// would have been pairs no term couples. Each such rebuild divides the
// pattern by at least 4, so they are few. One object serves the
// preconditioners of one run (akvf-newton's two phases share it).
#include <Eigen/SparseCore>
#include <cstdint>
#include <memory>
#include <unordered_set>
#include <vector>

#include "framework/optimization/boundary_contact.h"

namespace akvf {

// Each active term's part of C: its Gauss-Newton curvature b'' (dq/dx)(dq/dx)^T,
// or its whole Hessian, b'' (dq/dx)(dq/dx)^T + b' d^2q/dx^2
// (BoundaryContact::hessian), with its negative eigenvalues clamped to 0 as
// projected Newton does for each element, or as it is (C then may be
// indefinite: Newton's exact tries, newton_preconditioner.h).
enum class ContactModel { kGaussNewton, kProjectedHessian, kHessian };

class ContactCurvature {
 public:
  // The pattern's margin, in multiples of each term's reach, and how much it
  // shrinks before it is rebuilt (module comment).
  static constexpr double kProspectiveReach = 2;
  static constexpr std::size_t kShrinkRatio = 4;

  ContactCurvature(std::shared_ptr<const BoundaryContact> contact, int num_vertices);

  // C(x): the upper triangle, 2|V| square, on the pattern (module comment).
  const Eigen::SparseMatrix<double>& at(const Eigen::VectorXd& x, ContactModel model = ContactModel::kGaussNewton);
  // Grows by one each time the pattern changes.
  int pattern_version() const { return version_; }
  // The barrier whose terms C holds.
  const BoundaryContact& contact() const { return *contact_; }

 private:
  // matrix_ on sorted_pairs_, values zero.
  void build_pattern();
  // The index in matrix_'s values of (row, column), which the pattern holds.
  int entry(int row, int column) const;

  std::shared_ptr<const BoundaryContact> contact_;
  int num_vertices_;
  std::unordered_set<std::uint64_t> pairs_;  // vertex pairs (i <= j) as i * |V| + j
  std::vector<std::uint64_t> sorted_pairs_;
  int version_ = 0;
  Eigen::SparseMatrix<double> matrix_;
};

}  // namespace akvf
