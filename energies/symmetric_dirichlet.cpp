#include "energies/symmetric_dirichlet.h"

namespace akvf {

InvariantDerivatives SymmetricDirichlet2::derivatives(double s, double g) const { return formula(s, g); }

InvariantDerivatives SymmetricDirichlet2::formula(double s, double g) {
  const double g2 = g * g;
  return {s * (1 + 1 / g2), 1 + 1 / g2, -2 * s / (g2 * g), 0, -2 / (g2 * g), 6 * s / (g2 * g2)};
}

}  // namespace akvf
