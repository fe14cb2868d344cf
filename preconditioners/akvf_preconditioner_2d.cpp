#include "preconditioners/akvf_preconditioner_2d.h"

#include "preconditioners/energy_scale.h"

namespace akvf {

AkvfPreconditioner2D::AkvfPreconditioner2D(const MeshObjective2D& objective, AkvfOptions2D options)
    : FactoredPreconditioner2D(objective, options.factor),
      objective_(objective),
      options_(options),
      divergence_weight_(options.divergence_weight.value_or(rest_divergence_weight(objective.density()))) {}

void AkvfPreconditioner2D::assemble(const OptimizationState& state, ElementMatrix2D* matrix) {
  assemble_killing_operator_2d(objective_.elements(), state.x, objective_.rest().area, options_.area_scaling, matrix,
                               divergence_weight_);
}

}  // namespace akvf
