#pragma once
// Symmetric Dirichlet density, Eq. (2) [Schreiner et al. 2004; Smith and
// Schaefer 2015]: D(J) = |J|_F^2 + |J^-1|_F^2, minimum 4 (2D) or 6 (3D) at
// rotations. In the invariants: s (1 + 1 / g^2) in 2D, s + c / g^2 in 3D.
#include "energies/invariant_density_2d.h"
#include "energies/invariant_density_3d.h"

namespace akvf {

class SymmetricDirichlet2D final : public InvariantDensity2D {
 public:
  std::string name() const override { return "symmetric-dirichlet"; }
  double lower_bound() const override { return 4.0; }
  // f = s (1 + 1/g^2) and its partials (shared with the exponential variant).
  static InvariantDerivatives2D formula(double s, double g);

 protected:
  InvariantDerivatives2D derivatives(double s, double g) const override { return formula(s, g); }
};

class SymmetricDirichlet3D final : public InvariantDensity3D {
 public:
  std::string name() const override { return "symmetric-dirichlet"; }
  double lower_bound() const override { return 6.0; }
  // f = s + c / g^2 and its partials (shared with the exponential variant).
  static InvariantDerivatives3D formula(double s, double c, double g);

 protected:
  InvariantDerivatives3D derivatives(double s, double c, double g) const override { return formula(s, c, g); }
};

}  // namespace akvf
