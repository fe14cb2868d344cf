#include "solvers/lbfgs_solver.h"

#include <ceres/ceres.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "akvf/error.h"
#include "framework/optimization/iteration_limit.h"
#include "framework/process/interrupt.h"

namespace akvf {

namespace {

// The objective for Ceres. A point is a failed evaluation (Ceres' line
// search then shortens the step) when an element is inverted there, or when
// the segment from the last accepted iterate to it leaves the objective's
// feasible region on the way (Objective::max_feasible_step: an element
// inverted and back, or a boundary contact under global injectivity).
class ObjectiveFunction final : public ceres::FirstOrderFunction {
 public:
  //   accepted  the last accepted iterate (Ceres updates it every iteration)
  ObjectiveFunction(const Objective& objective, const Eigen::VectorXd& accepted)
      : objective_(objective),
        accepted_(accepted),
        x_(objective.num_variables()),
        gradient_(objective.num_variables()) {}

  bool Evaluate(const double* parameters, double* cost, double* gradient) const override {
    x_ = Eigen::Map<const Eigen::VectorXd>(parameters, x_.size());
    if (x_ != accepted_ && !(objective_.max_feasible_step(accepted_, x_ - accepted_) >= 1)) return false;
    if (gradient) {
      *cost = objective_.value_and_gradient(x_, &gradient_);
      Eigen::Map<Eigen::VectorXd>(gradient, x_.size()) = gradient_;
    } else {
      *cost = objective_.value(x_);
    }
    return std::isfinite(*cost);  // an inverted element: a failed evaluation
  }
  int NumParameters() const override { return objective_.num_variables(); }

 private:
  const Objective& objective_;
  const Eigen::VectorXd& accepted_;
  mutable Eigen::VectorXd x_, gradient_;
};

// Turns Ceres iterations into IterationSummary rows and applies our stopping
// rules and callbacks.
class TraceCallback final : public ceres::IterationCallback {
 public:
  TraceCallback(const Objective& objective, const Eigen::VectorXd& x, const OptimizerOptions& options,
                const std::vector<akvf::IterationCallback>& callbacks, OptimizerResult* result)
      : objective_(objective), x_(x), options_(options), callbacks_(callbacks), result_(result) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    IterationSummary row;
    row.iteration = s.iteration;
    row.seconds = s.cumulative_time_in_seconds;
    row.energy = s.cost;
    row.grad_norm = s.gradient_norm;
    row.step = s.iteration == 0 ? 0 : s.step_size;
    row.ls_evals = s.line_search_function_evaluations;
    row.flips = objective_.count_inverted(x_);
    row.constraint_distance = objective_.constraint_distance(x_);
    if (!s.step_is_successful && s.iteration > 0) return ceres::SOLVER_CONTINUE;  // not an iterate
    result_->trace.push_back(row);
    bool stop = false;
    for (const auto& callback : callbacks_) stop |= callback(row, x_) == CallbackAction::kStop;
    if (stop) {
      status_ = TerminationStatus::kUserStopped;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    if (row.grad_norm < options_.gradient_tolerance) {
      status_ = TerminationStatus::kConverged;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    if (row.seconds >= options_.time_limit) {
      status_ = TerminationStatus::kTimeLimit;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    if (interrupt_requested()) {
      status_ = TerminationStatus::kInterrupted;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }

  std::optional<TerminationStatus> status() const { return status_; }

 private:
  const Objective& objective_;
  const Eigen::VectorXd& x_;
  const OptimizerOptions& options_;
  const std::vector<akvf::IterationCallback>& callbacks_;
  OptimizerResult* result_;
  std::optional<TerminationStatus> status_;
};

}  // namespace

OptimizerResult minimize_lbfgs(const Objective& objective, Eigen::VectorXd x, const OptimizerOptions& options,
                               const LbfgsOptions& lbfgs, const std::vector<IterationCallback>& callbacks) {
  std::string invalid;
  if (!options.is_valid(&invalid)) throw OptionsError(invalid);
  if (lbfgs.memory < 1) throw OptionsError("L-BFGS memory must be >= 1");
  OptimizerResult result;
  if (const double energy = objective.value(x); !std::isfinite(energy)) {
    IterationSummary row;  // row 0 still describes the initial map
    row.energy = finite_or_inf(energy);
    row.grad_norm = std::numeric_limits<double>::infinity();
    row.flips = objective.count_inverted(x);
    row.constraint_distance = objective.constraint_distance(x);
    result.trace.push_back(row);
    const std::string bad = objective.first_bad_element(x);
    result.message = "the initial energy is not finite" + (bad.empty() ? "" : "; first bad element: " + bad);
    result.x = std::move(x);
    result.status = TerminationStatus::kNumericalFailure;
    return result;
  }
  ceres::GradientProblem problem(new ObjectiveFunction(objective, x));
  ceres::GradientProblemSolver::Options ceres_options;
  ceres_options.line_search_direction_type = ceres::LBFGS;
  ceres_options.max_lbfgs_rank = lbfgs.memory;
  ceres_options.max_num_iterations = options.max_iterations;
  // Our rules decide convergence; Ceres' relative tests are switched off.
  ceres_options.function_tolerance = 0;
  ceres_options.gradient_tolerance = 0;
  ceres_options.parameter_tolerance = 0;
  ceres_options.logging_type = ceres::SILENT;
  ceres_options.update_state_every_iteration = true;
  TraceCallback trace(objective, x, options, callbacks, &result);
  ceres_options.callbacks.push_back(&trace);
  ceres::GradientProblemSolver::Summary summary;
  {
    const InterruptibleLoop interruptible;  // the callback ends the solve cleanly on a signal
    ceres::Solve(ceres_options, problem, x.data(), &summary);
  }

  result.x = std::move(x);
  if (trace.status()) {
    result.status = *trace.status();
    result.message = result.status == TerminationStatus::kConverged
                         ? "gradient norm below " + std::to_string(options.gradient_tolerance)
                         : to_string(result.status);
  } else if (summary.termination_type == ceres::NO_CONVERGENCE) {
    result.status = TerminationStatus::kMaxIterations;
    result.message = iteration_limit_message(result.trace, options.gradient_tolerance, options.max_iterations);
  } else if (summary.termination_type == ceres::CONVERGENCE) {
    result.status = TerminationStatus::kStalled;
    result.message = "Ceres: " + summary.message;
  } else {
    result.status = TerminationStatus::kLineSearchFailed;
    result.message = "Ceres: " + summary.message;
  }
  return result;
}

}  // namespace akvf
