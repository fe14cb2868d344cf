#pragma once
// The JSON summary of one run: what `akvf param --summary`, `akvf deform
// --summary` and every case of the experiment runner (cases/<id>/summary.json)
// write. Fields: docs/experiments.md, "summary.json"; JSON Schema:
// docs/run_summary.schema.json.
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "akvf/internal/option_schema.h"
#include "akvf/optimizer.h"
#include "akvf/preconditioner.h"
#include "framework/mesh/mesh_validation.h"
#include "framework/mesh/seam_opening.h"

namespace akvf {

using Json = nlohmann::ordered_json;

// Linux: resets the process's peak resident set size (VmHWM), so that
// peak_memory_mb() after a run is that run's peak.
void reset_peak_memory();
// VmHWM of /proc/self/status in MiB (0 where unavailable).
double peak_memory_mb();

// Where and with what a run ran: CPU, cores, TBB threads, versions of akvf
// (`git describe` at configure time), Eigen, CHOLMOD and the compiler.
Json machine_record();

// The outcome of a finished run: status, message, reached (gradient below
// the tolerance), iterations, seconds, final_energy, lower_bound, grad_norm,
// max_flips (over all iterates), vertices, elements, peak_memory_mb.
Json run_record(const OptimizerResult& result, double lower_bound, int vertices, int elements);

// What the linear algebra cost: factorizations, reused_solves (CG with an
// earlier factorization), cg_solves (plain Jacobi CG), cg_iterations,
// symbolic_analyses, multigrid_setups, and the preconditioner's one-line
// report (for akvf-newton: each phase, where it switched).
Json linear_algebra_record(const PreconditionerStatistics& statistics, const std::string& report);

// What the automatic cut did (--cut auto): charts, cut_edges, and per chart
// the genus and boundary loops of its component before the cut; and the
// straight cuts that split charts for the packing (min_coverage).
Json cut_record(const DiskMesh& disk, int packing_splits);
// What --cut seams did.
Json seam_record(const SeamReport& seams, double max_distortion);
// What --repair auto did: counts, and the first few edges, vertices and
// faces set aside, numbered as the file numbers them.
Json repair_record(const DiskMesh& disk);

// The options as the schema writes them: numbers as numbers, integers as
// integers (a time limit of inf as the text "inf"), switches as booleans,
// names as text.
template <class Options>
void record_options(const std::vector<OptionField<Options>>& fields, const Options& options, Json* out) {
  for (const auto& field : fields) {
    const std::string text = field.format(options);
    if (field.kind == OptionKind::kInteger) {
      (*out)[field.key] = std::stoll(text);
    } else if (field.kind == OptionKind::kNumber) {
      const double value = std::stod(text);
      (*out)[field.key] = std::isfinite(value) ? Json(value) : Json(text);
    } else if (field.kind == OptionKind::kSwitch) {
      (*out)[field.key] = text == "true";
    } else {
      (*out)[field.key] = text;
    }
  }
}

// The record of a single run (`--summary`): problem ("param" or "deform"),
// mesh_file, settings, the fields of run_record, machine.
Json single_run_summary(const std::string& problem, const std::string& mesh_file, const Json& settings,
                        const Json& record);

// Writes `summary` (indented) to `path` through a temporary file.
void write_summary(const std::string& path, const Json& summary);

}  // namespace akvf
