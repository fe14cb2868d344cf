#include "energies/exp_symmetric_dirichlet.h"

#include <cmath>

#include "energies/exponent.h"
#include "energies/symmetric_dirichlet.h"

namespace akvf {

ExpSymmetricDirichlet2D::ExpSymmetricDirichlet2D(double exponent) : exponent_(checked_exponent(exponent)) {}

double ExpSymmetricDirichlet2D::lower_bound() const { return std::exp(4 * exponent_); }

InvariantDerivatives2D ExpSymmetricDirichlet2D::derivatives(double s, double g) const {
  return exponentiate(SymmetricDirichlet2D::formula(s, g), exponent_);
}

ExpSymmetricDirichlet3D::ExpSymmetricDirichlet3D(double exponent) : exponent_(checked_exponent(exponent)) {}

double ExpSymmetricDirichlet3D::lower_bound() const { return std::exp(6 * exponent_); }

InvariantDerivatives3D ExpSymmetricDirichlet3D::derivatives(double s, double c, double g) const {
  return exponentiate(SymmetricDirichlet3D::formula(s, c, g), exponent_);
}

}  // namespace akvf
