#include "preconditioners/switching_preconditioner.h"

#include <algorithm>
#include <cmath>

namespace akvf {

namespace {

void add_statistics(const PreconditionerStatistics& more, PreconditionerStatistics* sum) {
  sum->factorizations += more.factorizations;
  sum->cg_solves += more.cg_solves;
  sum->reused_solves += more.reused_solves;
  sum->cg_iterations += more.cg_iterations;
  sum->symbolic_analyses += more.symbolic_analyses;
  sum->multigrid_setups += more.multigrid_setups;
}

}  // namespace

SwitchingPreconditioner::SwitchingPreconditioner(std::string name, std::unique_ptr<Preconditioner> first,
                                                 Factory second, SwitchRule rule, Factory first_again)
    : name_(std::move(name)),
      current_(std::move(first)),
      make_second_(std::move(second)),
      make_first_again_(std::move(first_again)),
      rule_(rule),
      patience_(rule.patience) {}

std::optional<SwitchReason> SwitchingPreconditioner::leave_first(const OptimizationState& state) {
  const double step = state.previous_step;
  const bool curvature_limited = step > 0 && step < rule_.bound_share * state.previous_max_step;
  const bool newton_like =
      state.previous_backtracked && step >= std::sqrt(rule_.backtracking_factor) * rule_.isometric_step;
  // More than Newton's step lowers the logarithm of an exponential energy (module comment).
  const bool beyond_newton = state.energy * std::exp(1.0) < previous_energy_;
  const bool curvature_set = curvature_limited && !newton_like && !beyond_newton;
  // The bound set the step, far short of the model's (a step t along d
  // gains 2 t c - (t c)^2 of the decrease of the quadratic model c K, less
  // than half of it below t c = 1 - 1/sqrt(2)), and E - E_lb kept more than
  // stall_ratio of itself (NaN, so false, where E_lb is unknown).
  const bool barrier_limited = step < (1 - std::sqrt(0.5)) * rule_.isometric_step;
  const double gap_ratio = gap_kept(state);
  const bool stalled = step > 0 && !curvature_limited && barrier_limited && gap_ratio > rule_.stall_ratio;
  // Either kind of step is behind Newton's pace, so a run of them in any mix counts.
  limited_steps_ = curvature_set || stalled ? limited_steps_ + 1 : 0;
  // The first trial, short of the model's minimizer, accepted at once.
  const bool bound_set = step > 0 && step < rule_.isometric_step && !state.previous_backtracked && !curvature_limited;
  if (bound_set) first_phase_pace_ = gap_ratio;
  if (limited_steps_ >= patience_) return stalled ? SwitchReason::kStalled : SwitchReason::kCurvatureSet;
  if (bound_set && constraints_far(state)) return SwitchReason::kConstraintsFar;
  return std::nullopt;
}

double SwitchingPreconditioner::gap_kept(const OptimizationState& state) const {
  return (state.energy - rule_.energy_lower_bound) / (previous_energy_ - rule_.energy_lower_bound);
}

bool SwitchingPreconditioner::constraints_far(const OptimizationState& state) const {
  if (!rule_.distortion_energy) return false;
  const double added = state.energy - rule_.distortion_energy(state.x);
  return added > rule_.added_share * (state.energy - rule_.energy_lower_bound);
}

bool SwitchingPreconditioner::leave_second(const OptimizationState& state) {
  // The first trial min(1, 0.8 alpha_max) was below Newton's unit step and
  // accepted at once: the flip-free bound set it; and the bound is less than
  // half the step before's (the steps close in on a collapse) or a small
  // share of the unit step (the model's minimizer lies far beyond a
  // collapse) (module comment).
  const double step = state.previous_step;
  const bool bound_limited = step > 0 && step < 1 && !state.previous_backtracked;
  const bool closing_in = state.previous_max_step < rule_.closing_ratio * previous_max_step_;
  const bool model_far = state.previous_max_step < rule_.far_share;
  // Behind the first's pace: E - E_lb kept more than stall_ratio of itself
  // and more than the first phase's last bound-set step kept, where the
  // model promised more than 1 - stall_ratio of it (module comment).
  const bool behind_first =
      gap_kept(state) > std::max(rule_.stall_ratio, first_phase_pace_) &&
      promised_decrease_ > (1 - rule_.stall_ratio) * (previous_energy_ - rule_.energy_lower_bound);
  limited_steps_ = bound_limited && (closing_in || model_far || behind_first) ? limited_steps_ + 1 : 0;
  return limited_steps_ >= rule_.patience;
}

std::string SwitchingPreconditioner::current_report() const {
  const std::string since = switches_.empty() ? "" : "from iteration " + std::to_string(switches_.back()) + " ";
  return since + current_->name() + ": " + current_->report();
}

void SwitchingPreconditioner::switch_to(const Factory& make, SwitchReason why, int iteration) {
  std::unique_ptr<Preconditioner> next = make(*current_, why);
  released_reports_ += (released_reports_.empty() ? "" : "; ") + current_report();
  add_statistics(current_->statistics(), &released_statistics_);
  current_ = std::move(next);
  switches_.push_back(iteration);
  limited_steps_ = 0;
}

void SwitchingPreconditioner::update(const OptimizationState& state) {
  // The last step is the phase in use's: a switch takes effect at once.
  if (!in_second()) {
    if (const std::optional<SwitchReason> why = leave_first(state)) switch_to(make_second_, *why, state.iteration);
  } else if (make_first_again_ && leave_second(state)) {
    switch_to(make_first_again_, SwitchReason::kClosingIn, state.iteration);
    patience_ *= 2;
  }
  previous_energy_ = state.energy;
  previous_max_step_ = state.previous_max_step;
  current_->update(state);
}

void SwitchingPreconditioner::apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) {
  current_->apply(gradient, result);
  if (in_second()) promised_decrease_ = 0.5 * gradient.dot(*result);
}

std::string SwitchingPreconditioner::report() const {
  return released_reports_ + (released_reports_.empty() ? "" : "; ") + current_report() +
         (switches_.empty() ? "; no switch" : "");
}

PreconditionerStatistics SwitchingPreconditioner::statistics() const {
  PreconditionerStatistics sum = released_statistics_;
  add_statistics(current_->statistics(), &sum);
  return sum;
}

}  // namespace akvf
