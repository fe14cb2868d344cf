#include "framework/line_search.h"

#include <chrono>
#include <cmath>

namespace akvf {

LineSearchSummary LineSearch::search(const Objective& objective, const Eigen::VectorXd& x, double energy,
                                     const Eigen::VectorXd& gradient, const Eigen::VectorXd& direction) const {
  const auto start = std::chrono::steady_clock::now();
  LineSearchSummary summary;
  summary.energy = energy;
  const double slope = gradient.dot(direction);
  if (!direction.allFinite()) {
    summary.message = "search direction has non-finite entries";
  } else if (!(slope < 0)) {
    summary.message = "search direction is not a descent direction (grad . d = " + std::to_string(slope) + ")";
  } else {
    const double max_step = objective.max_feasible_step(x, direction);
    summary = do_search({objective, x, energy, gradient, direction, slope, max_step});
    summary.max_feasible_step = max_step;
    if (!summary.success) {
      summary.step = 0;
      summary.energy = energy;
    }
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace akvf
