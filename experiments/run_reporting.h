#pragma once
// Pieces the command-line programs share: output-path checks, per-iteration
// progress lines and the closing summary line.
#include <ostream>
#include <string>

#include "framework/optimizer.h"

namespace akvf {

// OutputError if the folder of `path` does not exist ("" is no output).
void check_output_path(const std::string& path);

// Prints one progress line per iteration on `err`.
IterationCallback progress_printer(std::ostream& err);

// "status converged after 28 iterations, 1.1 s: energy ..., gradient norm ..., 0 inverted"
std::string summary_line(const OptimizerResult& result);

}  // namespace akvf
