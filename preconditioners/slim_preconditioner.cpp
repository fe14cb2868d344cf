#include "preconditioners/slim_preconditioner.h"

#include <Eigen/SVD>
#include <cmath>

#include "framework/error.h"
#include "preconditioners/newton_preconditioner.h"

namespace akvf {

namespace {

const InvariantDensity2& singular_value_density(const ParamObjective& objective) {
  const auto* density = dynamic_cast<const InvariantDensity2*>(&objective.density());
  if (!density)
    throw OptionsError("the slim preconditioner needs an energy with a singular-value derivative; '" +
                       objective.density().name() + "' has none");
  return *density;
}

}  // namespace

SlimPreconditioner2D::SlimPreconditioner2D(const ParamObjective& objective, FactorOptions options)
    : FactoredPreconditioner2D(objective.faces(), objective.num_vertices(), options),
      objective_(objective),
      density_(singular_value_density(objective)),
      translations_(translation_basis_2d(objective.num_vertices())) {}

void SlimPreconditioner2D::proxy_weights(const InvariantDensity2& density, const Eigen::Matrix2d& J,
                                         Eigen::Matrix2d* WtW, Eigen::Matrix2d* R) {
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix2d U = svd.matrixU(), V = svd.matrixV();
  Eigen::Vector2d sigma = svd.singularValues();
  if (U.determinant() * V.determinant() < 0) {  // det J > 0: make U V^T a rotation
    U.col(1) *= -1;
    sigma[1] *= -1;
  }
  const Eigen::Vector2d dD = density.singular_value_gradient(sigma);
  Eigen::Vector2d w2;
  for (int i = 0; i < 2; ++i) {
    const double gap = sigma[i] - 1;
    // At sigma = 1 use the limit dD/dsigma / (2 (sigma - 1)) -> D''(1) / 2,
    // approximated by a one-sided difference.
    if (std::abs(gap) < 1e-8) {
      Eigen::Vector2d shifted = sigma;
      shifted[i] = 1 + 1e-6;
      w2[i] = density.singular_value_gradient(shifted)[i] / (2e-6);
    } else {
      w2[i] = dD[i] / (2 * gap);
    }
    w2[i] = std::max(w2[i], 1e-8);
  }
  *WtW = U * w2.asDiagonal() * U.transpose();
  *R = U * V.transpose();
}

void SlimPreconditioner2D::assemble(const OptimizationState& state, ElementMatrix2D* matrix) {
  matrix->assemble([&](int f, ElementMatrix2D::Local* local) {
    Eigen::Matrix2d WtW, R;
    proxy_weights(density_, objective_.jacobian(state.x, f), &WtW, &R);
    // Hessian of |W (J - R)|^2 in vec(J) (column-major): I_2 (x) 2 W^T W.
    Eigen::Matrix4d H = Eigen::Matrix4d::Zero();
    H.block<2, 2>(0, 0) = H.block<2, 2>(2, 2) = 2 * WtW;
    const Eigen::Matrix<double, 4, 6> G = jacobian_map(objective_.rest().Dm_inv[f]);
    *local = objective_.weights()[f] * G.transpose() * H * G;
  });
}

}  // namespace akvf
