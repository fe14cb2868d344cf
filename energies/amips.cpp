#include "energies/amips.h"

#include <cmath>

#include "energies/exponent.h"

namespace akvf {

namespace {

// u = s / (4g) + (g + 1/g) / 4: the 2D exponent's argument.
InvariantDerivatives2D amips_argument(double s, double g) {
  const double g2 = g * g;
  return {s / (4 * g) + (g + 1 / g) / 4, 1 / (4 * g), -s / (4 * g2) + (1 - 1 / g2) / 4, 0, -1 / (4 * g2),
          (s + 1) / (2 * g2 * g)};
}

// u = s / (6 g^(2/3)) + (g + 1/g) / 4: the 3D exponent's argument.
InvariantDerivatives3D amips_argument(double s, double, double g) {
  const double g23 = std::cbrt(g * g), g2 = g * g;
  InvariantDerivatives3D u;
  u.f = s / (6 * g23) + (g + 1 / g) / 4;
  u.f_s = 1 / (6 * g23);
  u.f_g = -s / (9 * g23 * g) + (1 - 1 / g2) / 4;
  u.f_sg = -1 / (9 * g23 * g);
  u.f_gg = 5 * s / (27 * g23 * g2) + 1 / (2 * g2 * g);
  return u;
}

}  // namespace

Amips2D::Amips2D(double exponent) : exponent_(checked_exponent(exponent)) {}

double Amips2D::lower_bound() const { return std::exp(exponent_); }

InvariantDerivatives2D Amips2D::derivatives(double s, double g) const {
  return exponentiate(amips_argument(s, g), exponent_);
}

Amips3D::Amips3D(double exponent) : exponent_(checked_exponent(exponent)) {}

double Amips3D::lower_bound() const { return std::exp(exponent_); }

InvariantDerivatives3D Amips3D::derivatives(double s, double c, double g) const {
  return exponentiate(amips_argument(s, c, g), exponent_);
}

}  // namespace akvf
