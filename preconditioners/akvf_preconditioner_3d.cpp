#include "preconditioners/akvf_preconditioner_3d.h"

#include "preconditioners/energy_scale.h"

namespace akvf {

namespace {

FactorOptions with_problem_hessian(FactorOptions options, const MeshObjective3D& objective) {
  if (options.extra_diagonal.size() == 0) options.extra_diagonal = objective.added_hessian_diagonal();
  return options;
}

}  // namespace

AkvfPreconditioner3D::AkvfPreconditioner3D(const MeshObjective3D& objective, AkvfOptions3D options)
    : FactoredPreconditioner3D(
          objective.elements(), objective.num_vertices(),
          options.include_problem_hessian ? with_problem_hessian(options.factor, objective) : options.factor),
      objective_(objective),
      options_(options),
      divergence_weight_(options.divergence_weight.value_or(rest_divergence_weight(objective.density()))),
      // Energy curvature (weights V_t / sum V) over K's, 4 sum V, along a shear.
      scale_(options.secant_scaling ? rest_shear_curvature(objective.density()) / (4 * objective.rest().total_volume)
                                    : 1.0) {}

void AkvfPreconditioner3D::assemble(const OptimizationState& state, ElementMatrix3D* matrix) {
  assemble_killing_operator_3d(objective_.elements(), state.x, matrix, divergence_weight_);
  if (options_.secant_scaling) {
    if (previous_x_.size() == state.x.size()) {
      const Eigen::VectorXd dx = state.x - previous_x_;
      Eigen::VectorXd dg = state.gradient - previous_gradient_;
      const Eigen::VectorXd& constraint_hessian = extra_diagonal();
      if (constraint_hessian.size() != 0) dg -= constraint_hessian.cwiseProduct(dx);
      const double energy_curvature = dx.dot(dg);
      const double killing_curvature = dx.dot(matrix->upper().selfadjointView<Eigen::Upper>() * dx);
      if (energy_curvature > 0 && killing_curvature > 0) scale_ = energy_curvature / killing_curvature;
    }
    previous_x_ = state.x;
    previous_gradient_ = state.gradient;
  }
  matrix->scale(scale_);
}

Eigen::MatrixXd AkvfPreconditioner3D::null_space(const Eigen::VectorXd& x) const {
  return motion_basis(3, options_.project_rigid ? MotionProjection::kRigidMotions : MotionProjection::kNone, x);
}

}  // namespace akvf
