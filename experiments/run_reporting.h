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

// The exit code of a finished run: 0 for a normal end, 130 when interrupted,
// 3 for a line-search or numerical failure (exit_codes.h).
int exit_code_of(const OptimizerResult& result);

// "status converged after 28 iterations, 1.1 s: energy ..., gradient norm ..., 0 inverted"
std::string summary_line(const OptimizerResult& result);

}  // namespace akvf
