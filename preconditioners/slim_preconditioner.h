#pragma once
// The SLIM proxy of Rabinovich, Poranne, Panozzo and Sorkine-Hornung 2017 as
// a preconditioner. At the current iterate, each face gets the reweighted
// ARAP proxy  A_f |W_f (J_f - R_f)|_F^2  with J_f = U S V^T, R_f = U V^T and
// W_f = U diag(w_1, w_2) U^T, w_i^2 = (dD/dsigma_i) / (2 (sigma_i - 1)),
// chosen so that the proxy's gradient equals the energy's gradient at x.
// The proxy is quadratic with Hessian
//   P = sum_f w_f G_f^T (I_2 (x) 2 W_f^T W_f) G_f,
// so the proxy minimizer x* satisfies P (x* - x) = -grad E(x): SLIM's
// search direction x* - x is -P^-1 grad E, a preconditioned gradient.
// Needs an energy that exposes its singular-value derivative
// (InvariantDensity2). Weights are clamped below at 1e-8 where w_i^2 <= 0
// (possible for non-isometric energies such as MIPS); there the gradient
// property holds only approximately, as in SLIM's own code.
#include "energies/invariant_density.h"
#include "framework/distortion_objective.h"
#include "preconditioners/factored_preconditioner.h"

namespace akvf {

class SlimPreconditioner2D final : public FactoredPreconditioner2D {
 public:
  // Throws OptionsError if the objective's density has no singular-value derivative.
  explicit SlimPreconditioner2D(const ParamObjective& objective, FactorOptions options = {});
  std::string name() const override { return "slim"; }

  // W_f^T W_f (the squared per-face weight matrix) and R_f at J.
  static void proxy_weights(const InvariantDensity2& density, const Eigen::Matrix2d& J, Eigen::Matrix2d* WtW,
                            Eigen::Matrix2d* R);

 private:
  void assemble(const OptimizationState& state, ElementMatrix2D* matrix) override;
  Eigen::MatrixXd null_space(const Eigen::VectorXd&) const override { return translations_; }

  const ParamObjective& objective_;
  const InvariantDensity2& density_;
  Eigen::MatrixXd translations_;
};

}  // namespace akvf
