#pragma once
// Symmetric Dirichlet density, Eq. (2) [Schreiner et al. 2004; Smith and
// Schaefer 2015]:  D(J) = |J|_F^2 + |J^-1|_F^2 = s (1 + 1 / g^2) in 2D.
// Minimum 4 at rotations.
#include "energies/invariant_density.h"

namespace akvf {

class SymmetricDirichlet2 final : public InvariantDensity2 {
 public:
  std::string name() const override { return "symmetric-dirichlet"; }
  double lower_bound() const override { return 4.0; }
  // f = s (1 + 1/g^2) and its partials (shared with the exponential variant).
  static InvariantDerivatives formula(double s, double g);

 protected:
  InvariantDerivatives derivatives(double s, double g) const override;
};

}  // namespace akvf
