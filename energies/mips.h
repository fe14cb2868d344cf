#pragma once
// Conformal / MIPS [Hormann and Greiner 2000]: |J|_F^2 / det(J)^(2/D),
// s / g in 2D (minimum 2) and s / g^(2/3) in 3D (minimum 3), attained at
// similarities.
#include "energies/invariant_density_2d.h"
#include "energies/invariant_density_3d.h"

namespace akvf {

class Mips2D final : public InvariantDensity2D {
 public:
  std::string name() const override { return "mips"; }
  bool minimal_at_similarities() const override { return true; }
  double lower_bound() const override { return 2.0; }

 protected:
  InvariantDerivatives2D derivatives(double s, double g) const override;
};

class Mips3D final : public InvariantDensity3D {
 public:
  std::string name() const override { return "mips"; }
  bool minimal_at_similarities() const override { return true; }
  double lower_bound() const override { return 3.0; }

 protected:
  InvariantDerivatives3D derivatives(double s, double c, double g) const override;
};

}  // namespace akvf
