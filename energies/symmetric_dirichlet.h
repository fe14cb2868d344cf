#pragma once
// Symmetric Dirichlet density, Eq. (2) [Schreiner et al. 2004; Smith and
// Schaefer 2015]:  D(J) = |J|_F^2 + |J^-1|_F^2, minimum 4 at rotations (2D).
#include "framework/distortion_density.h"

namespace akvf {

class SymmetricDirichlet2 final : public DistortionDensity2 {
 public:
  std::string name() const override { return "symmetric-dirichlet"; }
  double lower_bound() const override { return 4.0; }
  double value(const Matrix& J) const override;
  double value_and_gradient(const Matrix& J, Matrix* dD_dJ) const override;
  Hessian hessian(const Matrix& J) const override;
};

}  // namespace akvf
