#pragma once
// Runs the cases of a manifest (manifest.h) into a results folder:
//   OUT/manifest.json                 the manifest as read (merge and report check it)
//   OUT/cases/<id>/trace.csv          the optimizer trace (trace_csv.h; trace.csv.partial
//                                     grows row by row while the case runs)
//   OUT/cases/<id>/summary.json       iterations and seconds to the stopping rule,
//                                     final energy, gradient norm, flips, status,
//                                     machine, threads, versions
//   OUT/cases/<id>/iter-<k>.svg       UV layouts at the manifest's snapshot iterations
// Every file is written through a temporary name, so a killed run leaves no
// truncated summary; --resume skips the cases whose summary exists.
#include <ostream>
#include <string>
#include <vector>

#include "experiments/runner/manifest.h"

namespace akvf {

// Above this many faces the layout snapshots are PNG (2048 pixels), not SVG.
inline constexpr int kSvgFaceLimit = 100000;

struct RunnerOptions {
  std::string data_dir;  // the meshes
  std::string out_dir;
  int shard_index = 1, shard_count = 1;  // run the cases with index % count == index - 1
  bool resume = false;
  // Write cases/<id>/view.html for parameterization cases up to
  // kViewFaceLimit faces (html_view.h).
  bool views = false;
};

struct RunnerOutcome {
  int ran = 0, skipped = 0, failed = 0;  // failed: the case could not run (bad mesh file, ...)
  bool interrupted = false;              // a signal stopped the run (that case has no summary)
};

// Throws OutputError if out_dir holds results of a different manifest.
RunnerOutcome run_experiment(const Manifest& manifest, const RunnerOptions& options, std::ostream& progress);

// Copies the case results of `sources` (folders of earlier runs of one
// manifest) into `out_dir`. Throws InputError if the folders hold different
// manifests or one case twice with different summaries.
void merge_experiments(const std::vector<std::string>& sources, const std::string& out_dir, std::ostream& progress);

// "a/b" joined; "" stays relative.
std::string join_path(const std::string& folder, const std::string& name);

}  // namespace akvf
