#include "cli/experiment_command.h"

#include <cstdlib>
#include <filesystem>

#include "akvf/error.h"
#include "akvf/threads.h"
#include "cli/command_line.h"
#include "cli/exit_codes.h"
#include "cli/run_reporting.h"
#include "experiments/runner/experiment_report.h"
#include "experiments/runner/experiment_runner.h"
#include "framework/process/output_file.h"
#include "pictures/html_view.h"

namespace akvf {

namespace {

const char* kMergeUsage =
    "akvf experiment merge RESULTS_DIR... [--out-dir DIR]\n\n"
    "Joins the results folders of the shards of one manifest (they must hold the same manifest.json)\n"
    "into --out-dir (default: the first folder), then writes the reports of the whole: table.md,\n"
    "table.csv, plots/*.svg and index.html. A case present in two folders must have the same status and iterations.";
const char* kReportUsage =
    "akvf experiment report RESULTS_DIR\n\n"
    "Writes table.md, table.csv, plots/*.svg and index.html again from the cases of a results folder.";
const char* kExperimentUsage =
    "akvf experiment MANIFEST.json [--data-dir DIR] [--out-dir DIR] [--shard I/N] [--resume] [--views] [--threads N]\n"
    "akvf experiment merge RESULTS_DIR... [--out-dir DIR]\n"
    "akvf experiment report RESULTS_DIR\n\n"
    "Runs every mesh x method case of a manifest (schema: docs/experiments.md), writing per case a trace\n"
    "CSV and a JSON summary (and with --views an HTML view of the final map), then the reports: table.md,\n"
    "table.csv, plots/*.svg and index.html (the table, the plots and a link to each case) in the results folder.\n"
    "--shard I/N runs every N-th case (cases I, I+N, ...; 1-based) so a sweep can be split across\n"
    "machines or job-array tasks; `merge` joins their folders and writes the reports of the whole.";

void parse_shard(const std::string& text, RunnerOptions* options) {
  const std::size_t slash = text.find('/');
  try {
    if (slash == std::string::npos) throw std::invalid_argument("no slash");
    std::size_t used = 0;
    options->shard_index = std::stoi(text.substr(0, slash), &used);
    if (used != slash) throw std::invalid_argument("trailing text");
    options->shard_count = std::stoi(text.substr(slash + 1), &used);
    if (used != text.size() - slash - 1) throw std::invalid_argument("trailing text");
  } catch (const std::logic_error&) {
    throw OptionsError("option --shard: expected I/N such as 1/4, found '" + text + "'");
  }
  if (options->shard_count < 1 || options->shard_index < 1 || options->shard_index > options->shard_count)
    throw OptionsError("option --shard: expected 1 <= I <= N, found '" + text + "'");
}

std::string default_data_dir() {
  const char* env = std::getenv("AKVF_DATA_DIR");
  return env && *env ? env : "../shared/meshes";
}

}  // namespace

int experiment_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CommandLine cl(kExperimentUsage,
                 {
                     {"data-dir", "DIR", "the meshes (default $AKVF_DATA_DIR, else ../shared/meshes)"},
                     {"out-dir", "DIR", "results folder (default experiment-results/<manifest name>)"},
                     {"shard", "I/N", "run only cases I, I+N, I+2N, ... (1-based)"},
                     {"resume", "", "skip cases whose summary.json exists"},
                     {"views", "",
                      "write cases/<id>/view.html (akvf view) for parameterizations (decimated for display "
                      "above " +
                          std::to_string(kViewFaceLimit) + " faces)"},
                     {"threads", "N", "worker threads per case (default: all cores)"},
                     {"help", "", "show this help"},
                 });
  cl.parse(args);
  if (cl.has("help") && cl.positional().empty()) {
    out << cl.help();
    return kExitOk;
  }
  const std::vector<std::string>& positional = cl.positional();
  if (positional.empty()) throw OptionsError("expected a manifest, `merge DIR...` or `report DIR` (see --help)");
  if (cl.has("help")) {
    if (positional[0] == "merge")
      out << "usage: " << kMergeUsage << '\n';
    else if (positional[0] == "report")
      out << "usage: " << kReportUsage << '\n';
    else
      out << cl.help();
    return kExitOk;
  }
  if (positional[0] == "merge") {
    const std::vector<std::string> sources(positional.begin() + 1, positional.end());
    if (sources.empty()) throw OptionsError("merge: expected at least one results folder");
    const std::string out_dir = cl.text("out-dir", sources[0]);
    merge_experiments(sources, out_dir, err);
    out << write_experiment_report(out_dir);
    return kExitOk;
  }
  if (positional[0] == "report") {
    if (positional.size() != 2) throw OptionsError("report: expected exactly one results folder");
    out << write_experiment_report(positional[1]);
    return kExitOk;
  }
  if (positional.size() != 1) throw OptionsError("expected exactly one manifest (see --help)");
  const Manifest manifest = read_manifest(positional[0]);
  RunnerOptions options;
  options.data_dir = cl.text("data-dir", default_data_dir());
  options.out_dir = cl.text("out-dir", join_path("experiment-results", slug(manifest.name)));
  if (cl.has("shard")) parse_shard(cl.text("shard", ""), &options);
  options.resume = cl.has("resume");
  options.views = cl.has("views");
  if (options.views) require_html_view();
  bool needs_data = false;
  for (const ManifestMesh& mesh : manifest.meshes) needs_data |= !mesh.file.empty();
  if (needs_data && !std::filesystem::is_directory(options.data_dir))
    throw OptionsError("meshes folder not found: " + options.data_dir + " (give --data-dir or set AKVF_DATA_DIR)");
  const ThreadLimit threads(cl.thread_count());
  if (options.shard_index > static_cast<int>(manifest.cases.size())) {
    err << manifest.name << ": shard " << options.shard_index << "/" << options.shard_count
        << " is empty: the manifest has " << manifest.cases.size() << " cases; nothing to run\n";
    return kExitOk;
  }
  create_output_folder(options.out_dir);  // before any case runs: exit 4 if it cannot be made
  err << manifest.name << ": " << manifest.cases.size() << " cases";
  if (options.shard_count > 1) err << ", shard " << options.shard_index << "/" << options.shard_count;
  err << ", results in " << options.out_dir << '\n';
  const RunnerOutcome outcome = run_experiment(manifest, options, err);
  out << write_experiment_report(options.out_dir);
  err << outcome.ran << " cases run, " << outcome.skipped << " skipped, " << outcome.failed << " failed\n";
  if (outcome.interrupted) return kExitInterrupted;
  return outcome.failed == 0 ? kExitOk : kExitOptimizerFailure;
}

}  // namespace akvf
