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
// Newton model converges quadratically, unless AKVF is itself close to
// Newton's method: at an isometry the Hessian of the isometric energies is a
// multiple c K(x) of the Killing operator (energy_scale.h), so AKVF's
// direction with the step 1/c is Newton's. The switch is made when, in
// `patience` consecutive iterations, the accepted step t was below
// `bound_share` times its flip-free bound (the line search had to shorten
// the step while the barrier was at least 1 / bound_share times farther: the
// curvature set it) and did not show AKVF to be Newton-like. It shows that
// when the line search rejected a longer trial, t / rho, and t >= sqrt(rho)/c
// (rho the backtracking factor). Along a quadratic the sufficient-decrease
// test (small c1) accepts exactly the steps below twice the minimizing step
// t*, so then t / 2 < t* < t / (2 rho): t* lies within a factor 1 / rho of
// t, and above sqrt(rho) / (2 c), i.e. the energy curves along d less than
// 2 / sqrt(rho) (2.8 for rho = 0.5) times what c K predicts. A first trial
// accepted at once says nothing about the curvature (the step may be far
// too short), and a step shortened below sqrt(rho) / c says K misjudges it;
// both count toward the switch, unless the step lowered the energy by more
// than a factor e: Newton's steps on an energy that grows exponentially,
// E = exp(f), lower f = log E by only about 1 per iteration far from the
// minimum (the Newton step along f' is 1 / (f' + f''/f'), about 1 / f'),
// so an AKVF step that did more is outpacing Newton (AMIPS on cow_b from
// the Tutte map, E = 3e135: AKVF lowered log10 E by 4 to 16 per iteration,
// the Newton phase after a switch at iteration 9 by 0.4). That holds in 3D too, where AKVF scales K by
// the curvature measured along its *previous* step (the secant scale s_k,
// so its Newton step is 1): the scale says nothing about the new direction,
// and on the SLIM cube AKVF's unit steps, all accepted at once, decrease the
// energy far more slowly than Newton's (docs/design.md).
// On a nearly isometric map (hilbert_b, a developable strip) AKVF's steps
// are 1/c and it keeps AKVF, whose K models the flat bending modes better
// than the per-element projected Hessian (docs/design.md, "The default
// method"). The switch is made once and never undone, so the first
// preconditioner is released then (its report and statistics kept): its
// factor would otherwise stay in memory beside the second's.
#include <functional>
#include <limits>
#include <memory>
#include <string>

#include "framework/optimization/preconditioner.h"

namespace akvf {

struct SwitchRule {
  double bound_share = 0.5;  // a step below this share of alpha_max was set by curvature
  int patience = 2;          // consecutive such steps before switching
  // 1/c of energy_scale.h (isometric_newton_step); infinity: no step is
  // Newton-like, every curvature-set step counts.
  double isometric_step = std::numeric_limits<double>::infinity();
  double backtracking_factor = 0.5;  // rho of the line search
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
  std::string first_report() const;  // "name: report" of the first, while it exists

  std::string name_;
  std::unique_ptr<Preconditioner> first_, second_;
  std::string first_report_;  // "name: report" of the first, kept when it is released
  PreconditionerStatistics first_statistics_;
  Factory make_second_;
  SwitchRule rule_;
  int curvature_limited_steps_ = 0;
  double previous_energy_ = std::numeric_limits<double>::quiet_NaN();  // at the last update
  int switch_iteration_ = 0;
};

}  // namespace akvf
