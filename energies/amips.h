#pragma once
// AMIPS [Fu, Liu and Guo 2015] with equal weights on the conformal and the
// area (volume) terms: exp(k (s / (4g) + (g + 1/g) / 4)) in 2D and
// exp(k (s / (6 g^(2/3)) + (g + 1/g) / 4)) in 3D, exponent k > 0. Each term
// is at least 1/2 (equality at similarities and at g = 1), so the minimum is
// exp(k), at rotations.
#include "energies/invariant_density_2d.h"
#include "energies/invariant_density_3d.h"

namespace akvf {

class Amips2D final : public InvariantDensity2D {
 public:
  explicit Amips2D(double exponent);
  std::string name() const override { return "amips"; }
  double lower_bound() const override;

 protected:
  InvariantDerivatives2D derivatives(double s, double g) const override;

 private:
  double exponent_;
};

class Amips3D final : public InvariantDensity3D {
 public:
  explicit Amips3D(double exponent);
  std::string name() const override { return "amips"; }
  double lower_bound() const override;

 protected:
  InvariantDerivatives3D derivatives(double s, double c, double g) const override;

 private:
  double exponent_;
};

}  // namespace akvf
