#include "preconditioners/switching_preconditioner.h"

#include <cmath>

namespace akvf {

SwitchingPreconditioner::SwitchingPreconditioner(std::string name, std::unique_ptr<Preconditioner> first,
                                                 Factory second, SwitchRule rule)
    : name_(std::move(name)), first_(std::move(first)), make_second_(std::move(second)), rule_(rule) {}

void SwitchingPreconditioner::update(const OptimizationState& state) {
  if (!second_) {
    const double step = state.previous_step;
    const bool curvature_limited = step > 0 && step < rule_.bound_share * state.previous_max_step;
    const bool newton_like =
        state.previous_backtracked && step >= std::sqrt(rule_.backtracking_factor) * rule_.isometric_step;
    // More than Newton's step lowers the logarithm of an exponential energy (module comment).
    const bool beyond_newton = state.energy * std::exp(1.0) < previous_energy_;
    curvature_limited_steps_ = curvature_limited && !newton_like && !beyond_newton ? curvature_limited_steps_ + 1 : 0;
    previous_energy_ = state.energy;
    if (curvature_limited_steps_ >= rule_.patience) {
      second_ = make_second_();
      switch_iteration_ = state.iteration;
      first_report_ = first_report();
      first_statistics_ = first_->statistics();
      first_.reset();
    }
  }
  (second_ ? *second_ : *first_).update(state);
}

void SwitchingPreconditioner::apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) {
  (second_ ? *second_ : *first_).apply(gradient, result);
}

std::string SwitchingPreconditioner::first_report() const { return first_->name() + ": " + first_->report(); }

std::string SwitchingPreconditioner::report() const {
  if (!second_) return first_report() + "; no switch";
  return first_report_ + "; from iteration " + std::to_string(switch_iteration_) + " " + second_->name() + ": " +
         second_->report();
}

PreconditionerStatistics SwitchingPreconditioner::statistics() const {
  PreconditionerStatistics sum = second_ ? first_statistics_ : first_->statistics();
  if (second_) {
    const PreconditionerStatistics more = second_->statistics();
    sum.factorizations += more.factorizations;
    sum.cg_solves += more.cg_solves;
    sum.reused_solves += more.reused_solves;
    sum.cg_iterations += more.cg_iterations;
    sum.symbolic_analyses += more.symbolic_analyses;
    sum.multigrid_setups += more.multigrid_setups;
  }
  return sum;
}

}  // namespace akvf
