#include "preconditioners/slim_preconditioner.h"

#include <Eigen/SVD>
#include <cmath>

#include "akvf/error.h"
#include "framework/optimization/element_derivatives.h"

namespace akvf {

namespace {

template <int D>
const SingularValueDerivative<D>& singular_value_density(const MeshObjective<D>& objective) {
  const auto* density = dynamic_cast<const SingularValueDerivative<D>*>(&objective.density());
  if (!density)
    throw OptionsError("the slim preconditioner needs an energy with a singular-value derivative; '" +
                       objective.density().name() + "' has none");
  return *density;
}

// The orthogonal projector, in vec(J) (column-major), onto the directions
// (s I + Omega) J, Omega skew: J's image scaled and turned, tangent to the
// orbit on which a scale-invariant density is constant. J is invertible
// (det J > 0), so the directions are independent; each turn is orthogonal
// to J (tr(J^T Omega J) = 0), and in 3D the turns are made orthonormal by
// Gram-Schmidt.
template <int D>
Eigen::Matrix<double, D * D, D * D> similarity_orbit_projector(const Eigen::Matrix<double, D, D>& J) {
  using Square = Eigen::Matrix<double, D, D>;
  using Direction = Eigen::Matrix<double, D * D, 1>;
  constexpr int kDirections = 1 + D * (D - 1) / 2;  // the scale and the rotations' generators
  Eigen::Matrix<double, D * D, kDirections> basis;
  basis.col(0) = Eigen::Map<const Direction>(J.data()).normalized();
  int column = 1;
  for (int a = 0; a < D; ++a)
    for (int b = a + 1; b < D; ++b) {
      Square omega = Square::Zero();
      omega(a, b) = -1;
      omega(b, a) = 1;
      const Square turned = omega * J;
      Direction v = Eigen::Map<const Direction>(turned.data());
      for (int k = 1; k < column; ++k) v -= basis.col(k).dot(v) * basis.col(k);
      basis.col(column++) = v.normalized();
    }
  return basis * basis.transpose();
}

}  // namespace

template <int D>
void SlimPreconditioner<D>::soften_invariant_directions(const Square& J, SquareHessian* H) {
  const SquareHessian orbit = similarity_orbit_projector<D>(J);
  const SquareHessian rest = SquareHessian::Identity() - orbit;
  *H = rest * *H * rest + kInvariantShare * orbit * *H * orbit;
}

template <int D>
SlimPreconditioner<D>::SlimPreconditioner(const MeshObjective<D>& objective, FactorOptions options,
                                          MotionProjection projection)
    : FactoredPreconditioner<D>(objective, std::move(options)),
      objective_(objective),
      density_(singular_value_density(objective)),
      projection_(projection) {}

template <int D>
void SlimPreconditioner<D>::proxy_weights(const SingularValueDerivative<D>& density, const Square& J, Square* WtW,
                                          Square* R) {
  using Vector = Eigen::Matrix<double, D, 1>;
  const Eigen::JacobiSVD<Square> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Square U = svd.matrixU(), V = svd.matrixV();
  Vector sigma = svd.singularValues();
  if (U.determinant() * V.determinant() < 0) {  // det J > 0 expected: make U V^T a rotation
    U.col(D - 1) *= -1;
    sigma[D - 1] *= -1;
  }
  // The singular values of the nearest element where D is minimal: a
  // rotation, or for a scale-invariant density the similarity of the
  // geometric mean (libigl's SLIM does the same for its conformal energy).
  const double target = density.minimal_at_similarities() ? std::pow(std::abs(sigma.prod()), 1.0 / D) : 1.0;
  const Vector dD = density.singular_value_gradient(sigma);
  Vector w2;
  for (int i = 0; i < D; ++i) {
    const double gap = sigma[i] - target;
    // At sigma = target use the limit dD/dsigma / (2 (sigma - target)),
    // approximated by a one-sided difference.
    if (std::abs(gap) < 1e-8 * target) {
      const double h = 1e-6 * target;
      Vector shifted = sigma;
      shifted[i] = target + h;
      w2[i] = density.singular_value_gradient(shifted)[i] / (2 * h);
    } else {
      w2[i] = dD[i] / (2 * gap);
    }
    // No positive weight gives the gradient: the proxy's curvature along
    // sigma_i, 2 w_i^2, is the energy's there (a central difference of
    // dD/dsigma_i) instead, so that the element keeps its stiffness.
    if (!(w2[i] > 0)) {
      const double h = 1e-6 * std::abs(sigma[i]);
      Vector up = sigma, down = sigma;
      up[i] += h;
      down[i] -= h;
      w2[i] = (density.singular_value_gradient(up)[i] - density.singular_value_gradient(down)[i]) / (4 * h);
    }
    w2[i] = std::max(w2[i], 1e-8);
  }
  *WtW = U * w2.asDiagonal() * U.transpose();
  *R = target * U * V.transpose();
}

template <int D>
void SlimPreconditioner<D>::assemble(const OptimizationState& state, Matrix* matrix) {
  matrix->assemble([&](int e, typename Matrix::Local* local) {
    Square WtW, R;
    const Square J = objective_.jacobian(state.x, e);
    proxy_weights(density_, J, &WtW, &R);
    // Hessian of |W (J - R)|^2 in vec(J) (column-major): I_D (x) 2 W^T W.
    Eigen::Matrix<double, D * D, D* D> H = Eigen::Matrix<double, D * D, D * D>::Zero();
    for (int c = 0; c < D; ++c) H.template block<D, D>(D * c, D * c) = 2 * WtW;
    if (density_.minimal_at_similarities()) soften_invariant_directions(J, &H);
    typename DistortionDensity<D>::Hessian barrier;
    if (objective_.density().collapse_barrier_hessian(J, &barrier)) H += barrier;
    const auto G = jacobian_map<D>(objective_.rest().Dm_inv[e]);
    *local = objective_.weights()[e] * G.transpose() * H * G;
  });
}

template class SlimPreconditioner<2>;
template class SlimPreconditioner<3>;

}  // namespace akvf
