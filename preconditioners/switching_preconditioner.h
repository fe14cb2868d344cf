#pragma once
// Two preconditioners in sequence: the first while the flip-free bound
// decides the step, the second once the energy's curvature does.
//
// AKVF (§4-§5) is at its best far from the minimum, where the step is set by
// the flip-free bound alpha_max (§5.3) and K's near-rigid global motions
// move the whole map at once: the line search's first trial, a fixed share
// of alpha_max, is accepted. Near the minimum the bound recedes and the step
// is set by the energy's curvature along a direction K scales poorly: the
// line search shortens it several times per iteration and AKVF converges
// linearly (docs/design.md, "The default method"). That regime is where a
// Newton model converges quadratically. The switch is made when, in
// `patience` consecutive iterations, the accepted step was below
// `bound_share` times its flip-free bound, i.e. the line search had to
// shorten the step while the barrier was at least 1 / bound_share times
// farther. It is made once and never undone.
#include <functional>
#include <memory>
#include <string>

#include "framework/optimization/preconditioner.h"

namespace akvf {

struct SwitchRule {
  double bound_share = 0.5;  // a step below this share of alpha_max was set by curvature
  int patience = 2;          // consecutive such steps before switching
};

class SwitchingPreconditioner final : public Preconditioner {
 public:
  using Factory = std::function<std::unique_ptr<Preconditioner>()>;
  // `second` is built when the switch happens (its setup costs nothing before).
  SwitchingPreconditioner(std::string name, std::unique_ptr<Preconditioner> first, Factory second,
                          SwitchRule rule = {});

  std::string name() const override { return name_; }
  void update(const OptimizationState& state) override;
  void apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) override;
  std::string report() const override;
  PreconditionerStatistics statistics() const override;
  // The iteration at which the second preconditioner took over, or 0.
  int switch_iteration() const { return switch_iteration_; }

 private:
  std::string name_;
  std::unique_ptr<Preconditioner> first_, second_;
  Factory make_second_;
  SwitchRule rule_;
  int curvature_limited_steps_ = 0;
  int switch_iteration_ = 0;
};

}  // namespace akvf
