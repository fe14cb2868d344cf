#include "akvf/backtracking_line_search.h"

#include <algorithm>
#include <cmath>

#include "akvf/error.h"

namespace akvf {

BacktrackingLineSearch::BacktrackingLineSearch(LineSearchSettings settings) : settings_(settings) {
  std::string invalid;
  if (!settings_.is_valid(&invalid)) throw OptionsError(invalid);
}

LineSearchSummary BacktrackingLineSearch::do_search(const LineSearchInput& in) const {
  LineSearchSummary summary;
  double alpha = std::min(settings_.max_initial_step, settings_.max_step_fraction * in.max_feasible_step);
  summary.initial_step = alpha;
  Eigen::VectorXd trial(in.x.size());
  const double smallest = settings_.min_step_ratio * alpha;
  while (summary.evaluations < settings_.max_evaluations && alpha >= smallest) {
    trial = in.x + alpha * in.direction;
    const double energy = in.objective.value(trial);
    ++summary.evaluations;
    // +infinity (an inverted element) never satisfies the condition.
    if (energy <= in.energy + settings_.c1 * alpha * in.directional_derivative) {
      summary.success = true;
      summary.step = alpha;
      summary.energy = energy;
      return summary;
    }
    alpha *= settings_.rho;
  }
  summary.message = "no step satisfied the sufficient-decrease condition after " + std::to_string(summary.evaluations) +
                    " evaluations (initial alpha " + std::to_string(summary.initial_step) + ", alpha_max " +
                    std::to_string(in.max_feasible_step) + ")";
  return summary;
}

}  // namespace akvf
