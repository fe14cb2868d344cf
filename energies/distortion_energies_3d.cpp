#include "energies/distortion_energies_3d.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <limits>

#include "energies/exponent.h"
#include "framework/process/error.h"

namespace akvf {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Derivatives of exp(k u) from those of u.
InvariantDerivatives3 exponentiate(const InvariantDerivatives3& u, double k) {
  InvariantDerivatives3 d;
  d.f = std::exp(k * u.f);
  const double kf = k * d.f;
  d.f_s = kf * u.f_s;
  d.f_c = kf * u.f_c;
  d.f_g = kf * u.f_g;
  d.f_ss = kf * (u.f_ss + k * u.f_s * u.f_s);
  d.f_sc = kf * (u.f_sc + k * u.f_s * u.f_c);
  d.f_sg = kf * (u.f_sg + k * u.f_s * u.f_g);
  d.f_cc = kf * (u.f_cc + k * u.f_c * u.f_c);
  d.f_cg = kf * (u.f_cg + k * u.f_c * u.f_g);
  d.f_gg = kf * (u.f_gg + k * u.f_g * u.f_g);
  return d;
}

// u = s / (6 g^(2/3)) + (g + 1/g) / 4: the AMIPS exponent's argument.
InvariantDerivatives3 amips_argument(double s, double g) {
  const double g23 = std::cbrt(g * g), g2 = g * g;
  InvariantDerivatives3 u;
  u.f = s / (6 * g23) + (g + 1 / g) / 4;
  u.f_s = 1 / (6 * g23);
  u.f_g = -s / (9 * g23 * g) + (1 - 1 / g2) / 4;
  u.f_sg = -1 / (9 * g23 * g);
  u.f_gg = 5 * s / (27 * g23 * g2) + 1 / (2 * g2 * g);
  return u;
}

// SVD of J with U V^T a rotation (J is not inverted).
struct Rotation {
  Eigen::Matrix3d U, V;
  Eigen::Vector3d sigma;
  explicit Rotation(const Eigen::Matrix3d& J) {
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
    U = svd.matrixU();
    V = svd.matrixV();
    sigma = svd.singularValues();
  }
  Eigen::Matrix3d R() const { return U * V.transpose(); }
};

}  // namespace

ExpSymmetricDirichlet3::ExpSymmetricDirichlet3(double exponent) : exponent_(checked_exponent(exponent)) {}

double ExpSymmetricDirichlet3::lower_bound() const { return std::exp(6 * exponent_); }

InvariantDerivatives3 ExpSymmetricDirichlet3::derivatives(double s, double c, double g) const {
  return exponentiate(SymmetricDirichlet3::formula(s, c, g), exponent_);
}

InvariantDerivatives3 Mips3::derivatives(double s, double, double g) const {
  const double g23 = std::cbrt(g * g);
  InvariantDerivatives3 d;
  d.f = s / g23;
  d.f_s = 1 / g23;
  d.f_g = -2 * s / (3 * g23 * g);
  d.f_sg = -2 / (3 * g23 * g);
  d.f_gg = 10 * s / (9 * g23 * g * g);
  return d;
}

Amips3::Amips3(double exponent) : exponent_(checked_exponent(exponent)) {}

double Amips3::lower_bound() const { return std::exp(exponent_); }

InvariantDerivatives3 Amips3::derivatives(double s, double, double g) const {
  return exponentiate(amips_argument(s, g), exponent_);
}

double Arap3::value(const Matrix& J) const {
  if (!(J.determinant() > 0)) return kInfinity;
  return (Rotation(J).sigma.array() - 1).square().sum();
}

double Arap3::value_and_gradient(const Matrix& J, Matrix* dD_dJ) const {
  if (!(J.determinant() > 0)) return kInfinity;
  const Rotation polar(J);
  *dD_dJ = 2 * (J - polar.R());
  return (polar.sigma.array() - 1).square().sum();
}

Arap3::Hessian Arap3::hessian(const Matrix& J) const {
  const Rotation polar(J);
  Hessian H = 2 * Hessian::Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      Eigen::Matrix3d twist = polar.U.col(i) * polar.V.col(j).transpose() - polar.U.col(j) * polar.V.col(i).transpose();
      twist /= std::sqrt(2.0);
      const Eigen::Map<const Eigen::Matrix<double, 9, 1>> t(twist.data());
      H -= (4 / (polar.sigma[i] + polar.sigma[j])) * t * t.transpose();
    }
  return H;
}

Eigen::Vector3d Arap3::singular_value_gradient(const Eigen::Vector3d& sigma) const {
  return 2 * (sigma.array() - 1).matrix();
}

}  // namespace akvf
