#include "preconditioners/laplacian_preconditioner.h"

#include "framework/optimization/element_derivatives.h"

namespace akvf {

template <int D>
LaplacianPreconditioner<D>::LaplacianPreconditioner(const MeshObjective<D>& objective, FactorOptions options,
                                                    MotionProjection projection, double scale)
    : FactoredPreconditioner<D>(objective, std::move(options)),
      objective_(objective),
      projection_(projection),
      scale_(scale) {}

template <int D>
void LaplacianPreconditioner<D>::assemble(const OptimizationState&, Matrix* matrix) {
  matrix->assemble([&](int e, typename Matrix::Local* local) {
    const auto grad = hat_gradients<D>(objective_.rest().Dm_inv[e]);
    local->setZero();
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j <= D; ++j)
        local->template block<D, D>(D * i, D * j) =
            scale_ * objective_.weights()[e] * grad[i].dot(grad[j]) * Eigen::Matrix<double, D, D>::Identity();
  });
}

template class LaplacianPreconditioner<2>;
template class LaplacianPreconditioner<3>;

}  // namespace akvf
