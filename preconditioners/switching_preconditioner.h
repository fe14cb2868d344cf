#pragma once
// Two preconditioners: the first while the flip-free bound decides the
// step, the second once the energy's curvature does (and the first again if
// the bound comes back).
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
// method").
//
// AKVF stalling under the bound: far from the minimum the flip-free bound
// sets AKVF's steps, and on most meshes each of them removes a large share
// of the energy's excess over its infimum E_lb (the density's lower bound:
// energies are means over the rest measure). But K knows nothing of the
// energy: where a few elements carry most of the gradient (slivers of the
// initial map), K^-1 g drives them toward a collapse, alpha_max falls to
// 1e-5 of the direction, and each step removes a few percent of E - E_lb
// (tricera_b subdivided once: 80 such steps). Newton's direction weighs
// those elements by their curvature. Its bound-set steps left at most 0.84
// of E - E_lb at every iteration of its far phase on the meshes measured
// (docs/design.md), so an AKVF step that leaves more than `stall_ratio`
// (0.85) of it, although the bound and not the curvature set it, is behind
// Newton's pace, if the bound also held it below half of the decrease of
// AKVF's quadratic model c K (t c < 1 - 1/sqrt(2)): near the minimum E_lb
// lies below E* and every method's ratio tends to 1. `patience` such steps
// in a row switch too, and the two kinds count together: a phase that
// alternates them is as far behind Newton's pace as a run of either, and
// counted apart it would never switch (ARAP on jittered horse_b alternates
// AKVF's unit steps, set by the curvature, with bound-set steps keeping
// 0.99 of E; docs/notes/2026-12-04-switch-count-and-arap-tails.md).
//
// Constraints still far, the bound in the way: in deformation (§6.2) the
// energy adds soft constraints w sum |x_i - p_i|^2 to the distortion, and
// both preconditioners carry their Hessian, 2 w, exactly. From the rest
// shape (an isometry, where c K is the exact Hessian: energy_scale.h) AKVF's
// first step is Newton's. If that step was set by the flip-free bound (the
// first trial, below the model's minimizer, accepted at once) and the
// constraints still carry more than half of E - E_lb afterwards, the
// constrained vertices could not reach their targets without inverting
// elements: what limits the next step is how far the interior can follow,
// i.e. the elements' resistance to collapse, which the exact Hessian of a
// barrier energy carries (its curvature grows as an element is compressed)
// and the Killing operator, a measure of the motion's distance from a rigid
// one, does not. The switch is then made at once. Measured on the SLIM cube
// (twisted, 4.4 K and 48 K tets): after that first step the constraints
// carried more than 99.99 % of E - E_lb and AKVF's next step was held at 0.12 (0.14)
// of its direction, lowering E by 19 % (25 %), where Newton's unit step
// lowered it to 6.31 (6.24) from 10409 (272141); the lifted meshes, whose
// first step meets the constraints (their share falls below 2e-6), keep AKVF
// (docs/design.md, "The default method"). The factory is told the reason
// (SwitchReason): after this switch the elements the last step compressed
// leave the Hessian far from positive definite, and akvf-newton's Newton
// phase starts its fallback at the clamp (newton_preconditioner.h).
//
// Back to the first: Newton's quadratic model has its minimizer at the unit
// step. When the line search's first trial, 0.8 alpha_max, is below 1 and
// accepted at once, the flip-free bound and not the curvature set Newton's
// step: the model's minimizer lies beyond an inversion. That alone is no
// reason to leave (right after a switch Newton's first steps often meet the
// bound and still gain most: MIPS on camelhead), but when alpha_max is also
// smaller than the step before's, the steps close in on a collapse: each
// goes 0.8 of the way to it, and if the direction keeps pointing there the
// bound shrinks geometrically and the run stalls. Going 0.8 of the way
// leaves 0.2 of it, so along a direction of about the same length the next
// bound is about a fifth of the last; a bound that keeps more than
// `closing_ratio` (half) of the last is not closing in (Newton's far phase
// on tricera_b subdivided: 0.713, 0.710, 0.693). An energy whose infimum
// lies on a collapse does that (an energy without a collapse barrier, as
// ARAP's own density: energies/arap.h), and a barrier's stiff
// neighbourhood can. After
// `patience` such Newton steps in a row the first preconditioner is rebuilt
// (its assembly pattern anew) and takes over the second's analysis and
// factor. A bound-set Newton step counts as well when alpha_max is below
// `far_share` (1 %) of the unit step, however it compares with the last
// bound: the model puts its minimizer a hundred times farther than a
// collapse, and a step of t gains at most 2t - t^2 (2 %) of the decrease it
// promises, so the projected Hessian misses what limits the step (MIPS
// near its minimum on hilbert_b: MIPS is blind to each triangle's scale,
// and Newton's direction is long along those nearly singular modes). A
// share of 0.1 would cut into ARAP's Newton phases, which gain under the
// bound (docs/notes/2026-11-29-newton-held-far-short.md).
// A bound-set Newton step counts too when it is behind the first's pace: it
// kept more than stall_ratio of E - E_lb, as AKVF's stalled steps do, and
// more than the first phase's last bound-set step kept, while Newton's model
// promised a decrease g^T P^-1 g / 2 above 1 - stall_ratio of E - E_lb. Near a
// minimum E* above E_lb every step keeps nearly all of E - E_lb, and the
// promise, which estimates E - E*, is small there; a large promise held off
// by the bound means the model's minimizer is far and the bound lets through
// a sliver of it (2t - t^2 of the promise at step t). Where AKVF's own
// bound-set steps were slower (the last one kept more), Newton stays. On the
// jittered hilbert_b strips ARAP's Newton phase under the log-area damping
// (newton_preconditioner.h) promised 0.3-0.65 of E and gained 1-5 % per step;
// jittered camelhead's promised at most 0.14 of E, then below 1e-5
// (docs/notes/2026-12-04-newton-behind-first.md).
// Each return doubles the patience of the next switch to the second, so a
// run whose Newton phases keep meeting the barrier spends ever less of its
// iterations there.
// Whichever preconditioner is not in use is released (its report and
// statistics are kept): its factor would otherwise stay in memory beside the
// other's.
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "akvf/preconditioner.h"

namespace akvf {

struct SwitchRule {
  double bound_share = 0.5;  // a step below this share of alpha_max was set by curvature
  int patience = 2;          // consecutive such steps before switching
  // 1/c of energy_scale.h (isometric_newton_step); infinity: no step is
  // Newton-like, every curvature-set step counts.
  double isometric_step = std::numeric_limits<double>::infinity();
  double backtracking_factor = 0.5;  // rho of the line search
  // The energy's infimum E_lb (Objective::lower_bound: the density's, as
  // energies are means over the rest measure); -infinity if unknown: then
  // no step counts as stalled.
  double energy_lower_bound = -std::numeric_limits<double>::infinity();
  // A step the bound set stalls when E - E_lb keeps more than this share.
  double stall_ratio = 0.85;
  // A bound below this share of the step before's is closing in.
  double closing_ratio = 0.5;
  // A bound below this share of Newton's unit step puts the model's
  // minimizer far beyond a collapse.
  double far_share = 0.01;
  // The distortion part of the energy at x (the mesh objective's value)
  // when the problem adds terms to it (soft constraints): the state's energy
  // minus it is what they carry. Empty: no such terms, or unknown.
  std::function<double(const Eigen::VectorXd&)> distortion_energy;
  // A bound-set step switches at once when the added terms carry more than
  // this share of E - E_lb.
  double added_share = 0.5;
};

// Why the run left the phase in use (module comment): AKVF's steps set by
// the curvature, AKVF stalling under the bound, the constraints still far;
// Newton's steps held by the bound, closing in on a collapse, far short
// of the model's minimizer or behind the first's pace.
enum class SwitchReason { kCurvatureSet, kStalled, kConstraintsFar, kClosingIn };

class SwitchingPreconditioner final : public Preconditioner {
 public:
  // Builds a preconditioner when a switch happens (its setup costs nothing
  // before), from the one in use, whose factorization it may take over, and
  // told why; the one in use is released right after.
  using Factory = std::function<std::unique_ptr<Preconditioner>(Preconditioner& current, SwitchReason why)>;
  // Without `first_again` the switch to `second` is never undone.
  SwitchingPreconditioner(std::string name, std::unique_ptr<Preconditioner> first, Factory second, SwitchRule rule = {},
                          Factory first_again = nullptr);

  std::string name() const override { return name_; }
  void update(const OptimizationState& state) override;
  void apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) override;
  std::string report() const override;
  bool has_element_curvature() const override { return current_->has_element_curvature(); }
  PreconditionerStatistics statistics() const override;
  // The iteration at which the second preconditioner first took over, or 0.
  int switch_iteration() const { return switches_.empty() ? 0 : switches_.front(); }
  // Every iteration at which the preconditioner in use changed, in order
  // (first to second, back to the first, ...).
  const std::vector<int>& switches() const { return switches_; }
  bool in_second() const { return switches_.size() % 2 == 1; }

 private:
  // Counts the last step toward leaving the phase in use; the reason to
  // leave, or none.
  std::optional<SwitchReason> leave_first(const OptimizationState& state);
  // The share of E - E_lb the last step kept (NaN where E_lb is unknown
  // or there is no earlier energy).
  double gap_kept(const OptimizationState& state) const;
  // The problem's added terms (soft constraints) carry most of E - E_lb.
  bool constraints_far(const OptimizationState& state) const;
  bool leave_second(const OptimizationState& state);
  void switch_to(const Factory& make, SwitchReason why, int iteration);
  std::string current_report() const;  // "[from iteration k ]name: report" of the one in use

  std::string name_;
  std::unique_ptr<Preconditioner> current_;
  Factory make_second_, make_first_again_;
  SwitchRule rule_;
  std::string released_reports_;  // "name: report; from iteration k name: report; ..." of the released ones
  PreconditionerStatistics released_statistics_;
  std::vector<int> switches_;
  int patience_;           // of the next switch to the second
  int limited_steps_ = 0;  // consecutive steps that count toward leaving the phase in use
  double previous_energy_ = std::numeric_limits<double>::quiet_NaN();  // at the last update
  double previous_max_step_ = 0;                                       // alpha_max of the step before the last
  // The share of E - E_lb the first phase's last bound-set step kept (1 before any).
  double first_phase_pace_ = 1;
  // g^T d / 2 at the second's last apply, d the direction: the decrease
  // its model promises at the unit step (the quadratic model's, d = P^-1 g).
  double promised_decrease_ = 0;
};

}  // namespace akvf
