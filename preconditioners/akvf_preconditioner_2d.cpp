#include "preconditioners/akvf_preconditioner_2d.h"

#include <Eigen/LU>
#include <algorithm>

#include "framework/optimization/element_derivatives.h"
#include "preconditioners/energy_scale.h"

namespace akvf {

AkvfPreconditioner2D::AkvfPreconditioner2D(const MeshObjective2D& objective, AkvfOptions2D options)
    : FactoredPreconditioner2D(objective, options.factor),
      objective_(objective),
      options_(options),
      divergence_weight_(options.divergence_weight.value_or(rest_divergence_weight(objective.density()))),
      energy_scale_(options.energy_scaling ? 1 / isometric_newton_step(objective.density(), objective.rest().total_area)
                                           : 1.0) {
  if (options_.sliver_stretch) sliver_.assign(static_cast<std::size_t>(objective.elements().rows()), 0);
}

void AkvfPreconditioner2D::assemble(const OptimizationState& state, ElementMatrix2D* matrix) {
  ElementMatrix2D::LocalFunction add_energy_curvature;
  if (options_.sliver_stretch) {
    const double limit = *options_.sliver_stretch * *options_.sliver_stretch;
    add_energy_curvature = [&, limit](int f, ElementMatrix2D::Local* local) {
      const Eigen::Matrix2d J = objective_.jacobian(state.x, f);
      const Eigen::Matrix2d& Dm_inv = objective_.rest().Dm_inv[f];
      // Ds^-1 = Dm^-1 J^-1 (J = Ds Dm^-1).
      if (!(Dm_inv.squaredNorm() > limit * (Dm_inv * J.inverse()).squaredNorm())) return;
      sliver_[static_cast<std::size_t>(f)] = 1;
      const auto G = jacobian_map<2>(Dm_inv);
      local->triangularView<Eigen::Upper>() +=
          objective_.weights()[f] * G.transpose() * objective_.density().projected_hessian(J) * G;
    };
  }
  assemble_killing_operator_2d(objective_.elements(), state.x, objective_.rest().area, options_.area_scaling, matrix,
                               divergence_weight_, energy_scale_, add_energy_curvature);
}

std::string AkvfPreconditioner2D::report() const {
  std::string line = FactoredPreconditioner2D::report();
  const auto slivers = std::count(sliver_.begin(), sliver_.end(), 1);
  if (slivers > 0)
    line +=
        "; the energy's own curvature at " + std::to_string(slivers) + " stretched sliver" + (slivers == 1 ? "" : "s");
  return line;
}

}  // namespace akvf
