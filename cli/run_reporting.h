#pragma once
// Pieces the commands share: per-iteration progress lines, the closing
// summary line and the exit code.
#include <ostream>
#include <string>

#include "akvf/optimizer.h"

namespace akvf {

// Prints one progress line per iteration on `err`.
IterationCallback progress_printer(std::ostream& err);

// The exit code of a finished run: 0 for a normal end, 130 when interrupted,
// 3 for a line-search or numerical failure (exit_codes.h).
int exit_code_of(const OptimizerResult& result);

// "status converged after 28 iterations, 1.1 s: energy ..., gradient norm ..., 0 inverted"; at the
// iteration limit a second line, "not converged: " and the run's message (iteration_limit.h).
std::string summary_line(const OptimizerResult& result);

}  // namespace akvf
