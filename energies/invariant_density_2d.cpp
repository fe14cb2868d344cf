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

InvariantDensity2D::Hessian InvariantDensity2D::filtered_hessian(const Matrix& J, bool absolute) const {
  // Signed SVD in closed form: J = R(phi) diag(s1, s2) R(theta), R(t) the
  // rotation by t, so U = R(phi) and V = R(-theta); s2 < 0 iff det J < 0.
  const double E = (J(0, 0) + J(1, 1)) / 2, F = (J(0, 0) - J(1, 1)) / 2;
  const double G = (J(1, 0) + J(0, 1)) / 2, H = (J(1, 0) - J(0, 1)) / 2;
  const double Q = std::hypot(E, H), R = std::hypot(F, G);
  const double s1 = Q + R, s2 = Q - R;
  const double a1 = std::atan2(G, F), a2 = std::atan2(H, E);
  const double theta = (a2 - a1) / 2, phi = (a2 + a1) / 2;
  Eigen::Matrix2d U, Vt;
  U << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  Vt << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);

  const InvariantDerivatives2D d = derivatives(J.squaredNorm(), J.determinant());
  Eigen::Matrix2d B, S, A;
  B << 2 * s1, 2 * s2, s2, s1;
  S << d.f_ss, d.f_sg, d.f_sg, d.f_gg;
  A << 2 * d.f_s, d.f_g, d.f_g, 2 * d.f_s;
  A += B.transpose() * S * B;
  // Eigenpairs of the symmetric 2x2 A.
  const double mean = (A(0, 0) + A(1, 1)) / 2, half_gap = std::hypot((A(0, 0) - A(1, 1)) / 2, A(0, 1));
  const double angle = 0.5 * std::atan2(2 * A(0, 1), A(0, 0) - A(1, 1));
  const Eigen::Vector2d e1(std::cos(angle), std::sin(angle)), e2(-std::sin(angle), std::cos(angle));

  Hessian P = Hessian::Zero();
  const auto add = [&](double lambda, const Eigen::Matrix2d& M) {
    if (absolute) lambda = std::abs(lambda);
    if (!(lambda > 0)) return;
    const Eigen::Matrix2d mode = U * M * Vt;
    const Eigen::Vector4d v = vec_2d(mode);
    P += lambda * v * v.transpose();
  };
  const double r = 1 / std::sqrt(2.0);
  Eigen::Matrix2d twist, flip;
  twist << 0, -r, r, 0;
  flip << 0, r, r, 0;
  add(2 * d.f_s + d.f_g, twist);
  add(2 * d.f_s - d.f_g, flip);
  add(mean + half_gap, e1.asDiagonal().toDenseMatrix());
  add(mean - half_gap, e2.asDiagonal().toDenseMatrix());
  return P;
}

Eigen::Vector2d InvariantDensity2D::singular_value_gradient(const Eigen::Vector2d& sigma) const {
  const InvariantDerivatives2D d = derivatives(sigma.squaredNorm(), sigma[0] * sigma[1]);
  return {2 * d.f_s * sigma[0] + d.f_g * sigma[1], 2 * d.f_s * sigma[1] + d.f_g * sigma[0]};
}

}  // namespace akvf
