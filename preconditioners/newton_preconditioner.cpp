#include "preconditioners/newton_preconditioner.h"

#include "preconditioners/element_derivatives.h"

namespace akvf {

template <int D>
NewtonPreconditioner<D>::NewtonPreconditioner(const MeshObjective<D>& objective, FactorOptions options,
                                              MotionProjection projection)
    : FactoredPreconditioner<D>(objective, std::move(options)), objective_(objective), projection_(projection) {}

template <int D>
void NewtonPreconditioner<D>::assemble(const OptimizationState& state, Matrix* matrix) {
  matrix->assemble([&](int e, typename Matrix::Local* local) {
    const auto G = jacobian_map<D>(objective_.rest().Dm_inv[e]);
    const auto H = objective_.density().projected_hessian(objective_.jacobian(state.x, e));
    *local = objective_.weights()[e] * G.transpose() * H * G;
  });
}

template class NewtonPreconditioner<2>;
template class NewtonPreconditioner<3>;

}  // namespace akvf
