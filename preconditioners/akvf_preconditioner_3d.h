#pragma once
// The AKVF preconditioner on tet meshes (§4.2.2, §6.2): P = K(x) + c I with
// K(x) of Eq. (9)-(10) at the current positions. In deformation with
// positional constraints the energy is not rigid-invariant, so nothing is
// projected out by default and the Tikhonov term c I (§6.2: c = 1e-4) makes
// P positive definite; for an unconstrained rigid-invariant energy,
// project_rigid removes the six rigid motions as in 2D.
#include "framework/distortion_objective.h"
#include "preconditioners/factored_preconditioner.h"
#include "preconditioners/killing_operator_3d.h"

namespace akvf {

struct Akvf3DOptions {
  FactorOptions factor{.tikhonov = 1e-8, .absolute_shift = 1e-4, .reuse_tolerance = 0, .reuse_max_cg = 8};
  bool project_rigid = false;
};

class AkvfPreconditioner3D final : public FactoredPreconditioner3D {
 public:
  explicit AkvfPreconditioner3D(const TetObjective& objective, Akvf3DOptions options = {});
  std::string name() const override { return "akvf"; }

 private:
  void assemble(const OptimizationState& state, ElementMatrix3D* matrix) override;
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override;

  const TetObjective& objective_;
  Akvf3DOptions options_;
};

}  // namespace akvf
