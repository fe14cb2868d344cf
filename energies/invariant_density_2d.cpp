#include "energies/invariant_density_2d.h"

#include <limits>

namespace akvf {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// vec(J) and the cofactor c = d det / dvec(J), column-major.
Eigen::Vector4d vec(const Eigen::Matrix2d& J) { return {J(0, 0), J(1, 0), J(0, 1), J(1, 1)}; }
Eigen::Vector4d cofactor(const Eigen::Matrix2d& J) { return {J(1, 1), -J(0, 1), -J(1, 0), J(0, 0)}; }

}  // namespace

double InvariantDensity2D::value(const Matrix& J) const {
  const double g = J.determinant();
  return g > 0 ? derivatives(J.squaredNorm(), g).f : kInfinity;
}

double InvariantDensity2D::value_and_gradient(const Matrix& J, Matrix* dD_dJ) const {
  const double g = J.determinant();
  if (!(g > 0)) return kInfinity;
  const InvariantDerivatives2D d = derivatives(J.squaredNorm(), g);
  Matrix c;
  c << J(1, 1), -J(1, 0), -J(0, 1), J(0, 0);
  *dD_dJ = 2 * d.f_s * J + d.f_g * c;
  return d.f;
}

InvariantDensity2D::Hessian InvariantDensity2D::hessian(const Matrix& J) const {
  const InvariantDerivatives2D d = derivatives(J.squaredNorm(), J.determinant());
  Eigen::Matrix<double, 4, 2> G;  // gradients of (s, g) with respect to vec(J)
  G.col(0) = 2 * vec(J);
  G.col(1) = cofactor(J);
  Eigen::Matrix2d second;
  second << d.f_ss, d.f_sg, d.f_sg, d.f_gg;
  Hessian det_hessian = Hessian::Zero();
  det_hessian(0, 3) = det_hessian(3, 0) = 1;
  det_hessian(1, 2) = det_hessian(2, 1) = -1;
  return 2 * d.f_s * Hessian::Identity() + d.f_g * det_hessian + G * second * G.transpose();
}

Eigen::Vector2d InvariantDensity2D::singular_value_gradient(const Eigen::Vector2d& sigma) const {
  const InvariantDerivatives2D d = derivatives(sigma.squaredNorm(), sigma[0] * sigma[1]);
  return {2 * d.f_s * sigma[0] + d.f_g * sigma[1], 2 * d.f_s * sigma[1] + d.f_g * sigma[0]};
}

}  // namespace akvf
