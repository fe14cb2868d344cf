#pragma once
// Rotation-invariant 2D densities written as functions of the two invariants
//   s = |J|_F^2 = sigma_1^2 + sigma_2^2   and   g = det J = sigma_1 sigma_2,
// D(J) = f(s, g). One chain rule serves them all:
//   dD/dvec(J)   = f_s 2 j + f_g c
//   d2D/dvec(J)2 = 2 f_s I + f_g H_det + [2j c] [[f_ss f_sg] [f_sg f_gg]] [2j c]^T
// with j = vec(J), c = d det / dvec(J) (the cofactor) and H_det the constant
// Hessian of det. +infinity when g <= 0 (inverted or degenerate elements).
#include "akvf/distortion_density.h"

namespace akvf {

// c = d det J / dvec(J) (column-major vec), and the constant d2 det J / dvec(J)2.
Eigen::Vector4d cofactor_2d(const Eigen::Matrix2d& J);
Eigen::Matrix4d determinant_hessian_2d();

// f and its first and second partial derivatives at (s, g).
struct InvariantDerivatives2D {
  double f = 0, f_s = 0, f_g = 0, f_ss = 0, f_sg = 0, f_gg = 0;
};

class InvariantDensity2D : public DistortionDensity2D, public SingularValueDerivative<2>, public HessianEigensystem<2> {
 public:
  double value(const Matrix& J) const final;
  double value_and_gradient(const Matrix& J, Matrix* dD_dJ) const final;
  Hessian hessian(const Matrix& J) const final;
  // The Hessian with its negative eigenvalues clamped to 0, in closed form
  // [Smith, de Goes and Kim 2019]: with J = U diag(sigma) V^T (signed, U and
  // V rotations) the eigenvectors are U M V^T for the twist M = [0 -1; 1 0]
  // / sqrt(2) (eigenvalue 2 f_s + f_g), the flip [0 1; 1 0] / sqrt(2)
  // (2 f_s - f_g), and two scalings diag(e) with e the eigenvectors of
  //   A = 2 f_s I + f_g [0 1; 1 0] + B^T [f_ss f_sg; f_sg f_gg] B,
  //   B = [2 sigma_1, 2 sigma_2; sigma_2, sigma_1]
  // (the rows are ds and dg along diag(e)). No iterative eigensolver.
  Hessian projected_hessian(const Matrix& J) const final { return filtered_hessian(J, false); }
  // The same eigensystem with |lambda| for every eigenvalue.
  Hessian absolute_hessian(const Matrix& J) const final { return filtered_hessian(J, true); }
  // The eigensystem above: the twist, the flip, the two scalings.
  Eigenpairs hessian_eigensystem(const Matrix& J) const final;

  // dD/dsigma_i = 2 f_s sigma_i + f_g sigma_j (j != i).
  Eigen::Vector2d singular_value_gradient(const Eigen::Vector2d& sigma) const final;

 protected:
  // f and its partials (g > 0). value() uses the same f, so the energy the
  // line search sees and the one reported with the gradient agree bitwise.
  virtual InvariantDerivatives2D derivatives(double s, double g) const = 0;

 private:
  // The closed-form eigensystem above, negative eigenvalues dropped
  // (clamped) or mirrored (absolute).
  Hessian filtered_hessian(const Matrix& J, bool absolute) const;
};

}  // namespace akvf
