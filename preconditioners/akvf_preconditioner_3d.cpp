#include "preconditioners/akvf_preconditioner_3d.h"

namespace akvf {

AkvfPreconditioner3D::AkvfPreconditioner3D(const TetObjective& objective, Akvf3DOptions options)
    : FactoredPreconditioner3D(objective.faces(), objective.num_vertices(), options.factor),
      objective_(objective),
      options_(options) {}

void AkvfPreconditioner3D::assemble(const OptimizationState& state, ElementMatrix3D* matrix) {
  assemble_killing_operator_3d(objective_.faces(), state.x, matrix);
}

Eigen::MatrixXd AkvfPreconditioner3D::null_space(const Eigen::VectorXd& x) const {
  return options_.project_rigid ? rigid_motion_basis_3d(x) : Eigen::MatrixXd(x.size(), 0);
}

}  // namespace akvf
