#pragma once
// Rotation-invariant 3D densities as functions of the invariants of J (3x3)
//   s = |J|_F^2,  c = |cof J|_F^2 = (s^2 - |J^T J|_F^2) / 2,  g = det J,
// D(J) = f(s, c, g), with one chain rule for gradient and Hessian:
//   dD/dvec(J) = G f',   d2D/dvec(J)^2 = G f'' G^T + f_s H_s + f_c H_c + f_g H_g,
// G = [ds dc dg] (9 by 3); ds = 2 vec J, dc = vec(2 s J - 2 J J^T J),
// dg = vec(cof J); H_s = 2 I, H_c and H_g (linear in J) as derived in the
// .cpp. +infinity when g <= 0. The energies built on it: symmetric_dirichlet.h,
// exp_symmetric_dirichlet.h, mips.h, amips.h.
#include "akvf/distortion_density.h"
#include "energies/singular_eigensystem_3d.h"

namespace akvf {

// cof J = d det J / dJ, and d2 det J / dvec(J)2 (column-major vec, linear in J).
Eigen::Matrix3d cofactor_3d(const Eigen::Matrix3d& J);
Eigen::Matrix<double, 9, 9> determinant_hessian_3d(const Eigen::Matrix3d& J);

struct InvariantDerivatives3D {
  double f = 0;
  double f_s = 0, f_c = 0, f_g = 0;
  double f_ss = 0, f_sc = 0, f_sg = 0, f_cc = 0, f_cg = 0, f_gg = 0;
};

class InvariantDensity3D : public DistortionDensity<3>,
                           public SingularValueDerivative<3>,
                           public HessianEigensystem<3> {
 public:
  double value(const Matrix& J) const final;
  double value_and_gradient(const Matrix& J, Matrix* dD_dJ) const final;
  Hessian hessian(const Matrix& J) const final;
  // The Hessian with negative eigenvalues clamped to 0 (absolute: mirrored),
  // from the closed-form eigensystem of singular_eigensystem_3d.h. With
  // Psi(sigma) = f(s, c, g) the pair (i, j), k the third index, has
  //   twist  2 f_s + 2 f_c (sigma_i sigma_j + sigma_k^2) + f_g sigma_k,
  //   flip   2 f_s + 2 f_c (sigma_k^2 - sigma_i sigma_j) - f_g sigma_k
  // ((Psi_i +- Psi_j) / (sigma_i +- sigma_j) with the division done by hand),
  // and d2 Psi / dsigma^2 = B^T f'' B + 2 f_s I + f_c d2c/dsigma^2 + f_g
  // d2g/dsigma^2, B = d(s, c, g)/dsigma.
  Hessian projected_hessian(const Matrix& J) const final { return filtered_hessian(J, false); }
  Hessian absolute_hessian(const Matrix& J) const final { return filtered_hessian(J, true); }
  Eigenpairs hessian_eigensystem(const Matrix& J) const final { return eigensystem(J).eigenpairs(); }
  // dD/dsigma_i = 2 sigma_i (f_s + f_c (sigma_j^2 + sigma_k^2)) + f_g sigma_j sigma_k.
  Eigen::Vector3d singular_value_gradient(const Eigen::Vector3d& sigma) const final;

 protected:
  virtual InvariantDerivatives3D derivatives(double s, double c, double g) const = 0;

 private:
  Hessian filtered_hessian(const Matrix& J, bool absolute) const { return eigensystem(J).filtered_hessian(absolute); }
  // The eigensystem above at J.
  SingularEigensystem3D eigensystem(const Matrix& J) const;
};

}  // namespace akvf
