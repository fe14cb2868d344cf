#include "akvf/line_search.h"

#include <chrono>
#include <cmath>

namespace akvf {

bool LineSearchSettings::is_valid(std::string* error) const {
  auto fail = [&](const char* message) {
    if (error) *error = message;
    return false;
  };
  if (!(c1 > 0 && c1 < 1)) return fail("line search c1 must be in (0, 1)");
  if (!(rho > 0 && rho < 1)) return fail("line search rho must be in (0, 1)");
  if (!(max_step_fraction > 0 && max_step_fraction < 1)) return fail("line search max step fraction must be in (0, 1)");
  if (!(max_initial_step > 0)) return fail("line search initial step must be > 0");
  if (!(min_step_ratio > 0 && min_step_ratio < 1)) return fail("line search min step ratio must be in (0, 1)");
  if (max_evaluations < 1) return fail("line search needs at least one evaluation");
  return true;
}

void point_along_path(const Eigen::VectorXd& x, const Eigen::VectorXd& direction, const Eigen::VectorXd& turn,
                      double alpha, Eigen::VectorXd* point) {
  *point = x + alpha * direction;
  if (turn.size() > 0) *point += (0.5 * alpha * alpha) * turn;
}

Eigen::VectorXd accepted_point(const Eigen::VectorXd& x, const Eigen::VectorXd& direction,
                               const LineSearchSummary& summary) {
  Eigen::VectorXd point;
  point_along_path(x, direction, summary.turn, summary.step, &point);
  return point;
}

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
    if (!(max_step > 0)) {
      summary.message = "no step along the direction is flip-free (alpha_max = " + std::to_string(max_step) + ")";
    } else {
      summary = do_search({objective, x, energy, gradient, direction, slope, max_step});
    }
    summary.max_feasible_step = max_step;
    if (!summary.success) {
      summary.step = 0;
      summary.energy = energy;
      summary.gradient.resize(0);
    }
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace akvf
