#include "energies/invariant_density_3d.h"

#include <Eigen/LU>
#include <cmath>
#include <limits>

#include "akvf/error.h"
#include "energies/singular_eigensystem_3d.h"

namespace akvf {

namespace {

using Matrix3 = Eigen::Matrix3d;
using Vector9 = Eigen::Matrix<double, 9, 1>;
using Matrix9 = Eigen::Matrix<double, 9, 9>;

Vector9 vec_3d(const Matrix3& M) { return Eigen::Map<const Vector9>(M.data()); }

double cofactor_norm2(const Matrix3& J) {
  const double s = J.squaredNorm();
  return 0.5 * (s * s - (J.transpose() * J).squaredNorm());
}

// Hessian of c = (s^2 - |J^T J|^2) / 2 in vec_3d(J):
//   4 j j^T + 2 s I - 2 [ (J^T J (x) I) + (J^T (x) J) K + (I (x) J J^T) ],
// K the commutation matrix (vec_3d(J^T) = K vec_3d(J)).
Matrix9 cofactor_norm_hessian(const Matrix3& J) {
  const Vector9 j = vec_3d(J);
  const double s = J.squaredNorm();
  const Matrix3 JtJ = J.transpose() * J, JJt = J * J.transpose();
  Matrix9 H = 4 * j * j.transpose() + 2 * s * Matrix9::Identity();
  for (int a = 0; a < 3; ++a)      // row index of dJ entry (a, b)
    for (int b = 0; b < 3; ++b) {  // column
      // Directional derivative of J J^T J along the unit dJ = E_ab.
      Matrix3 E = Matrix3::Zero();
      E(a, b) = 1;
      const Matrix3 d = E * JtJ + J * E.transpose() * J + JJt * E;
      H.col(a + 3 * b) -= 2 * vec_3d(d);
    }
  return H;
}

}  // namespace

Eigen::Matrix3d cofactor_3d(const Eigen::Matrix3d& J) {
  Eigen::Matrix3d C;
  C.col(0) = J.col(1).cross(J.col(2));
  C.col(1) = J.col(2).cross(J.col(0));
  C.col(2) = J.col(0).cross(J.col(1));
  return C;
}

// Entry (i + 3j, k + 3l) = sum_mn eps_ikm eps_jln J_mn: zero unless i != k
// and j != l, and then the one term m = 3 - i - k, n = 3 - j - l.
Eigen::Matrix<double, 9, 9> determinant_hessian_3d(const Eigen::Matrix3d& J) {
  const auto eps = [](int a, int b, int c) { return double((a - b) * (b - c) * (c - a)) / 2; };
  Eigen::Matrix<double, 9, 9> H = Eigen::Matrix<double, 9, 9>::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          if (i == k || j == l) continue;
          const int m = 3 - i - k, n = 3 - j - l;
          H(i + 3 * j, k + 3 * l) = eps(i, k, m) * eps(j, l, n) * J(m, n);
        }
  return H;
}

double InvariantDensity3D::value(const Matrix& J) const {
  const double g = J.determinant();
  return g > 0 ? derivatives(J.squaredNorm(), cofactor_norm2(J), g).f : kInvertedEnergy;
}

double InvariantDensity3D::value_and_gradient(const Matrix& J, Matrix* dD_dJ) const {
  const double g = J.determinant();
  if (!(g > 0)) return kInvertedEnergy;
  const double s = J.squaredNorm();
  const InvariantDerivatives3D d = derivatives(s, cofactor_norm2(J), g);
  *dD_dJ = d.f_s * 2 * J + d.f_c * (2 * s * J - 2 * J * J.transpose() * J) + d.f_g * cofactor_3d(J);
  return d.f;
}

InvariantDensity3D::Hessian InvariantDensity3D::hessian(const Matrix& J) const {
  const double s = J.squaredNorm();
  const InvariantDerivatives3D d = derivatives(s, cofactor_norm2(J), J.determinant());
  Eigen::Matrix<double, 9, 3> G;
  G.col(0) = 2 * vec_3d(J);
  G.col(1) = vec_3d(2 * s * J - 2 * J * J.transpose() * J);
  G.col(2) = vec_3d(cofactor_3d(J));
  Eigen::Matrix3d second;
  second << d.f_ss, d.f_sc, d.f_sg, d.f_sc, d.f_cc, d.f_cg, d.f_sg, d.f_cg, d.f_gg;
  return G * second * G.transpose() + 2 * d.f_s * Matrix9::Identity() + d.f_c * cofactor_norm_hessian(J) +
         d.f_g * determinant_hessian_3d(J);
}

SingularEigensystem3D InvariantDensity3D::eigensystem(const Matrix& J) const {
  SingularEigensystem3D system(J);
  const Eigen::Vector3d& sigma = system.sigma;
  const Eigen::Vector3d squared = sigma.cwiseAbs2();
  const InvariantDerivatives3D d = derivatives(J.squaredNorm(), cofactor_norm2(J), J.determinant());
  Eigen::Matrix3d B, second_c, second_g;  // B's rows: ds, dc, dg along dsigma
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    system.twist[k] = 2 * d.f_s + 2 * d.f_c * (sigma[i] * sigma[j] + squared[k]) + d.f_g * sigma[k];
    system.flip[k] = 2 * d.f_s + 2 * d.f_c * (squared[k] - sigma[i] * sigma[j]) - d.f_g * sigma[k];
    B(0, k) = 2 * sigma[k];
    B(1, k) = 2 * sigma[k] * (squared[i] + squared[j]);
    B(2, k) = sigma[i] * sigma[j];
    second_c(k, k) = 2 * (squared[i] + squared[j]);
    second_c(i, j) = second_c(j, i) = 4 * sigma[i] * sigma[j];
    second_g(k, k) = 0;
    second_g(i, j) = second_g(j, i) = sigma[k];
  }
  Eigen::Matrix3d second;
  second << d.f_ss, d.f_sc, d.f_sg, d.f_sc, d.f_cc, d.f_cg, d.f_sg, d.f_cg, d.f_gg;
  system.scaling =
      B.transpose() * second * B + 2 * d.f_s * Eigen::Matrix3d::Identity() + d.f_c * second_c + d.f_g * second_g;
  return system;
}

Eigen::Vector3d InvariantDensity3D::singular_value_gradient(const Eigen::Vector3d& sigma) const {
  const Eigen::Vector3d squared = sigma.cwiseAbs2();
  const double s = squared.sum();
  const double c = squared[0] * squared[1] + squared[1] * squared[2] + squared[2] * squared[0];
  const double g = sigma.prod();
  const InvariantDerivatives3D d = derivatives(s, c, g);
  Eigen::Vector3d gradient;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    gradient[i] = 2 * sigma[i] * (d.f_s + d.f_c * (squared[j] + squared[k])) + d.f_g * sigma[j] * sigma[k];
  }
  return gradient;
}

}  // namespace akvf
