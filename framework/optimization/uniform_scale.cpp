#include "framework/optimization/uniform_scale.h"

#include <cmath>

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
  for (double step = 0.125;; step *= 2) {
    const double t = inner + direction * step;
    if (std::abs(t) > 20) return 1;
    const double d = slope(t, &finite);
    if (!finite || direction * d >= 0) {  // past the minimum (or where E overflows): bracketed
      outer = t;
      break;
    }
    inner = t;
  }
  while (std::abs(outer - inner) > 1e-12) {
    const double middle = 0.5 * (inner + outer);
    const double d = slope(middle, &finite);
    if (finite && direction * d < 0) {
      inner = middle;
    } else {
      outer = middle;
    }
  }
  return std::exp(0.5 * (inner + outer));
}

}  // namespace akvf
