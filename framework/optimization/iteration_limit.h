#pragma once
// Why a run that reached its iteration limit had not converged, in words:
// how the gradient norm fell over the last fifth of the run, how many more
// iterations that rate would need to reach the tolerance, and what held the
// last tenth's steps. A method
// whose model is far from the energy's curvature converges linearly and
// slowly (the paper's K on ARAP: docs/energies.md); one that is stuck does not
// lower the gradient at all.
#include <string>
#include <vector>

#include "akvf/optimizer.h"

namespace akvf {

// "reached 1000 iterations; the least gradient norm of iterations 801-900
// was 0.0469, of 901-1000 0.036 (tolerance 0.0001): about 3500 more
// iterations at that rate" (blocks of a tenth of the run, at least 10
// iterations). trace: the run's rows (row 0 the start; warm-start rows are
// skipped).
std::string iteration_limit_message(const std::vector<IterationSummary>& trace, double gradient_tolerance,
                                    int max_iterations);

// What held the steps of `rows` (the last block), as a clause that starts
// with "; ", from the rows whose line search reported its first trial
// alpha_0 (none: ""). Whichever kind makes up more than half of them:
// - the search took less than alpha_0 (backtracking, or the parabola's
//   minimizer after an overshoot): the preconditioner's model, whose
//   minimizer along the direction is its own step 1, is softer than the
//   energy there (SLIM on the exponential energy, the paper's K on ARAP);
// - alpha_0 was the flip-free bound's share and was taken: an element
//   close to collapse limits every step (an energy whose infimum presses
//   elements onto a collapse);
// - alpha_0 was the direction's own step and was taken: the steps are not
//   held, so where the gradient falls slowly the preconditioner P is
//   stiffer than the energy's Hessian H in some directions (P^-1 H has
//   eigenvalues far below 1: projected Newton's clamped Hessian);
// - the search took more than alpha_0 (a Wolfe search's growth): the model
//   is stiffer than the energy along the direction.
// Otherwise the counts.
std::string step_diagnosis(const std::vector<IterationSummary>& rows);

}  // namespace akvf
