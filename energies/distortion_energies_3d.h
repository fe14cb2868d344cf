#pragma once
// The 3D distortion densities beyond symmetric Dirichlet (tet issue): the
// exponential symmetric Dirichlet, MIPS and AMIPS as functions f(s, c, g) of
// the invariants (invariant_density_3d.h), and ARAP through the SVD.
// Formulas, lower bounds and sources are in docs/energies.md.
#include "energies/invariant_density_3d.h"

namespace akvf {

// Exponential symmetric Dirichlet (SLIM's convention): exp(k (|J|^2 + |J^-1|^2)),
// minimum exp(6k) at rotations.
class ExpSymmetricDirichlet3 final : public InvariantDensity3 {
 public:
  explicit ExpSymmetricDirichlet3(double exponent);
  std::string name() const override { return "exp-symmetric-dirichlet"; }
  double lower_bound() const override;

 protected:
  InvariantDerivatives3 derivatives(double s, double c, double g) const override;

 private:
  double exponent_;
};

// Conformal / MIPS in 3D: |J|_F^2 / det(J)^(2/3) = s / g^(2/3), minimum 3 at
// similarities.
class Mips3 final : public InvariantDensity3 {
 public:
  std::string name() const override { return "mips"; }
  double lower_bound() const override { return 3.0; }

 protected:
  InvariantDerivatives3 derivatives(double s, double c, double g) const override;
};

// AMIPS [Fu, Liu and Guo 2015] in 3D with equal weights on the conformal and
// volume terms, as in 2D: exp(k (s / (6 g^(2/3)) + (g + 1/g) / 4)). Each
// term is at least 1/2 (equality at similarities and at g = 1), so the
// minimum is exp(k), at rotations.
class Amips3 final : public InvariantDensity3 {
 public:
  explicit Amips3(double exponent);
  std::string name() const override { return "amips"; }
  double lower_bound() const override;

 protected:
  InvariantDerivatives3 derivatives(double s, double c, double g) const override;

 private:
  double exponent_;
};

// ARAP [Liu et al. 2008] in 3D: |J - R(J)|_F^2 = sum_i (sigma_i - 1)^2 with
// R = U V^T the closest rotation. Gradient 2 (J - R); Hessian 2 I - 2 dR/dJ,
// where dR/dJ has the eigenvalue 2 / (sigma_i + sigma_j) on each twist
// U (e_i e_j^T - e_j e_i^T) V^T / sqrt(2) and 0 elsewhere. +infinity when
// det J <= 0, as every density here (ARAP itself has no barrier).
class Arap3 final : public DistortionDensity<3>, public SingularValueDerivative<3> {
 public:
  std::string name() const override { return "arap"; }
  double lower_bound() const override { return 0.0; }
  double value(const Matrix& J) const override;
  double value_and_gradient(const Matrix& J, Matrix* dD_dJ) const override;
  Hessian hessian(const Matrix& J) const override;
  Eigen::Vector3d singular_value_gradient(const Eigen::Vector3d& sigma) const override;
};

}  // namespace akvf
