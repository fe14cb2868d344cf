#include "energies/symmetric_dirichlet.h"

#include <limits>

namespace akvf {

// In 2D, |J^-1|_F^2 = |J|_F^2 / det(J)^2, so with s = |J|_F^2 and g = det J,
//   D = s (1 + g^-2).
// Derivatives use vec(J) = (J00, J10, J01, J11) and the cofactor
// c = d det / d vec(J) = (J11, -J01, -J10, J00).

double SymmetricDirichlet2::value(const Matrix& J) const {
  const double g = J.determinant();
  if (!(g > 0)) return std::numeric_limits<double>::infinity();
  return J.squaredNorm() * (1 + 1 / (g * g));
}

double SymmetricDirichlet2::value_and_gradient(const Matrix& J, Matrix* dD_dJ) const {
  const double g = J.determinant();
  if (!(g > 0)) return std::numeric_limits<double>::infinity();
  const double s = J.squaredNorm();
  const double f = 1 + 1 / (g * g);
  const double df = -2 / (g * g * g);
  Matrix cofactor;
  cofactor << J(1, 1), -J(1, 0), -J(0, 1), J(0, 0);
  *dD_dJ = 2 * f * J + s * df * cofactor;
  return s * f;
}

SymmetricDirichlet2::Hessian SymmetricDirichlet2::hessian(const Matrix& J) const {
  const double g = J.determinant();
  const double s = J.squaredNorm();
  const double f = 1 + 1 / (g * g);
  const double df = -2 / (g * g * g);
  const double ddf = 6 / (g * g * g * g);
  const Eigen::Vector4d j(J(0, 0), J(1, 0), J(0, 1), J(1, 1));
  const Eigen::Vector4d c(J(1, 1), -J(0, 1), -J(1, 0), J(0, 0));
  Hessian det_hessian = Hessian::Zero();  // d^2 det / dvec(J)^2
  det_hessian(0, 3) = det_hessian(3, 0) = 1;
  det_hessian(1, 2) = det_hessian(2, 1) = -1;
  return 2 * f * Hessian::Identity() + 2 * df * (j * c.transpose() + c * j.transpose()) +
         s * ddf * c * c.transpose() + s * df * det_hessian;
}

}  // namespace akvf
