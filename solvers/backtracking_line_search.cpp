#include "akvf/backtracking_line_search.h"

#include <algorithm>
#include <cmath>

#include "akvf/error.h"

namespace akvf {

namespace {
// A relative change of E below this is round-off (OptimizerOptions::stall_tolerance).
constexpr double kRoundOff = 1e-13;
}  // namespace

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
  // The rotation-following path (Objective::rotation_following_term), tried
  // beside each straight trial that fails when the first trial was the
  // direction's own step (max_initial_step: Newton's, or AKVF's at an
  // isometry): the energy along the straight line then left the model that
  // chose the step, as it does when the step turns elements. Where the
  // flip-free bound cut the first trial, a failure says an element nears
  // collapse, which no turn relieves. Asked for at the first failure.
  const bool model_step_first = alpha == settings_.max_initial_step;
  Eigen::VectorXd turn;
  bool turn_asked = false, has_turn = false;
  auto accept = [&](double energy) { return energy <= in.energy + settings_.c1 * alpha * in.directional_derivative; };
  // The first trial is usually accepted, and the optimizer then needs the
  // gradient there: it is evaluated with the energy.
  Eigen::VectorXd gradient;
  while (summary.evaluations < settings_.max_evaluations && alpha >= smallest) {
    trial = in.x + alpha * in.direction;
    const bool first = summary.evaluations == 0;
    double energy = first ? in.objective.value_and_gradient(trial, &gradient) : in.objective.value(trial);
    ++summary.evaluations;
    // +infinity (an inverted element) never satisfies the condition.
    if (!accept(energy) && model_step_first) {
      if (!turn_asked) has_turn = in.objective.rotation_following_term(in.x, in.direction, &turn);
      turn_asked = true;
      // The curved trial is taken only if the straight segment to it is
      // flip-free (a bound beyond 1 along trial - x): then so is the point.
      if (has_turn) {
        point_along_path(in.x, in.direction, turn, alpha, &trial);
        if (in.objective.max_feasible_step(in.x, trial - in.x) > 1 && summary.evaluations < settings_.max_evaluations) {
          const double curved = in.objective.value(trial);
          ++summary.evaluations;
          // Off the straight line only for a decrease above round-off (the
          // optimizer's stall tolerance): at the minimum to rounding the
          // straight line, the direction's own, keeps going.
          const bool resolved = in.energy - curved > kRoundOff * std::max(1.0, std::abs(in.energy));
          if (resolved && accept(curved)) {
            energy = curved;
            summary.turn = std::move(turn);
          }
        }
      }
    }
    if (accept(energy)) {
      summary.success = true;
      summary.step = alpha;
      summary.energy = energy;
      if (first && summary.turn.size() == 0) summary.gradient = std::move(gradient);
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
