#include "akvf/optimizer.h"

#include <chrono>
#include <cmath>

#include "akvf/error.h"
#include "framework/optimization/iteration_limit.h"
#include "framework/process/interrupt.h"

namespace akvf {

namespace {

// AQP's extrapolated point y = x + theta (x - previous), or nothing when it
// is not allowed (first iteration, no motion, an inverted element, or higher
// energy than at x).
struct Extrapolation {
  Eigen::VectorXd y, gradient;
  double energy = 0;
};

bool extrapolate(const Objective& objective, const Eigen::VectorXd& x, const Eigen::VectorXd& previous, double energy,
                 double eta, Extrapolation* out) {
  const Eigen::VectorXd motion = x - previous;
  if (!(motion.squaredNorm() > 0)) return false;
  const double root = 1 / std::sqrt(eta);
  const double theta = std::min((1 - root) / (1 + root), 0.8 * objective.max_feasible_step(x, motion));
  if (!(theta > 0)) return false;
  out->y = x + theta * motion;
  out->energy = objective.value_and_gradient(out->y, &out->gradient);
  return out->energy <= energy && out->gradient.allFinite();
}

// "; first bad element: triangle 3 (...): ..." or "" when the objective
// finds nothing wrong with x.
std::string bad_element_note(const Objective& objective, const Eigen::VectorXd& x) {
  const std::string bad = objective.first_bad_element(x);
  return bad.empty() ? "" : "; first bad element: " + bad;
}

}  // namespace

std::string status_with_reason(const OptimizerResult& result) {
  if (result.status != TerminationStatus::kStalled || result.message.empty()) return to_string(result.status);
  return to_string(result.status) + " (" + result.message + ")";
}

bool OptimizerOptions::is_valid(std::string* error) const {
  auto fail = [&](const std::string& message) {
    if (error) *error = message;
    return false;
  };
  if (!(gradient_tolerance >= 0)) return fail("gradient tolerance must be >= 0");
  if (max_iterations < 0) return fail("max iterations must be >= 0");
  if (!(time_limit > 0)) return fail("time limit must be > 0 seconds");
  if (!(stall_tolerance >= 0)) return fail("stall tolerance must be >= 0");
  if (stall_iterations < 1) return fail("stall iterations must be >= 1");
  if (!(acceleration_eta == 0 || acceleration_eta > 1)) return fail("acceleration eta must be 0 (off) or > 1");
  return true;
}

std::string to_string(TerminationStatus status) {
  switch (status) {
    case TerminationStatus::kConverged:
      return "converged";
    case TerminationStatus::kMaxIterations:
      return "max-iterations";
    case TerminationStatus::kTimeLimit:
      return "time-limit";
    case TerminationStatus::kStalled:
      return "stalled";
    case TerminationStatus::kLineSearchFailed:
      return "line-search-failed";
    case TerminationStatus::kNumericalFailure:
      return "numerical-failure";
    case TerminationStatus::kUserStopped:
      return "user-stopped";
    case TerminationStatus::kInterrupted:
      return "interrupted";
  }
  return "unknown";
}

bool is_normal_termination(TerminationStatus status) {
  return status != TerminationStatus::kLineSearchFailed && status != TerminationStatus::kNumericalFailure;
}

OptimizerResult minimize(const Objective& objective, Preconditioner& preconditioner, const LineSearch& line_search,
                         Eigen::VectorXd x, const OptimizerOptions& options,
                         const std::vector<IterationCallback>& callbacks) {
  std::string invalid;
  if (!options.is_valid(&invalid)) throw OptionsError(invalid);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

  OptimizerResult result;
  Eigen::VectorXd gradient, preconditioned;
  double energy = objective.value_and_gradient(x, &gradient);

  auto finish = [&](TerminationStatus status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    result.x = std::move(x);
    return result;
  };
  auto notify = [&](const IterationSummary& summary) {
    result.trace.push_back(summary);
    bool stop = false;
    for (const auto& callback : callbacks) stop |= callback(summary, x) == CallbackAction::kStop;
    return stop;
  };

  IterationSummary row;
  row.energy = finite_or_inf(energy);
  row.grad_norm = finite_or_inf(gradient.norm());
  row.flips = objective.count_inverted(x);
  row.constraint_distance = objective.constraint_distance(x);
  row.seconds = elapsed();
  // A gradient of finite entries whose norm overflows is as unusable.
  if (!std::isfinite(energy) || !std::isfinite(row.grad_norm)) {
    result.trace.push_back(row);
    return finish(TerminationStatus::kNumericalFailure,
                  (row.flips > 0 ? "the initial map has " + std::to_string(row.flips) + " inverted elements"
                                 : std::string("the initial energy or gradient is not finite")) +
                      bad_element_note(objective, x));
  }
  if (notify(row)) return finish(TerminationStatus::kUserStopped, "stopped by a callback");

  const InterruptibleLoop interruptible;  // a signal now ends the loop below cleanly
  int stalled_iterations = 0;
  bool backtracked = false;  // the last line search accepted less than its first trial
  Eigen::VectorXd previous = x;
  Extrapolation extrapolation;
  for (int k = 1;; ++k) {
    if (row.grad_norm < options.gradient_tolerance)
      return finish(TerminationStatus::kConverged, "gradient norm below " + std::to_string(options.gradient_tolerance));
    if (k > options.max_iterations)
      return finish(TerminationStatus::kMaxIterations,
                    iteration_limit_message(result.trace, options.gradient_tolerance, options.max_iterations));
    if (elapsed() >= options.time_limit) return finish(TerminationStatus::kTimeLimit, "reached the time limit");
    if (interrupt_requested()) return finish(TerminationStatus::kInterrupted, "interrupted by a signal");

    // The point the step starts from: x, or AQP's extrapolation of it.
    const bool accelerated = options.acceleration_eta > 0 &&
                             extrapolate(objective, x, previous, energy, options.acceleration_eta, &extrapolation);
    const Eigen::VectorXd& start_x = accelerated ? extrapolation.y : x;
    const Eigen::VectorXd& start_gradient = accelerated ? extrapolation.gradient : gradient;
    const double start_energy = accelerated ? extrapolation.energy : energy;

    const auto precond_start = Clock::now();
    preconditioner.update({start_x, start_gradient, start_energy, k, row.step, row.max_step, backtracked});
    preconditioner.apply(start_gradient, &preconditioned);
    const double precond_seconds = std::chrono::duration<double>(Clock::now() - precond_start).count();

    const Eigen::VectorXd direction = -preconditioned;
    if (!direction.allFinite())
      return finish(TerminationStatus::kNumericalFailure,
                    "the preconditioner returned a non-finite direction at iteration " + std::to_string(k) + " (" +
                        first_non_finite_entry(direction, "entry") + "); the last finite iterate is kept");
    LineSearchSummary search = line_search.search(objective, start_x, start_energy, start_gradient, direction);
    if (!search.success)
      return finish(TerminationStatus::kLineSearchFailed,
                    "line search failed at iteration " + std::to_string(k) + ": " + search.message);
    backtracked = search.step < search.initial_step;
    Eigen::VectorXd next = accepted_point(start_x, direction, search);
    bool moved_after = false;
    if (options.after_bound_set_step && search.bound_cut_initial_step && !backtracked) {
      if (search.gradient.size() != next.size()) search.energy = objective.value_and_gradient(next, &search.gradient);
      moved_after = options.after_bound_set_step(search.gradient, &next);
    }
    previous.swap(x);
    x.swap(next);
    const double previous_energy = energy;
    if (search.gradient.size() == x.size() && !moved_after) {
      energy = search.energy;
      gradient.swap(search.gradient);
    } else {
      energy = objective.value_and_gradient(x, &gradient);
    }

    row = IterationSummary{};
    row.iteration = k;
    row.energy = energy;
    row.grad_norm = gradient.norm();
    row.step = search.step;
    row.max_step = search.max_feasible_step;
    row.initial_step = search.initial_step;
    row.bound_cut_initial_step = search.bound_cut_initial_step;
    row.ls_evals = search.evaluations;
    row.flips = objective.count_inverted(x);
    row.constraint_distance = objective.constraint_distance(x);
    row.precond_seconds = precond_seconds;
    row.line_search_seconds = search.seconds;
    row.seconds = elapsed();
    if (!std::isfinite(energy) || !std::isfinite(row.grad_norm) || row.flips > 0) {
      // Never hand back a bad iterate: the result is the last accepted one,
      // whose row ends the trace.
      const std::string note = bad_element_note(objective, x);
      x.swap(previous);
      // In exact arithmetic no element inverts below alpha_max (§5.3), so an
      // inversion there means an element was already degenerate to rounding:
      // an energy without a barrier (ARAP) lets elements collapse, and the
      // bound cannot be resolved any further. The run has ended, not failed.
      if (std::isfinite(energy) && std::isfinite(row.grad_norm) && search.step < search.max_feasible_step)
        return finish(TerminationStatus::kStalled,
                      "iteration " + std::to_string(k) + " would invert " + std::to_string(row.flips) +
                          " element(s) within the flip-free bound, i.e. an element has collapsed to rounding (the "
                          "energy does not keep it from inverting)" +
                          note + "; the previous iterate is kept");
      return finish(TerminationStatus::kNumericalFailure,
                    "iteration " + std::to_string(k) +
                        " produced a non-finite energy or gradient or an inverted element (" +
                        std::to_string(row.flips) + " inverted)" + note + "; the previous iterate is kept");
    }
    if (notify(row)) return finish(TerminationStatus::kUserStopped, "stopped by a callback");

    stalled_iterations = previous_energy - energy <= options.stall_tolerance * std::max(1.0, std::abs(energy))
                             ? stalled_iterations + 1
                             : 0;
    // A run whose last step reached the gradient tolerance has converged
    // (the loop's first check), however little the energy moved.
    if (stalled_iterations >= options.stall_iterations && !(row.grad_norm < options.gradient_tolerance))
      return finish(TerminationStatus::kStalled, "energy decreased by less than " +
                                                     number_text(options.stall_tolerance) + " (relative) for " +
                                                     std::to_string(options.stall_iterations) + " iterations");
  }
}

}  // namespace akvf
