#pragma once
// The geometric proxies (the Killing operator, the Laplacian) carry no unit
// of the energy: K's quadratic form is (1/2) sum_t V_t |G_t + G_t^T|^2 for
// the velocity gradients G_t, the Laplacian's sum_t V_t |G_t|^2, whatever
// the energy. Alone (2D parameterization) that only rescales the step; next
// to a term with its own scale (the soft constraints' Hessian 2w in 3D
// deformation) the proxy must be brought to the energy's curvature, or one
// of the two dominates every direction. This is the energy's curvature at
// rest along a unit shear, the reference both proxies are scaled to.
#include <algorithm>
#include <cmath>

#include "akvf/distortion_density.h"

namespace akvf {

// vec(S)^T [d^2 D / dvec(J)^2 at J = I] vec(S), S = e1 e2^T + e2 e1^T
// (|S|^2 = 2, (1/2)|S + S^T|^2 = 4). Positive for every energy here.
template <int D>
double rest_shear_curvature(const DistortionDensity<D>& density) {
  Eigen::Matrix<double, D, D> S = Eigen::Matrix<double, D, D>::Zero();
  S(0, 1) = S(1, 0) = 1;
  const Eigen::Map<const Eigen::Matrix<double, D * D, 1>> s(S.data());
  return s.dot(density.hessian(Eigen::Matrix<double, D, D>::Identity()) * s);
}

// The step along AKVF's direction d = -K^+ grad E that Newton's method would
// take at an isometry, 1 / c with c = (energy's curvature) / (K's curvature)
// along a rest shear: the energy, normalized by the rest measure, curves by
// rest_shear_curvature / measure; K by 4 per unit measure. For the energies
// whose second variation at a rotation R is a multiple of |sym(R^T dJ)|^2
// (symmetric Dirichlet: 2|A|^2 + 2 tr(A^2) = 4|sym A|^2; ARAP; their
// exponentials, whose gradient vanishes there), the Hessian at an isometric
// map *is* c K(x), so AKVF is Newton's method there up to this step
// (symmetric Dirichlet on a unit-area mesh: c = 16 / 4, the step 1/4).
template <int D>
double isometric_newton_step(const DistortionDensity<D>& density, double rest_measure) {
  return 4 * rest_measure / rest_shear_curvature(density);
}

// The divergence weight beta of K_beta (killing_operator_2d.h, _3d.h) that
// makes c K_beta the density's Hessian at the rest isometry along dilations
// as well as shears. A rotation-invariant density's Hessian at I is
// a |sym_0 A|^2 + b (tr A)^2 (the skew part is a rotation), and K_beta's
// form is 2 |sym_0 G|^2 + beta (2/D) (tr G)^2: along the shear S both curve
// by 4 and H_S, along the dilation I by 2 D beta and H_I, so
// beta = 2 H_I / (D H_S). It is 1 (K itself) for symmetric Dirichlet, ARAP,
// the exponential energy and 2D AMIPS, 0 for MIPS, which does not feel
// dilations, 9/4 for 3D AMIPS. The ratio is rounded to 0 or 1 when within
// 1e-9 of it (the chain rule's rounding is about 1e-15), so those K are the
// paper's to the bit; it is never negative.
template <int D>
double rest_divergence_weight(const DistortionDensity<D>& density) {
  const Eigen::Matrix<double, D, D> I = Eigen::Matrix<double, D, D>::Identity();
  const Eigen::Map<const Eigen::Matrix<double, D * D, 1>> i(I.data());
  const double beta = std::max(0.0, 2 * i.dot(density.hessian(I) * i) / (D * rest_shear_curvature(density)));
  for (const double exact : {0.0, 1.0})
    if (std::abs(beta - exact) <= 1e-9) return exact;
  return beta;
}

}  // namespace akvf
