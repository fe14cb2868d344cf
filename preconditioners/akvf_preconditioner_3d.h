#pragma once
// The AKVF preconditioner on tet meshes (§4.2.2, §6.2): P = s K(x) + c I + H_c
// with K(x) of Eq. (9)-(10) at the current positions (K_beta with the
// energy's divergence weight, energy_scale.h: K itself for the isometric
// energies, K_0 for MIPS, 9/4 for AMIPS), c = 1e-4 (§6.2) and
// H_c the soft constraints' Hessian (the objective's added Hessian diagonal), as in
// SLIM's own solve, which §6.2 follows "identically". In deformation the
// energy is not rigid-invariant, so nothing is projected out by default;
// for an unconstrained rigid-invariant energy, project_rigid removes the six
// rigid motions as in 2D.
//
// The scale s (energy_scale.h): K is dimensionless, the constraint term is
// not. s starts at the energy's rest curvature over K's along a shear and
// then follows the secant: s_k = dx^T (dg - H_c dx) / dx^T K(x_k) dx with
// dx = x_k - x_{k-1} and dg the change of the gradient, the curvature the
// energy showed over the last step (kept when that is not positive). Without
// it (secant_scaling = false, s = 1) the direction is off by the energy's
// scale (exp(6k) for the exponential energies) and the descent crawls; see
// docs/deformation.md.
#include <optional>

#include "akvf/mesh_objective.h"
#include "preconditioners/factored_preconditioner.h"
#include "preconditioners/killing_operator_3d.h"

namespace akvf {

struct AkvfOptions3D {
  FactorOptions factor = shifted_factor_options(1e-4);  // c of §6.2
  bool project_rigid = false;
  bool secant_scaling = true;
  // Include the Hessian of the terms the problem adds to the energy
  // (MeshObjective::added_hessian_diagonal: the constraints). Off is
  // §6.2 as written, K + c I alone (--akvf-as-written).
  bool include_problem_hessian = true;
  // beta of K_beta (killing_operator_3d.h); unset: the energy's
  // (rest_divergence_weight), 1 as written.
  std::optional<double> divergence_weight;
};

class AkvfPreconditioner3D final : public FactoredPreconditioner3D {
 public:
  explicit AkvfPreconditioner3D(const MeshObjective3D& objective, AkvfOptions3D options = {});
  std::string name() const override { return "akvf"; }

 private:
  void assemble(const OptimizationState& state, ElementMatrix3D* matrix) override;
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override;

  const MeshObjective3D& objective_;
  AkvfOptions3D options_;
  double divergence_weight_;  // beta
  double scale_;              // s
  Eigen::VectorXd previous_x_, previous_gradient_;
};

}  // namespace akvf
