#include "energies/invariant_density_2d.h"

#include <cmath>
#include <limits>

namespace akvf {

namespace {

Eigen::Vector4d vec_2d(const Eigen::Matrix2d& J) { return {J(0, 0), J(1, 0), J(0, 1), J(1, 1)}; }

}  // namespace

Eigen::Vector4d cofactor_2d(const Eigen::Matrix2d& J) { return {J(1, 1), -J(0, 1), -J(1, 0), J(0, 0)}; }

Eigen::Matrix4d determinant_hessian_2d() {
  Eigen::Matrix4d H = Eigen::Matrix4d::Zero();
  H(0, 3) = H(3, 0) = 1;
  H(1, 2) = H(2, 1) = -1;
  return H;
}

double InvariantDensity2D::value(const Matrix& J) const {
  const double g = J.determinant();
  return g > 0 ? derivatives(J.squaredNorm(), g).f : kInvertedEnergy;
}

double InvariantDensity2D::value_and_gradient(const Matrix& J, Matrix* dD_dJ) const {
  const double g = J.determinant();
  if (!(g > 0)) return kInvertedEnergy;
  const InvariantDerivatives2D d = derivatives(J.squaredNorm(), g);
  Matrix c;
  c << J(1, 1), -J(1, 0), -J(0, 1), J(0, 0);
  *dD_dJ = 2 * d.f_s * J + d.f_g * c;
  return d.f;
}

InvariantDensity2D::Hessian InvariantDensity2D::hessian(const Matrix& J) const {
  const InvariantDerivatives2D d = derivatives(J.squaredNorm(), J.determinant());
  Eigen::Matrix<double, 4, 2> G;  // gradients of (s, g) with respect to vec_2d(J)
  G.col(0) = 2 * vec_2d(J);
  G.col(1) = cofactor_2d(J);
  Eigen::Matrix2d second;
  second << d.f_ss, d.f_sg, d.f_sg, d.f_gg;
  return 2 * d.f_s * Hessian::Identity() + d.f_g * determinant_hessian_2d() + G * second * G.transpose();
}

namespace {
// |(a, b)|: sqrt(a^2 + b^2), where it does not overflow (std::hypot, which
// guards against that at every call, took 8 % of a one-core run whose
// Newton phase is long: tricera_b x4).
double norm_2d(double a, double b) {
  const double norm = std::sqrt(a * a + b * b);
  return std::isfinite(norm) ? norm : std::hypot(a, b);
}
}  // namespace

InvariantDensity2D::Eigenpairs InvariantDensity2D::hessian_eigensystem(const Matrix& J) const {
  // Signed SVD in closed form: J = R(phi) diag(s1, s2) R(theta), R(t) the
  // rotation by t, phi = (a2 + a1) / 2, theta = (a2 - a1) / 2 with
  // (cos, sin)(a1) = (F, G) / R and (cos, sin)(a2) = (E, H) / Q; s2 < 0 iff
  // det J < 0. The eigenmodes U M V^T below need only a1 and a2: with
  // T = [0 -1; 1 0], X = [0 1; 1 0], D = diag(1, -1), R(phi) T R(theta) =
  // T R(a2), R(phi) X R(theta) = X R(-a1), R(phi) R(theta) = R(a2) and
  // R(phi) D R(theta) = D R(-a1).
  const double E = (J(0, 0) + J(1, 1)) / 2, F = (J(0, 0) - J(1, 1)) / 2;
  const double G = (J(1, 0) + J(0, 1)) / 2, H = (J(1, 0) - J(0, 1)) / 2;
  const double Q = norm_2d(E, H), R = norm_2d(F, G);
  const double s1 = Q + R, s2 = Q - R;
  const double c_2 = Q > 0 ? E / Q : 1, s_2 = Q > 0 ? H / Q : 0;  // a2
  const double c_1 = R > 0 ? F / R : 1, s_1 = R > 0 ? G / R : 0;  // a1
  Eigen::Matrix2d rotation, reflection, twist, flip;              // R(a2), D R(-a1), T R(a2), X R(-a1)
  rotation << c_2, -s_2, s_2, c_2;
  reflection << c_1, s_1, s_1, -c_1;
  twist << -s_2, -c_2, c_2, -s_2;
  flip << -s_1, c_1, c_1, s_1;

  const InvariantDerivatives2D d = derivatives(J.squaredNorm(), J.determinant());
  Eigen::Matrix2d B, S, A;
  B << 2 * s1, 2 * s2, s2, s1;
  S << d.f_ss, d.f_sg, d.f_sg, d.f_gg;
  A << 2 * d.f_s, d.f_g, d.f_g, 2 * d.f_s;
  A += B.transpose() * S * B;
  // Eigenpairs of the symmetric 2x2 A: (cos, sin) of half the angle of
  // (x, y), x = (A00 - A11) / 2, y = A01, by the half-angle formulas.
  const double x = (A(0, 0) - A(1, 1)) / 2, y = A(0, 1);
  const double mean = (A(0, 0) + A(1, 1)) / 2, half_gap = norm_2d(x, y);
  double ca = 1, sa = 0;
  if (half_gap > 0 && x >= 0) {
    ca = std::sqrt((1 + x / half_gap) / 2);
    sa = y / (2 * half_gap * ca);
  } else if (half_gap > 0) {
    sa = std::copysign(std::sqrt((1 - x / half_gap) / 2), y);
    ca = y / (2 * half_gap * sa);
  }

  Eigenpairs pairs;
  const double r = 1 / std::sqrt(2.0);
  pairs.values << 2 * d.f_s + d.f_g, 2 * d.f_s - d.f_g, mean + half_gap, mean - half_gap;
  pairs.modes[0] = r * twist;
  pairs.modes[1] = r * flip;
  // diag(u, v) = (u + v) / 2 I + (u - v) / 2 D, for e1 = (ca, sa) and e2 = (-sa, ca).
  pairs.modes[2] = (ca + sa) / 2 * rotation + (ca - sa) / 2 * reflection;
  pairs.modes[3] = (ca - sa) / 2 * rotation - (sa + ca) / 2 * reflection;
  return pairs;
}

InvariantDensity2D::Hessian InvariantDensity2D::filtered_hessian(const Matrix& J, bool absolute) const {
  const Eigenpairs pairs = hessian_eigensystem(J);
  Hessian P = Hessian::Zero();
  for (int i = 0; i < 4; ++i) {
    const double lambda = absolute ? std::abs(pairs.values[i]) : pairs.values[i];
    if (!(lambda > 0)) continue;
    const Eigen::Vector4d v = vec_2d(pairs.modes[i]);
    P += lambda * v * v.transpose();
  }
  return P;
}

Eigen::Vector2d InvariantDensity2D::singular_value_gradient(const Eigen::Vector2d& sigma) const {
  const InvariantDerivatives2D d = derivatives(sigma.squaredNorm(), sigma[0] * sigma[1]);
  return {2 * d.f_s * sigma[0] + d.f_g * sigma[1], 2 * d.f_s * sigma[1] + d.f_g * sigma[0]};
}

}  // namespace akvf
