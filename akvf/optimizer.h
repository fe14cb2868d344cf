#pragma once
// The preconditioned descent loop of Algorithm 1, generic in the objective,
// the preconditioner and the line search:
//   d_k = -P(x_k)^-1 grad E(x_k),  x_{k+1} = x_k + alpha_k d_k.
#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "akvf/line_search.h"
#include "akvf/objective.h"
#include "akvf/preconditioner.h"

namespace akvf {

struct OptimizerOptions {
  // Converged when ||grad E(x_k)||_2 < gradient_tolerance (§5.5; Table 1 uses 1e-3).
  double gradient_tolerance = 1e-3;
  // Upper bound on k.
  int max_iterations = 1000;
  // Upper bound on cumulative optimizer seconds; checked between iterations.
  double time_limit = std::numeric_limits<double>::infinity();
  // Stalled when E_{k-1} - E_k <= stall_tolerance * max(1, |E_k|) for
  // stall_iterations consecutive iterations (progress below round-off).
  double stall_tolerance = 1e-13;
  int stall_iterations = 10;
  // Momentum of AQP (Kovalsky, Galun and Lipman 2016), 0 = off. Before each
  // step the iterate is extrapolated to y = x_k + theta (x_k - x_{k-1}) with
  // theta = (1 - 1/sqrt(eta)) / (1 + 1/sqrt(eta)), capped at 0.8 of the
  // flip-free step along x_k - x_{k-1}; the direction and the line search
  // start from y. If E(y) > E(x_k) the step starts from x_k instead, so the
  // energy never increases.
  double acceleration_eta = 0;
  // Called after each step whose length the flip-free bound set (the line
  // search's first trial, cut by the bound, accepted), with the new iterate
  // and its gradient: it may move x to a point of no higher energy with no
  // inverted element (the optimizer checks) and returns whether it did.
  // Empty: none. The parameterization's local Newton sweeps
  // (ParameterizeOptions::local_sweep) are one.
  std::function<bool(const Eigen::VectorXd& gradient, Eigen::VectorXd* x)> after_bound_set_step;

  // True if every option is in range; otherwise *error says which is not.
  bool is_valid(std::string* error) const;
};

enum class TerminationStatus {
  kConverged,  // gradient norm below tolerance
  kMaxIterations,
  kTimeLimit,
  kStalled,
  kLineSearchFailed,  // no acceptable step; x is the last accepted iterate
  kNumericalFailure,  // non-finite energy or gradient
  kUserStopped,       // a callback asked to stop
  kInterrupted,       // SIGINT / SIGTERM (interrupt.h); x is the last accepted iterate
};
std::string to_string(TerminationStatus status);
// Converged, iteration or time limits, stall, user stops and interrupts are normal ends;
// the others mean the result should not be trusted as a minimum.
bool is_normal_termination(TerminationStatus status);

// What a trace row records for a value that is not finite: +inf, so that a
// trace never holds NaN (the run's message names the first bad element).
inline double finite_or_inf(double value) {
  return std::isfinite(value) ? value : std::numeric_limits<double>::infinity();
}

struct IterationSummary {
  int iteration = 0;
  // A row of the symmetric Dirichlet run that starts the exponential energies
  // (parameterization.h), not of the run itself.
  bool warm_start = false;
  double seconds = 0;  // cumulative optimizer time at the end of this iteration
  double energy = 0;
  double grad_norm = 0;        // ||grad E||_2 at the new iterate
  double step = 0;             // accepted alpha (0 for row 0)
  double max_step = 0;         // flip-free bound alpha_max
  // The line search's first trial alpha_0 (0 for row 0 and where the solver
  // does not say: L-BFGS), and whether the flip-free bound cut it below the
  // direction's own step (LineSearchSummary::bound_cut_initial_step).
  double initial_step = 0;
  bool bound_cut_initial_step = false;
  int ls_evals = 0;            // energy evaluations in the line search
  int flips = 0;               // inverted elements at the new iterate
  double precond_seconds = 0;  // update + apply
  double line_search_seconds = 0;
  // Objective::constraint_distance at the new iterate (NaN for a problem
  // without positional constraints).
  double constraint_distance = std::numeric_limits<double>::quiet_NaN();
};

enum class CallbackAction { kContinue, kStop };
using IterationCallback = std::function<CallbackAction(const IterationSummary&, const Eigen::VectorXd& x)>;

struct OptimizerResult {
  Eigen::VectorXd x;
  std::vector<IterationSummary> trace;  // row 0 is the initial map
  TerminationStatus status = TerminationStatus::kMaxIterations;
  std::string message;
};

// The status as the programs print it: "converged", or for a run that
// stalled the reason too ("stalled (Ceres: Parameter tolerance reached ...)"),
// since "stalled" alone does not say why.
std::string status_with_reason(const OptimizerResult& result);

OptimizerResult minimize(const Objective& objective, Preconditioner& preconditioner, const LineSearch& line_search,
                         Eigen::VectorXd x, const OptimizerOptions& options,
                         const std::vector<IterationCallback>& callbacks = {});

}  // namespace akvf
