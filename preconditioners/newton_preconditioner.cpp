#include "preconditioners/newton_preconditioner.h"

namespace akvf {

Eigen::Matrix<double, 4, 6> jacobian_map(const Eigen::Matrix2d& Dm_inv) {
  // J(r, c) = sum_k (x_{k+1} - x_0)[r] Dm_inv(k, c); vec index r + 2c, dof 2 i + r.
  Eigen::Matrix<double, 4, 6> G = Eigen::Matrix<double, 4, 6>::Zero();
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) {
      G(r + 2 * c, r) = -(Dm_inv(0, c) + Dm_inv(1, c));
      G(r + 2 * c, 2 + r) = Dm_inv(0, c);
      G(r + 2 * c, 4 + r) = Dm_inv(1, c);
    }
  return G;
}

NewtonPreconditioner2D::NewtonPreconditioner2D(const ParamObjective& objective, FactorOptions options)
    : FactoredPreconditioner2D(objective.faces(), objective.num_vertices(), options), objective_(objective) {}

void NewtonPreconditioner2D::assemble(const OptimizationState& state, ElementMatrix2D* matrix) {
  matrix->assemble([&](int f, ElementMatrix2D::Local* local) {
    const Eigen::Matrix<double, 4, 6> G = jacobian_map(objective_.rest().Dm_inv[f]);
    const Eigen::Matrix4d H = objective_.density().projected_hessian(objective_.jacobian(state.x, f));
    *local = objective_.weights()[f] * G.transpose() * H * G;
  });
}

}  // namespace akvf
