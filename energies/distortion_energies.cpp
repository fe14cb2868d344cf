#include "energies/distortion_energies.h"

#include <cmath>

#include "energies/exponent.h"
#include "energies/symmetric_dirichlet.h"
#include "framework/process/error.h"

namespace akvf {

namespace {

// Derivatives of exp(k u) from those of u.
InvariantDerivatives exponentiate(const InvariantDerivatives& u, double k) {
  InvariantDerivatives d;
  d.f = std::exp(k * u.f);
  d.f_s = k * d.f * u.f_s;
  d.f_g = k * d.f * u.f_g;
  d.f_ss = k * d.f * (u.f_ss + k * u.f_s * u.f_s);
  d.f_sg = k * d.f * (u.f_sg + k * u.f_s * u.f_g);
  d.f_gg = k * d.f * (u.f_gg + k * u.f_g * u.f_g);
  return d;
}

// u = s / (4g) + (g + 1/g) / 4: the AMIPS exponent's argument.
InvariantDerivatives amips_argument(double s, double g) {
  const double g2 = g * g;
  return {s / (4 * g) + (g + 1 / g) / 4, 1 / (4 * g), -s / (4 * g2) + (1 - 1 / g2) / 4, 0, -1 / (4 * g2),
          (s + 1) / (2 * g2 * g)};
}

}  // namespace

InvariantDerivatives Arap2::derivatives(double s, double g) const {
  const double root = std::sqrt(s + 2 * g);
  const double inv3 = 1 / (root * root * root);
  return {s - 2 * root + 2, 1 - 1 / root, -2 / root, 0.5 * inv3, inv3, 2 * inv3};
}

InvariantDerivatives Mips2::derivatives(double s, double g) const {
  const double g2 = g * g;
  return {s / g, 1 / g, -s / g2, 0, -1 / g2, 2 * s / (g2 * g)};
}

ExpSymmetricDirichlet2::ExpSymmetricDirichlet2(double exponent) : exponent_(checked_exponent(exponent)) {}

double ExpSymmetricDirichlet2::lower_bound() const { return std::exp(4 * exponent_); }

InvariantDerivatives ExpSymmetricDirichlet2::derivatives(double s, double g) const {
  return exponentiate(SymmetricDirichlet2::formula(s, g), exponent_);
}

Amips2::Amips2(double exponent) : exponent_(checked_exponent(exponent)) {}

double Amips2::lower_bound() const { return std::exp(exponent_); }

InvariantDerivatives Amips2::derivatives(double s, double g) const {
  return exponentiate(amips_argument(s, g), exponent_);
}

}  // namespace akvf
