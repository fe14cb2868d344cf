#pragma once
// Pieces the command-line programs share: the output folder, per-iteration
// progress lines and the closing summary line.
#include <ostream>
#include <string>

#include "framework/optimization/optimizer.h"

namespace akvf {

// Creates `folder` and its parents if needed; OutputError naming it if that
// fails or it is not a folder.
void create_output_folder(const std::string& folder);

// Prints one progress line per iteration on `err`.
IterationCallback progress_printer(std::ostream& err);

// The exit code of a finished run: 0 for a normal end, 130 when interrupted,
// 3 for a line-search or numerical failure (exit_codes.h).
int exit_code_of(const OptimizerResult& result);

// "status converged after 28 iterations, 1.1 s: energy ..., gradient norm ..., 0 inverted"
std::string summary_line(const OptimizerResult& result);

}  // namespace akvf
