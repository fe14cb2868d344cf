#pragma once
// The uniform scale at which a map starts best: a saved map (a texture's unit
// square, or any other scale) restarts at the energy it was saved with.
#include <Eigen/Core>

#include "akvf/objective.h"

namespace akvf {

// The s > 0 minimizing E(s x), or 1 when E does not depend on the scale
// (MIPS, AMIPS), is not finite at x, or has no minimum along s within
// e^-20 < s < e^20. Searched on t = log s, where the slope is
// dE/dt = grad E(e^t x) . e^t x: brackets a sign change of the slope by
// doubling steps downhill, then bisects it to 1e-12 in t. Symmetric Dirichlet
// s^2 a + s^-2 b is convex in t with its minimum at s^4 = b / a.
double best_uniform_scale(const Objective& objective, const Eigen::VectorXd& x);

}  // namespace akvf
