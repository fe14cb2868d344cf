#pragma once
// The AQP proxy of Kovalsky, Galun and Lipman 2016: the cotangent Laplacian
// of the 3D (rest) mesh for each coordinate, L = sum_f w_f grad phi_i .
// grad phi_j (x) I_2, constant, so assembled and factored once. Its null
// space is the two translations. (AQP's momentum acceleration is not
// implemented yet.)
#include "framework/distortion_objective.h"
#include "preconditioners/factored_preconditioner.h"

namespace akvf {

class LaplacianPreconditioner2D final : public FactoredPreconditioner2D {
 public:
  explicit LaplacianPreconditioner2D(const ParamObjective& objective, FactorOptions options = {});
  std::string name() const override { return "laplacian"; }

 private:
  void assemble(const OptimizationState& state, ElementMatrix2D* matrix) override;
  Eigen::MatrixXd null_space(const Eigen::VectorXd&) const override { return translations_; }
  bool is_constant() const override { return true; }

  const ParamObjective& objective_;
  Eigen::MatrixXd translations_;
};

}  // namespace akvf
