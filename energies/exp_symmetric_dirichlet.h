#pragma once
// Exponential symmetric Dirichlet (SLIM's convention, Rabinovich et al.
// 2017): exp(k (|J|^2 + |J^-1|^2)) with exponent k > 0; minimum exp(4k) (2D)
// or exp(6k) (3D) at rotations.
#include "energies/invariant_density_2d.h"
#include "energies/invariant_density_3d.h"

namespace akvf {

class ExpSymmetricDirichlet2D final : public InvariantDensity2D {
 public:
  explicit ExpSymmetricDirichlet2D(double exponent);
  std::string name() const override { return "exp-symmetric-dirichlet"; }
  double lower_bound() const override;

 protected:
  InvariantDerivatives2D derivatives(double s, double g) const override;

 private:
  double exponent_;
};

class ExpSymmetricDirichlet3D final : public InvariantDensity3D {
 public:
  explicit ExpSymmetricDirichlet3D(double exponent);
  std::string name() const override { return "exp-symmetric-dirichlet"; }
  double lower_bound() const override;

 protected:
  InvariantDerivatives3D derivatives(double s, double c, double g) const override;

 private:
  double exponent_;
};

}  // namespace akvf
