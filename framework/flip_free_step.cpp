#include "framework/flip_free_step.h"

#include <cmath>
#include <limits>

namespace akvf {

double smallest_positive_root(double a, double b, double c) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  if (a == 0) return b < 0 ? -c / b : kNone;  // linear, or constant c > 0
  const double discriminant = b * b - 4 * a * c;
  if (discriminant < 0) return kNone;
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  // q != 0: q = 0 would need b = 0 and a c = 0, excluded by a != 0, c > 0.
  const double r1 = q / a, r2 = c / q;
  double best = kNone;
  if (r1 > 0) best = r1;
  if (r2 > 0 && r2 < best) best = r2;
  return best;
}

double triangle_flip_step(const double Ds[4], const double Dd[4]) {
  // det(M) = m00 m11 - m01 m10 with column-major {m00, m10, m01, m11}.
  const double a = Dd[0] * Dd[3] - Dd[2] * Dd[1];
  const double b = Ds[0] * Dd[3] + Dd[0] * Ds[3] - Ds[2] * Dd[1] - Dd[2] * Ds[1];
  const double c = Ds[0] * Ds[3] - Ds[2] * Ds[1];
  return smallest_positive_root(a, b, c);
}

}  // namespace akvf
