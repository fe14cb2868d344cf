#include "solvers/backtracking_line_search.h"

#include <algorithm>
#include <cmath>

#include "framework/error.h"

namespace akvf {

BacktrackingLineSearch::BacktrackingLineSearch(BacktrackingOptions options) : options_(options) {
  if (!(options_.c1 > 0 && options_.c1 < 1)) throw OptionsError("line search c1 must be in (0, 1)");
  if (!(options_.rho > 0 && options_.rho < 1)) throw OptionsError("line search rho must be in (0, 1)");
  if (!(options_.max_step_fraction > 0 && options_.max_step_fraction < 1))
    throw OptionsError("line search max step fraction must be in (0, 1)");
  if (!(options_.max_initial_step > 0)) throw OptionsError("line search initial step must be > 0");
  if (options_.max_evaluations < 1) throw OptionsError("line search needs at least one evaluation");
}

LineSearchSummary BacktrackingLineSearch::do_search(const LineSearchInput& in) const {
  LineSearchSummary summary;
  double alpha = std::min(options_.max_initial_step, options_.max_step_fraction * in.max_feasible_step);
  summary.initial_step = alpha;
  Eigen::VectorXd trial(in.x.size());
  for (int k = 0; k < options_.max_evaluations; ++k) {
    trial = in.x + alpha * in.direction;
    const double energy = in.objective.value(trial);
    ++summary.evaluations;
    // +infinity (an inverted element) never satisfies the condition.
    if (energy <= in.energy + options_.c1 * alpha * in.directional_derivative) {
      summary.success = true;
      summary.step = alpha;
      summary.energy = energy;
      return summary;
    }
    alpha *= options_.rho;
  }
  summary.message = "no step satisfied the sufficient-decrease condition in " +
                    std::to_string(options_.max_evaluations) + " evaluations (last alpha " + std::to_string(alpha) +
                    ", alpha_max " + std::to_string(in.max_feasible_step) + ")";
  return summary;
}

}  // namespace akvf
