#include "framework/optimization/uniform_scale.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace akvf {

double best_uniform_scale(const Objective& objective, const Eigen::VectorXd& x) {
  // dE/dt at t, and whether E and its gradient are finite there.
  auto slope = [&](double t, bool* finite) {
    const Eigen::VectorXd y = std::exp(t) * x;
    Eigen::VectorXd gradient;
    const double value = objective.value_and_gradient(y, &gradient);
    const double d = gradient.dot(y);
    *finite = std::isfinite(value) && std::isfinite(d);
    return d;
  };
  Eigen::VectorXd gradient;
  const double value = objective.value_and_gradient(x, &gradient);
  const double d0 = gradient.dot(x);
  if (!std::isfinite(value) || !std::isfinite(d0)) return 1;
  // A slope at rounding level: the energy does not see the scale (or x is
  // already at its best one).
  if (std::abs(d0) <= 1e-12 * gradient.norm() * x.norm()) return 1;
  bool finite = false;
  // Downhill: t grows where the slope is negative.
  const double direction = d0 < 0 ? 1 : -1;
  double inner = 0, outer = 0;
  // The bracket's slopes, signed so that inner's is negative; outer's is
  // NaN where E is not finite.
  double inner_slope = direction * d0, outer_slope = 0;
  for (double step = 0.125;; step *= 2) {
    const double t = inner + direction * step;
    if (std::abs(t) > 20) return 1;
    const double d = direction * slope(t, &finite);
    if (!finite || d >= 0) {  // past the minimum (or where E overflows): bracketed
      outer = t;
      outer_slope = finite ? d : std::numeric_limits<double>::quiet_NaN();
      break;
    }
    inner = t;
    inner_slope = d;
  }
  // Regula falsi with the Illinois rule (the end kept twice in a row has
  // its slope halved), bisecting while outer's slope is unknown:
  // superlinear, where bisection took about 40 gradients.
  int kept = 0;  // -1: inner was kept last, +1: outer
  for (int i = 0; i < 200 && std::abs(outer - inner) > 1e-12; ++i) {
    double t = 0.5 * (inner + outer);
    if (std::isfinite(outer_slope)) {
      const double secant = inner + (outer - inner) * inner_slope / (inner_slope - outer_slope);
      if (secant > std::min(inner, outer) && secant < std::max(inner, outer)) t = secant;
    }
    const double d = direction * slope(t, &finite);
    if (finite && d < 0) {
      inner = t;
      inner_slope = d;
      if (kept == 1) outer_slope *= 0.5;
      kept = 1;
    } else {
      outer = t;
      outer_slope = finite ? d : std::numeric_limits<double>::quiet_NaN();
      if (finite && d == 0) return std::exp(t);
      if (kept == -1) inner_slope *= 0.5;
      kept = -1;
    }
  }
  return std::exp(0.5 * (inner + outer));
}

}  // namespace akvf
