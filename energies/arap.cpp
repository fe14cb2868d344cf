#include "energies/arap.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <limits>

#include "energies/singular_eigensystem_3d.h"

namespace akvf {

namespace {

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

InvariantDerivatives2D Arap2D::derivatives(double s, double g) const {
  const double root = std::sqrt(s + 2 * g);
  const double inv3 = 1 / (root * root * root);
  InvariantDerivatives2D d = {s - 2 * root + 2, 1 - 1 / root, -2 / root, 0.5 * inv3, inv3, 2 * inv3};
  const double hat = collapse_area_ratio();
  if (g < hat) {  // b = -(r - 1)^2 log r in r = g / hat, C2 at r = 1 (IPC's barrier)
    const double r = g / hat, gap = r - 1, log_r = std::log(r);
    d.f += -gap * gap * log_r;
    d.f_g += (-2 * gap * log_r - gap * gap / r) / hat;
    d.f_gg += (-2 * log_r - 4 * gap / r + gap * gap / (r * r)) / (hat * hat);
  }
  return d;
}

double Arap3D::value(const Matrix& J) const {
  if (!(J.determinant() > 0)) return kInvertedEnergy;
  return (Rotation(J).sigma.array() - 1).square().sum();
}

double Arap3D::value_and_gradient(const Matrix& J, Matrix* dD_dJ) const {
  if (!(J.determinant() > 0)) return kInvertedEnergy;
  const Rotation polar(J);
  *dD_dJ = 2 * (J - polar.R());
  return (polar.sigma.array() - 1).square().sum();
}

Arap3D::Hessian Arap3D::hessian(const Matrix& J) const {
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

Arap3D::Hessian Arap3D::filtered_hessian(const Matrix& J, bool absolute) const {
  SingularEigensystem3D system(J);
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    system.twist[k] = 2 - 4 / (system.sigma[i] + system.sigma[j]);
    system.flip[k] = 2;
  }
  system.scaling = 2 * Eigen::Matrix3d::Identity();
  return system.filtered_hessian(absolute);
}

Eigen::Vector3d Arap3D::singular_value_gradient(const Eigen::Vector3d& sigma) const {
  return 2 * (sigma.array() - 1).matrix();
}

}  // namespace akvf
