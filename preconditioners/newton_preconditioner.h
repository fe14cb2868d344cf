#pragma once
// Projected Newton: P(x) = sum_f w_f G_f^T [d^2 D / dvec(J)^2]_+ G_f, the
// energy's Hessian with every element block projected to PSD (the density's
// projected_hessian), where G_f maps the face's corner positions to vec(J_f).
// The baseline of TinyAD-style second-order solvers; shift, projection of
// the rigid motions and factorization reuse as in factored_preconditioner.h.
#include "framework/distortion_objective.h"
#include "preconditioners/factored_preconditioner.h"

namespace akvf {

class NewtonPreconditioner2D final : public FactoredPreconditioner2D {
 public:
  explicit NewtonPreconditioner2D(const ParamObjective& objective, FactorOptions options = {});
  std::string name() const override { return "newton"; }

 private:
  void assemble(const OptimizationState& state, ElementMatrix2D* matrix) override;
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override { return rigid_motion_basis_2d(x); }

  const ParamObjective& objective_;
};

// G (4 by 6): dvec(J) / d(x_0, x_1, x_2) for J = [x1 - x0, x2 - x0] Dm^-1.
Eigen::Matrix<double, 4, 6> jacobian_map(const Eigen::Matrix2d& Dm_inv);

}  // namespace akvf
