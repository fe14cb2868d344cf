#include "energies/symmetric_dirichlet.h"

namespace akvf {

InvariantDerivatives2D SymmetricDirichlet2D::formula(double s, double g) {
  const double g2 = g * g;
  return {s * (1 + 1 / g2), 1 + 1 / g2, -2 * s / (g2 * g), 0, -2 / (g2 * g), 6 * s / (g2 * g2)};
}

InvariantDerivatives3D SymmetricDirichlet3D::formula(double s, double c, double g) {
  const double g2 = g * g, g3 = g2 * g;
  InvariantDerivatives3D d;
  d.f = s + c / g2;
  d.f_s = 1;
  d.f_c = 1 / g2;
  d.f_g = -2 * c / g3;
  d.f_cg = -2 / g3;
  d.f_gg = 6 * c / (g2 * g2);
  return d;
}

}  // namespace akvf
