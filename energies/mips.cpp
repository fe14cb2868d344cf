#include "energies/mips.h"

#include <cmath>

namespace akvf {

InvariantDerivatives2D Mips2D::derivatives(double s, double g) const {
  const double g2 = g * g;
  return {s / g, 1 / g, -s / g2, 0, -1 / g2, 2 * s / (g2 * g)};
}

InvariantDerivatives3D Mips3D::derivatives(double s, double, double g) const {
  const double g23 = std::cbrt(g * g);
  InvariantDerivatives3D d;
  d.f = s / g23;
  d.f_s = 1 / g23;
  d.f_g = -2 * s / (3 * g23 * g);
  d.f_sg = -2 / (3 * g23 * g);
  d.f_gg = 10 * s / (9 * g23 * g * g);
  return d;
}

}  // namespace akvf
