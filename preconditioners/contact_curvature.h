#pragma once
// The boundary barrier's curvature as a sparse matrix, for a factored
// preconditioner to add to P (global injectivity; boundary_contact.h):
//   C(x) = sum_k c_k (dq_k/dx)(dq_k/dx)^T
// over the barrier's active terms k (BoundaryContact::ActiveTerm), each
// coupling three vertices as a triangle does; or, for a preconditioner that
// models the energy's curvature (projected Newton), each term's whole
// Hessian projected to be positive semi-definite (ContactModel). Factored
// with P, C costs one factorization however many terms are active, where
// ContactPreconditioner's low-rank update costs a solve per term (and a
// term left out of P stalls the descent: its vertices run into the barrier
// and the line search shortens every step).
//
// The pattern. C is stored on every vertex pair that any term has coupled so
// far (explicit zeros where none does now): the pattern only grows, so a
// factorization's symbolic analysis is redone only when a new pair comes
// within reach, which the version number tells. Each new analysis costs
// several factorizations (horse_b: 20 ms against 6; 1.7 s at 16 times its
// faces), and where a boundary closes in on itself the active pairs alone
// bring a new one at most iterations (cow_b: 30 of 45, horse_b: 19 of 25).
// So a pattern that grows also takes the pairs of every term within twice
// its reach: a vertex must then cover a whole reach toward an edge (at most
// half the edge's rest length) before the pattern grows again. One object serves the
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
// projected Newton does for each element.
enum class ContactModel { kGaussNewton, kProjectedHessian };

class ContactCurvature {
 public:
  // The pattern's margin, in multiples of each term's reach (module comment).
  static constexpr double kProspectiveReach = 2;

  ContactCurvature(std::shared_ptr<const BoundaryContact> contact, int num_vertices);

  // C(x): the upper triangle, 2|V| square, on the pattern of every pair so far.
  const Eigen::SparseMatrix<double>& at(const Eigen::VectorXd& x, ContactModel model = ContactModel::kGaussNewton);
  // Grows by one each time the pattern does.
  int pattern_version() const { return version_; }

 private:
  std::shared_ptr<const BoundaryContact> contact_;
  int num_vertices_;
  std::unordered_set<std::uint64_t> pairs_;  // vertex pairs (i <= j) as i * |V| + j
  std::vector<std::uint64_t> sorted_pairs_;
  int version_ = 0;
  Eigen::SparseMatrix<double> matrix_;
};

}  // namespace akvf
