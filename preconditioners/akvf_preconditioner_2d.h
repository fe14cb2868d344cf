#pragma once
// The As-Killing-As-Possible preconditioner of §4-§5 in the plane:
// d = -K(x)^+ grad E (Eq. 11-12), with K(x) of Eq. (5), area-scaled
// (§4.2.1). Its null space is exactly the rigid motions of x. Shift,
// projection and factorization reuse: factored_preconditioner.h.
// It uses K_beta (killing_operator_2d.h) with the energy's beta
// (energy_scale.h): K itself except for MIPS, whose K_0 has the
// similarities of x as null space; they are projected out instead.
// The paper's Algorithm 1 factors K_beta unscaled. The default method's
// AKVF phase (akvf/catalog.cpp) factors c K_beta instead, c the energy's
// curvature at the rest isometry over K's (energy_scale.h), so that the
// direction's unit step, the line search's first trial, is Newton's step
// at an isometry (for symmetric Dirichlet the unscaled one is 4 times it).
#include <optional>

#include "akvf/mesh_objective.h"
#include "preconditioners/factored_preconditioner.h"
#include "preconditioners/killing_operator_2d.h"

namespace akvf {

struct AkvfOptions2D {
  // Reuse tau 0.03: measured by scripts/performance.sh.
  FactorOptions factor = [] {
    FactorOptions o;
    o.reuse_tolerance = 0.03;
    return o;
  }();
  // Scale each face by A_hat_f / A_f (§4.2.1); off integrates over the UV domain.
  bool area_scaling = true;
  // beta of K_beta; unset: the energy's (rest_divergence_weight).
  std::optional<double> divergence_weight;
  // c K_beta instead of K_beta (above).
  bool energy_scaling = false;
};

class AkvfPreconditioner2D final : public FactoredPreconditioner2D {
 public:
  explicit AkvfPreconditioner2D(const MeshObjective2D& objective, AkvfOptions2D options = {});
  std::string name() const override { return "akvf"; }

 private:
  void assemble(const OptimizationState& state, ElementMatrix2D* matrix) override;
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override {
    return divergence_weight_ > 0 ? rigid_motion_basis_2d(x) : similarity_motion_basis_2d(x);
  }

  const MeshObjective2D& objective_;
  AkvfOptions2D options_;
  double divergence_weight_;  // beta
  double energy_scale_;       // c, or 1 without energy_scaling
};

}  // namespace akvf
