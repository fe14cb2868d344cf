#include "energies/arap.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <limits>

#include "energies/invariant_density_3d.h"
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

// The collapse barrier b(g) = -(r - 1)^2 log r in r = g / hat for g < hat
// (IPC's barrier, C2 at r = 1) and its first two derivatives in g.
struct CollapseBarrier {
  double b = 0, b_g = 0, b_gg = 0;
  CollapseBarrier(double g, double hat) {
    if (!(g < hat)) return;
    const double r = g / hat, gap = r - 1, log_r = std::log(r);
    b = -gap * gap * log_r;
    b_g = (-2 * gap * log_r - gap * gap / r) / hat;
    b_gg = (-2 * log_r - 4 * gap / r + gap * gap / (r * r)) / (hat * hat);
  }
};

// The barrier's eigenvalues added in the singular-value frame (Smith et
// al.; the barrier is b(sigma_1 sigma_2 sigma_3)): for the pair (i, j) with
// third index k, twist b_g sigma_k and flip -b_g sigma_k; the scalings'
// matrix b_gg p p^T (p_i = g / sigma_i) plus b_g sigma_k at (i, j) off the
// diagonal.
void add_barrier_eigenvalues(const CollapseBarrier& barrier, SingularEigensystem3D* system) {
  const Eigen::Vector3d& sigma = system->sigma;
  const Eigen::Vector3d p(sigma[1] * sigma[2], sigma[2] * sigma[0], sigma[0] * sigma[1]);
  for (int k = 0; k < 3; ++k) {
    system->twist[k] += barrier.b_g * sigma[k];
    system->flip[k] -= barrier.b_g * sigma[k];
  }
  system->scaling += barrier.b_gg * p * p.transpose();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j) system->scaling(i, j) += barrier.b_g * sigma[3 - i - j];
}

// Arap3D's eigensystem at J (arap.h), its collapse barrier's eigenvalues added.
SingularEigensystem3D arap_eigensystem(const Eigen::Matrix3d& J, double collapse_volume_ratio) {
  SingularEigensystem3D system(J);
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    system.twist[k] = 2 - 4 / (system.sigma[i] + system.sigma[j]);
    system.flip[k] = 2;
  }
  system.scaling = 2 * Eigen::Matrix3d::Identity();
  add_barrier_eigenvalues(CollapseBarrier(J.determinant(), collapse_volume_ratio), &system);
  return system;
}

}  // namespace

InvariantDerivatives2D Arap2D::derivatives(double s, double g) const {
  const double root = std::sqrt(s + 2 * g);
  const double inv3 = 1 / (root * root * root);
  InvariantDerivatives2D d = {s - 2 * root + 2, 1 - 1 / root, -2 / root, 0.5 * inv3, inv3, 2 * inv3};
  const CollapseBarrier barrier(g, collapse_area_ratio());
  d.f += barrier.b;
  d.f_g += barrier.b_g;
  d.f_gg += barrier.b_gg;
  return d;
}

bool Arap2D::collapse_barrier_hessian(const Matrix& J, Hessian* H) const {
  const double g = J.determinant();
  if (!(g > 0 && g < collapse_area_ratio())) return false;
  // d2 b(det J) / dvec(J)^2 = b_gg c c^T + b_g H_det, c the cofactor.
  const CollapseBarrier barrier(g, collapse_area_ratio());
  const Eigen::Vector4d c = cofactor_2d(J);
  *H = with_eigenvalues(barrier.b_gg * c * c.transpose() + barrier.b_g * determinant_hessian_2d(),
                        [](double lambda) { return lambda > 0 ? lambda : 0.0; });
  return true;
}

double Arap3D::value(const Matrix& J) const {
  const double g = J.determinant();
  if (!(g > 0)) return kInvertedEnergy;
  return (Rotation(J).sigma.array() - 1).square().sum() + CollapseBarrier(g, collapse_volume_ratio()).b;
}

double Arap3D::value_and_gradient(const Matrix& J, Matrix* dD_dJ) const {
  const double g = J.determinant();
  if (!(g > 0)) return kInvertedEnergy;
  const Rotation polar(J);
  const CollapseBarrier barrier(g, collapse_volume_ratio());
  *dD_dJ = 2 * (J - polar.R());
  if (barrier.b_g != 0) *dD_dJ += barrier.b_g * cofactor_3d(J);
  return (polar.sigma.array() - 1).square().sum() + barrier.b;
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
  const CollapseBarrier barrier(J.determinant(), collapse_volume_ratio());
  if (barrier.b_g != 0) {
    const Eigen::Matrix3d C = cofactor_3d(J);
    const Eigen::Map<const Eigen::Matrix<double, 9, 1>> c(C.data());
    H += barrier.b_gg * c * c.transpose() + barrier.b_g * determinant_hessian_3d(J);
  }
  return H;
}

Arap3D::Hessian Arap3D::filtered_hessian(const Matrix& J, bool absolute) const {
  return arap_eigensystem(J, collapse_volume_ratio()).filtered_hessian(absolute);
}

Arap3D::Eigenpairs Arap3D::hessian_eigensystem(const Matrix& J) const {
  return arap_eigensystem(J, collapse_volume_ratio()).eigenpairs();
}

bool Arap3D::collapse_barrier_hessian(const Matrix& J, Hessian* H) const {
  const double g = J.determinant();
  if (!(g > 0 && g < collapse_volume_ratio())) return false;
  SingularEigensystem3D system(J);
  add_barrier_eigenvalues(CollapseBarrier(g, collapse_volume_ratio()), &system);
  *H = system.filtered_hessian(false);
  return true;
}

Eigen::Vector3d Arap3D::singular_value_gradient(const Eigen::Vector3d& sigma) const {
  const CollapseBarrier barrier(sigma.prod(), collapse_volume_ratio());
  const Eigen::Vector3d p(sigma[1] * sigma[2], sigma[2] * sigma[0], sigma[0] * sigma[1]);
  return 2 * (sigma.array() - 1).matrix() + barrier.b_g * p;
}

}  // namespace akvf
