#include "preconditioners/akvf_preconditioner_2d.h"

#include "preconditioners/energy_scale.h"

namespace akvf {

AkvfPreconditioner2D::AkvfPreconditioner2D(const MeshObjective2D& objective, AkvfOptions2D options)
    : FactoredPreconditioner2D(objective, options.factor),
      objective_(objective),
      options_(options),
      divergence_weight_(options.divergence_weight.value_or(rest_divergence_weight(objective.density()))),
      energy_scale_(options.energy_scaling ? 1 / isometric_newton_step(objective.density(), objective.rest().total_area)
                                           : 1.0) {}

void AkvfPreconditioner2D::assemble(const OptimizationState& state, ElementMatrix2D* matrix) {
  assemble_killing_operator_2d(objective_.elements(), state.x, objective_.rest().area, options_.area_scaling, matrix,
                               divergence_weight_, energy_scale_);
}

}  // namespace akvf
