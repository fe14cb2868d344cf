#include "framework/optimization/flip_free_step.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace akvf {

int positive_roots(double a, double b, double c, double roots[2]) {
  double candidates[2];
  int m = 0;
  if (a == 0) {
    if (b != 0) candidates[m++] = -c / b;  // linear; constant: no root, or every t
  } else {
    const double discriminant = b * b - 4 * a * c;
    if (discriminant < 0) return 0;
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    candidates[m++] = q / a;
    if (q != 0) candidates[m++] = c / q;  // q = 0 only for b = 0 and a c = 0: the double root 0
  }
  int n = 0;
  for (int k = 0; k < m; ++k)
    if (candidates[k] > 0) roots[n++] = candidates[k];
  if (n == 2 && roots[1] < roots[0]) std::swap(roots[0], roots[1]);
  return n;
}

double smallest_positive_root(double a, double b, double c) {
  double roots[2];
  return positive_roots(a, b, c, roots) > 0 ? roots[0] : std::numeric_limits<double>::infinity();
}

double triangle_flip_step(const double Ds[4], const double Dd[4]) {
  // det(M) = m00 m11 - m01 m10 with column-major {m00, m10, m01, m11}.
  const double a = Dd[0] * Dd[3] - Dd[2] * Dd[1];
  const double b = Ds[0] * Dd[3] + Dd[0] * Ds[3] - Ds[2] * Dd[1] - Dd[2] * Ds[1];
  const double c = Ds[0] * Ds[3] - Ds[2] * Ds[1];
  return smallest_positive_root(a, b, c);
}

double smallest_positive_root_cubic(double a3, double a2, double a1, double a0) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  if (a3 == 0) return smallest_positive_root(a2, a1, a0);
  const auto p = [&](double t) { return ((a3 * t + a2) * t + a1) * t + a0; };
  // Breakpoints: 0, the positive critical points (roots of 3 a3 t^2 + 2 a2 t + a1), and a
  // Cauchy bound beyond which no root lies.
  double points[4];
  int count = 0;
  points[count++] = 0;
  const double disc = a2 * a2 - 3 * a3 * a1;
  if (disc >= 0) {
    const double q = -(a2 + std::copysign(std::sqrt(disc), a2));  // roots q / (3 a3) and a1 / q
    double c1 = q / (3 * a3), c2 = q != 0 ? a1 / q : c1;
    if (c1 > c2) std::swap(c1, c2);
    for (double c : {c1, c2})
      if (c > 0 && std::isfinite(c)) points[count++] = c;
  }
  points[count++] = 1 + std::max({std::abs(a2), std::abs(a1), std::abs(a0)}) / std::abs(a3);
  for (int i = 0; i + 1 < count; ++i) {
    double lo = points[i], hi = points[i + 1];
    if (!(hi > lo)) continue;
    if (p(hi) > 0) continue;  // p(lo) > 0 on the first piece with a root; monotone in between
    // Bisect to the last representable step below the root.
    while (true) {
      const double mid = 0.5 * (lo + hi);
      if (!(mid > lo && mid < hi)) break;
      (p(mid) > 0 ? lo : hi) = mid;
    }
    return hi;
  }
  return kNone;
}

double tet_flip_step(const Eigen::Matrix3d& Ds, const Eigen::Matrix3d& Dd) {
  const auto adjugate = [](const Eigen::Matrix3d& M) {
    Eigen::Matrix3d A;
    A << M(1, 1) * M(2, 2) - M(1, 2) * M(2, 1), M(0, 2) * M(2, 1) - M(0, 1) * M(2, 2),
        M(0, 1) * M(1, 2) - M(0, 2) * M(1, 1), M(1, 2) * M(2, 0) - M(1, 0) * M(2, 2),
        M(0, 0) * M(2, 2) - M(0, 2) * M(2, 0), M(0, 2) * M(1, 0) - M(0, 0) * M(1, 2),
        M(1, 0) * M(2, 1) - M(1, 1) * M(2, 0), M(0, 1) * M(2, 0) - M(0, 0) * M(2, 1),
        M(0, 0) * M(1, 1) - M(0, 1) * M(1, 0);
    return A;
  };
  return smallest_positive_root_cubic(Dd.determinant(), (adjugate(Dd) * Ds).trace(), (adjugate(Ds) * Dd).trace(),
                                      Ds.determinant());
}

}  // namespace akvf
