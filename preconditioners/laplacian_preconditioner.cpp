#include "preconditioners/laplacian_preconditioner.h"

namespace akvf {

LaplacianPreconditioner2D::LaplacianPreconditioner2D(const ParamObjective& objective, FactorOptions options)
    : FactoredPreconditioner2D(objective.faces(), objective.num_vertices(), options),
      objective_(objective),
      translations_(translation_basis_2d(objective.num_vertices())) {}

void LaplacianPreconditioner2D::assemble(const OptimizationState&, ElementMatrix2D* matrix) {
  matrix->assemble([&](int f, ElementMatrix2D::Local* local) {
    // Rest hat-function gradients: rows of Dm^-1 for corners 1, 2; corner 0 is minus their sum.
    const Eigen::Matrix2d& Dm_inv = objective_.rest().Dm_inv[f];
    const Eigen::Vector2d grad[3] = {-(Dm_inv.row(0) + Dm_inv.row(1)).transpose(), Dm_inv.row(0).transpose(),
                                     Dm_inv.row(1).transpose()};
    local->setZero();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        local->block<2, 2>(2 * i, 2 * j) = objective_.weights()[f] * grad[i].dot(grad[j]) * Eigen::Matrix2d::Identity();
  });
}

}  // namespace akvf
