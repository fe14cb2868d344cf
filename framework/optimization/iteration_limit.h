#pragma once
// Why a run that reached its iteration limit had not converged, in words:
// how the gradient norm fell over the last fifth of the run, and how many
// more iterations that rate would need to reach the tolerance. A method
// whose model is far from the energy's curvature converges linearly and
// slowly (AKVF on ARAP: docs/energies.md); one that is stuck does not
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

}  // namespace akvf
