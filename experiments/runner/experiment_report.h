#pragma once
// The reports of a results folder (experiment_runner.h), from its
// manifest.json and whatever case summaries it holds:
//   OUT/table.md    meshes x methods (time or energy at the stopping rule),
//                   with the paper's columns where the manifest gives them;
//                   missing meshes and cases not run say so in their cells
//   OUT/table.csv   one row per case: every summary field other tools need
//   OUT/plots/<mesh>-iterations.svg, <mesh>-seconds.svg
//                   energy minus the lower bound (log) per method
//   OUT/plots/seconds-per-iteration.svg
//                   per method, seconds per iteration against the element
//                   count (log-log), when the cases cover two sizes or more
#include <ostream>
#include <string>

namespace akvf {

// Returns the Markdown table (also written to OUT/table.md).
std::string write_experiment_report(const std::string& out_dir);

}  // namespace akvf
