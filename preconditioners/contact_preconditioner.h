#pragma once
// Any preconditioner P with the curvature of the boundary barrier added
// (framework/optimization/boundary_contact.h), so that directions near a
// boundary contact account for the barrier instead of running into it:
//   P_B = P + U U^T,  U = [sqrt(c_k) g_k] over the active terms k
// (BoundaryContact::ActiveTerm: curvature c_k, gradient g_k of the term's
// argument), solved by the Sherman-Morrison-Woodbury identity
//   P_B^-1 g = y - P^-1 (U S^-1 U^T y),  y = P^-1 g,  S = I + U^T P^-1 U.
// update() costs one solve with P per kept term (the max_terms stiffest),
// apply() two; with no term within reach, P_B = P and apply() is P's. If P's
// solves are inexact (CG on an earlier factor) and the corrected direction is
// no longer a descent direction, apply() returns P's own.
#include <Eigen/Cholesky>
#include <memory>
#include <vector>

#include "akvf/preconditioner.h"
#include "framework/optimization/boundary_contact.h"

namespace akvf {

class ContactPreconditioner final : public Preconditioner {
 public:
  ContactPreconditioner(std::unique_ptr<Preconditioner> inner, std::shared_ptr<const BoundaryContact> contact,
                        int max_terms = 256);

  std::string name() const override { return inner_->name(); }
  void update(const OptimizationState& state) override;
  void apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) override;
  std::string report() const override { return inner_->report(); }
  bool has_element_curvature() const override { return inner_->has_element_curvature(); }
  PreconditionerStatistics statistics() const override { return inner_->statistics(); }

 private:
  // U z (a vector of the variables' size) for term weights z.
  Eigen::VectorXd spread(const Eigen::VectorXd& z, Eigen::Index size) const;
  // U^T y.
  Eigen::VectorXd gather(const Eigen::VectorXd& y) const;

  std::unique_ptr<Preconditioner> inner_;
  std::shared_ptr<const BoundaryContact> contact_;
  int max_terms_;
  std::vector<BoundaryContact::ActiveTerm> terms_;  // the kept terms of the last update
  Eigen::LDLT<Eigen::MatrixXd> capacitance_;        // S = I + U^T P^-1 U
};

}  // namespace akvf
