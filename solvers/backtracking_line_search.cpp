#include "akvf/backtracking_line_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "akvf/error.h"

namespace akvf {

namespace {
// A relative change of E below this is round-off (OptimizerOptions::stall_tolerance).
constexpr double kRoundOff = 1e-13;
// A straight step whose decrease is below this share of its linear
// prediction overshot the line's minimizer, if the line is a parabola, by
// more than 1.5 times: the parabola's minimizer then gains at least 4/3 of
// the step's decrease (1 / (4 r (1 - r)) at share r).
constexpr double kOvershootShare = 0.25;

// After an accepted straight step alpha with decrease ratio
// r = (E(x) - E(x + alpha d)) / (alpha |g^T d|) < kOvershootShare, tries
// the minimizer of the parabola through E(x), g^T d and E(x + alpha d),
// alpha / (2 (1 - r)), and keeps the lower of the two points. It lies
// between x and the accepted point, so it is flip-free, and it satisfies
// the sufficient-decrease condition whenever it is lower.
void try_line_minimizer(const LineSearchInput& in, Eigen::VectorXd* trial, LineSearchSummary* summary) {
  const double alpha = summary->step;
  const double r = (in.energy - summary->energy) / (alpha * -in.directional_derivative);
  if (!(r < kOvershootShare)) return;
  const double shorter = alpha / (2 * (1 - r));
  *trial = in.x + shorter * in.direction;
  Eigen::VectorXd gradient;
  const double energy = in.objective.value_and_gradient(*trial, &gradient);
  ++summary->evaluations;
  if (!(energy < summary->energy)) return;
  summary->step = shorter;
  summary->energy = energy;
  summary->gradient = std::move(gradient);
}

// E's round-off at E(x): below it, energy values no longer order the
// points along the line.
double round_off(double energy) { return kRoundOff * std::max(1.0, std::abs(energy)); }

// g^T d, or NaN where E is not finite or no gradient came with it (an
// objective may leave it empty at an inverted element).
double slope_along(double energy, const Eigen::VectorXd& gradient, const Eigen::VectorXd& direction) {
  return std::isfinite(energy) && gradient.size() == direction.size() ? gradient.dot(direction)
                                                                      : std::numeric_limits<double>::quiet_NaN();
}

// Hager and Zhang's approximate Wolfe condition, for E's rounding floor: a
// slope at alpha of at most (1 - 2 c1) |g^T d| is the sufficient-decrease
// condition of the parabola through E(x), g^T d and that slope. The
// measured E(x + alpha d) must still not exceed E(x): E never rises.
bool approximately_wolfe(const LineSearchInput& in, double c1, double energy, double slope) {
  return energy <= in.energy && slope <= (1 - 2 * c1) * -in.directional_derivative;
}

// After a first trial alpha that failed with a rising slope there, the
// minimizer of the parabola through E(x)'s slope and that slope (the secant
// step). Where that parabola's decrease is below round-off, the values of
// a backtracking search cannot find it; the secant step is then taken if
// its gradient passes the approximate Wolfe condition. The parabola is
// trusted only if it also predicts E(x + alpha d) to round-off (the
// trapezoid rule, exact for a parabola): far from the floor a long first
// trial fails that test.
bool try_secant_at_floor(const LineSearchInput& in, double c1, double alpha, double energy_at_alpha, double slope,
                         Eigen::VectorXd* trial, LineSearchSummary* summary) {
  const double descent = -in.directional_derivative;
  if (!(slope > 0)) return false;
  const double parabola_rise = 0.5 * alpha * (slope - descent);
  if (!(std::abs(energy_at_alpha - in.energy - parabola_rise) <= round_off(in.energy))) return false;
  const double secant = alpha * descent / (slope + descent);
  if (!(0.5 * secant * descent <= round_off(in.energy))) return false;
  *trial = in.x + secant * in.direction;
  Eigen::VectorXd gradient;
  const double energy = in.objective.value_and_gradient(*trial, &gradient);
  ++summary->evaluations;
  if (!approximately_wolfe(in, c1, energy, slope_along(energy, gradient, in.direction))) return false;
  summary->success = true;
  summary->step = secant;
  summary->energy = energy;
  summary->gradient = std::move(gradient);
  return true;
}
}  // namespace

BacktrackingLineSearch::BacktrackingLineSearch(LineSearchSettings settings) : settings_(settings) {
  std::string invalid;
  if (!settings_.is_valid(&invalid)) throw OptionsError(invalid);
}

LineSearchSummary BacktrackingLineSearch::do_search(const LineSearchInput& in) const {
  LineSearchSummary summary;
  double alpha = std::min(settings_.max_initial_step, settings_.max_step_fraction * in.max_feasible_step);
  summary.initial_step = alpha;
  summary.bound_cut_initial_step = alpha < settings_.max_initial_step;
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
    const double slope = first ? slope_along(energy, gradient, in.direction) : 0;
    const bool floor_accepted = first && !accept(energy) && approximately_wolfe(in, settings_.c1, energy, slope);
    if (first && !accept(energy) && !floor_accepted && summary.evaluations < settings_.max_evaluations &&
        try_secant_at_floor(in, settings_.c1, alpha, energy, slope, &trial, &summary))
      return summary;
    // +infinity (an inverted element) never satisfies the condition.
    if (!accept(energy) && !floor_accepted && model_step_first) {
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
          const bool resolved = in.energy - curved > round_off(in.energy);
          if (resolved && accept(curved)) {
            energy = curved;
            summary.turn = std::move(turn);
          }
        }
      }
    }
    if (accept(energy) || floor_accepted) {
      summary.success = true;
      summary.step = alpha;
      summary.energy = energy;
      if (first && summary.turn.size() == 0) summary.gradient = std::move(gradient);
      if (settings_.fit_parabola && !floor_accepted && summary.turn.size() == 0 &&
          summary.evaluations < settings_.max_evaluations)
        try_line_minimizer(in, &trial, &summary);
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
