#pragma once
// The geometric proxies (the Killing operator, the Laplacian) carry no unit
// of the energy: K's quadratic form is (1/2) sum_t V_t |G_t + G_t^T|^2 for
// the velocity gradients G_t, the Laplacian's sum_t V_t |G_t|^2, whatever
// the energy. Alone (2D parameterization) that only rescales the step; next
// to a term with its own scale (the soft constraints' Hessian 2w in 3D
// deformation) the proxy must be brought to the energy's curvature, or one
// of the two dominates every direction. This is the energy's curvature at
// rest along a unit shear, the reference both proxies are scaled to.
#include "framework/optimization/distortion_density.h"

namespace akvf {

// vec(S)^T [d^2 D / dvec(J)^2 at J = I] vec(S), S = e1 e2^T + e2 e1^T
// (|S|^2 = 2, (1/2)|S + S^T|^2 = 4). Positive for every energy here.
inline double rest_shear_curvature(const DistortionDensity<3>& density) {
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  S(0, 1) = S(1, 0) = 1;
  const Eigen::Map<const Eigen::Matrix<double, 9, 1>> s(S.data());
  return s.dot(density.hessian(Eigen::Matrix3d::Identity()) * s);
}

}  // namespace akvf
