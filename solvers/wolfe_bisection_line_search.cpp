#include "solvers/wolfe_bisection_line_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "akvf/error.h"

namespace akvf {

WolfeBisectionLineSearch::WolfeBisectionLineSearch(LineSearchSettings settings, double c2)
    : settings_(settings), c2_(c2) {
  std::string invalid;
  if (!settings_.is_valid(&invalid)) throw OptionsError(invalid);
  if (!(c2_ > settings_.c1 && c2_ < 1)) throw OptionsError("Wolfe c2 must be in (c1, 1)");
}

LineSearchSummary WolfeBisectionLineSearch::do_search(const LineSearchInput& in) const {
  LineSearchSummary summary;
  const double hi_bound = settings_.max_step_fraction * in.max_feasible_step;  // may be +infinity
  double lo = 0, hi = hi_bound;
  double alpha = std::min(settings_.max_initial_step, hi_bound);
  summary.initial_step = alpha;
  summary.bound_cut_initial_step = alpha < settings_.max_initial_step;
  double best_alpha = 0, best_energy = in.energy;  // the last step that satisfied Armijo
  Eigen::VectorXd trial(in.x.size()), gradient;
  const double smallest = settings_.min_step_ratio * alpha;
  while (summary.evaluations < settings_.max_evaluations && alpha >= smallest) {
    trial = in.x + alpha * in.direction;
    const double energy = in.objective.value_and_gradient(trial, &gradient);
    ++summary.evaluations;
    if (!(energy <= in.energy + settings_.c1 * alpha * in.directional_derivative)) {
      hi = alpha;  // too long (or inverted: +infinity)
    } else {
      best_alpha = alpha;
      best_energy = energy;
      summary.gradient = gradient;
      if (gradient.dot(in.direction) >= c2_ * in.directional_derivative) break;  // both conditions hold
      lo = alpha;                                                                // too short
      if (alpha >= hi_bound) break;  // cannot go further without nearing a flip
    }
    alpha = std::isfinite(hi) ? 0.5 * (lo + hi) : 2 * alpha;
  }
  if (best_alpha > 0) {
    summary.success = true;
    summary.step = best_alpha;
    summary.energy = best_energy;
  } else {
    summary.gradient.resize(0);
    summary.message = "no step satisfied the sufficient-decrease condition after " +
                      std::to_string(summary.evaluations) + " evaluations (alpha_max " +
                      std::to_string(in.max_feasible_step) + ")";
  }
  return summary;
}

}  // namespace akvf
