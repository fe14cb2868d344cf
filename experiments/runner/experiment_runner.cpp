#include "experiments/runner/experiment_runner.h"

#include <tbb/global_control.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <thread>

#include "akvf/error.h"
#include "akvf/internal/deformation.h"
#include "akvf/internal/options.h"
#include "akvf/internal/parameterization.h"
#include "akvf/internal/slim_cube.h"
#include "akvf/mesh_io.h"
#include "akvf/tet_mesh_io.h"
#include "experiments/report/run_summary.h"
#include "experiments/report/trace_csv.h"
#include "framework/mesh/mesh_subdivision.h"
#include "framework/process/output_file.h"
#include "io/constraints_io.h"
#include "io/json_text.h"
#include "io/text_utilities.h"
#include "pictures/html_view.h"
#include "pictures/layout.h"
#include "pictures/uv_png.h"
#include "pictures/uv_svg.h"
#include "solvers/sparse_cholesky.h"

namespace akvf {

namespace fs = std::filesystem;

namespace {

Json settings_record(const CaseSettings& s) {
  Json j = {{"problem", s.problem}};
  if (s.problem == "deform") {
    record_options(deform_option_fields(), s.deform, &j);
    j["preset"] = s.preset;
    j["constraints"] = s.constraints;
  } else {
    record_options(parameterize_option_fields(), s.param, &j);
  }
  return j;
}

struct CaseResult {
  OptimizerResult result;
  double lower_bound = 0;
  int vertices = 0, elements = 0;
  std::optional<ViewContent> view;  // the final map, when views are asked for
  Json cut;                         // cut_record after --cut auto or seams, else null
  Json seams;                       // seam_record after --cut seams, else null
  Json linear_algebra;              // linear_algebra_record
};

CaseResult run_param_case(const ExperimentCase& c, const ManifestMesh& mesh, const std::string& mesh_path,
                          const std::string& case_dir, bool views, const IterationCallback& progress) {
  const CaseSettings& s = c.settings;
  const ParamConfig config = param_config(s.param);
  const ParamSetup setup =
      prepare_parameterization(subdivide_midpoint(read_triangle_mesh(mesh_path), mesh.subdivide), mesh_path, config);
  // SVG layouts hold about 60 bytes per triangle: above kSvgFaceLimit they
  // pass 6 MB and browsers crawl, so the layouts are PNG images instead.
  const bool png = setup.disk.mesh.num_faces() > kSvgFaceLimit;
  const auto snapshot = [&](const std::string& name, const ParamSetup& of, const Eigen::VectorXd& x,
                            const std::string& title) {
    if (png)
      write_layout_png(join_path(case_dir, name + ".png"), of, x, 2048);
    else
      write_layout_svg(join_path(case_dir, name + ".svg"), of, x, title);
  };
  std::vector<IterationCallback> callbacks = {progress};
  // With cut seams, the rounds after the first are maps of the mesh their
  // seams opened: no snapshot of them but the final one.
  const Eigen::Index first_mesh_size = 2 * static_cast<Eigen::Index>(setup.disk.mesh.num_vertices());
  callbacks.push_back([&](const IterationSummary& row, const Eigen::VectorXd& x) {
    for (int k : s.snapshots)
      if (row.iteration == k && x.size() == first_mesh_size)
        snapshot("iter-" + std::to_string(k), setup, x,
                 c.mesh_label + " - " + c.method_label + ", iteration " + std::to_string(k));
    return CallbackAction::kContinue;
  });
  CaseResult out;
  ParamRun run = run_parameterization(setup, config, callbacks);
  const ParamSetup& final = final_setup(setup, run);
  out.result = std::move(run.result);
  out.linear_algebra = linear_algebra_record(run.preconditioner_statistics, run.preconditioner_report);
  if (!s.snapshots.empty())  // also the layout where the run stopped (it may stop before a snapshot)
    snapshot("final", final, out.result.x,
             c.mesh_label + " - " + c.method_label + ", final (iteration " +
                 std::to_string(out.result.trace.back().iteration) + ")");
  out.lower_bound = final.objective->lower_bound();
  out.vertices = final.disk.mesh.num_vertices();
  out.elements = final.disk.mesh.num_faces();
  if (final.disk.cut) out.cut = cut_record(final.disk, run.packing_splits);
  if (config.seams) out.seams = seam_record(run.seams, config.max_distortion);
  if (views) out.view = view_of(final, out.result.x, c.mesh_label + " - " + c.method_label);
  return out;
}

// data_dir/relative, refused (InputError naming the manifest's key) when
// links lead it out of the data folder and the manifest does not allow it.
std::string data_path(const Manifest& manifest, const std::string& data_dir, const std::string& relative,
                      const std::string& key) {
  const std::string path = join_path(data_dir, relative);
  if (manifest.allow_outside_data_dir) return path;
  std::error_code error;
  const fs::path folder = fs::weakly_canonical(fs::absolute(data_dir), error);
  const fs::path resolved = fs::weakly_canonical(fs::absolute(path), error);
  const fs::path inside = resolved.lexically_relative(folder);
  if (error || inside.empty() || *inside.begin() == "..")
    throw InputError(key + ": " + path + " resolves to " + resolved.string() + ", outside the data folder " +
                     folder.string() + " (set \"allow_outside_data_dir\": true in the manifest to allow it)");
  return path;
}

CaseResult run_deform_case(const ExperimentCase& c, const std::string& mesh_path, const Manifest& manifest,
                           const std::string& data_dir, const IterationCallback& progress) {
  const CaseSettings& s = c.settings;
  const TetMesh mesh = read_tet_mesh(mesh_path);
  const PositionConstraints constraints =
      s.preset.empty() ? read_constraints_file(data_path(manifest, data_dir, s.constraints, "constraints of " + c.id),
                                               mesh.num_vertices())
                       : slim_cube_constraints(mesh);
  const DeformConfig config = deform_config(s.deform);
  const DeformRun run = run_deformation(mesh, mesh_path, constraints, config, {progress});
  CaseResult out;
  out.result = run.result;
  out.linear_algebra = linear_algebra_record(run.preconditioner_statistics, run.preconditioner_report);
  out.lower_bound = energies_3d().create(s.deform.energy, {s.deform.exponent})->lower_bound();
  out.vertices = run.prepared.mesh.num_vertices();
  out.elements = run.prepared.mesh.num_tets();
  return out;
}

// Runs one case and returns its summary record (also for a missing mesh or a case that failed to start).
Json run_case(const Manifest& manifest, const ExperimentCase& c, const RunnerOptions& options,
              const std::string& case_dir) {
  const ManifestMesh& mesh = manifest.meshes[c.mesh_index];
  Json summary;
  summary["id"] = c.id;
  summary["mesh"] = c.mesh_label;
  summary["method"] = c.method_label;
  summary["mesh_file"] = mesh.file;
  summary["settings"] = settings_record(c.settings);
  if (!mesh.missing.empty()) {
    summary["status"] = "missing";
    summary["message"] = mesh.missing;
    return summary;
  }
  try {
    const std::string path =
        data_path(manifest, options.data_dir, mesh.file, "meshes[" + std::to_string(c.mesh_index) + "].file");
    reset_peak_memory();
    GrowingTraceCsv trace(join_path(case_dir, "trace.csv"));  // trace.csv.partial while the case runs
    CaseResult r = c.settings.problem == "param"
                       ? run_param_case(c, mesh, path, case_dir, options.views, trace.callback())
                       : run_deform_case(c, path, manifest, options.data_dir, trace.callback());
    trace.finish(r.result);
    summary.update(run_record(r.result, r.lower_bound, r.vertices, r.elements));
    summary["linear_algebra"] = r.linear_algebra;
    if (!r.cut.is_null()) summary["cut"] = r.cut;
    if (!r.seams.is_null()) summary["seams"] = r.seams;
    if (r.view) {
      r.view->summary = summary;
      write_html_view(join_path(case_dir, "view.html"), *r.view);
    }
  } catch (const Error& e) {
    summary["status"] = "error";
    summary["message"] = e.what();
  }
  summary["machine"] = machine_record();
  return summary;
}

std::string format_seconds(double seconds) {
  std::ostringstream text;
  text << std::setprecision(seconds < 100 ? 2 : 3) << seconds << " s";
  return text.str();
}

// Writes the manifest into out_dir, or checks that the one there is the same.
void claim_folder(const Manifest& manifest, const std::string& out_dir) {
  create_output_folder(join_path(out_dir, "cases"));
  const std::string path = join_path(out_dir, "manifest.json");
  if (fs::exists(path)) {
    if (read_text_file(path) != manifest.source_text)
      throw OutputError(out_dir + ": holds the results of a different manifest (" + path +
                        "); choose another --out-dir or remove it");
    return;
  }
  write_file_atomically(path, [&](std::ostream& out) { out << manifest.source_text; });
}

}  // namespace

std::string join_path(const std::string& folder, const std::string& name) {
  return folder.empty() ? name : (fs::path(folder) / name).string();
}

RunnerOutcome run_experiment(const Manifest& manifest, const RunnerOptions& options, std::ostream& progress) {
  if (options.shard_count < 1 || options.shard_index < 1 || options.shard_index > options.shard_count)
    throw OptionsError("shard must be I/N with 1 <= I <= N");
  claim_folder(manifest, options.out_dir);
  std::vector<const ExperimentCase*> mine;
  for (const ExperimentCase& c : manifest.cases)
    if (c.index % options.shard_count == options.shard_index - 1) mine.push_back(&c);
  RunnerOutcome outcome;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  double ran_seconds = 0;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    const ExperimentCase& c = *mine[k];
    const std::string case_dir = join_path(join_path(options.out_dir, "cases"), c.id);
    const std::string summary_path = join_path(case_dir, "summary.json");
    progress << "[" << k + 1 << "/" << mine.size() << "] " << c.mesh_label << " / " << c.method_label << ": ";
    if (options.resume && fs::exists(summary_path)) {
      ++outcome.skipped;
      progress << "done earlier, skipped\n";
      continue;
    }
    create_output_folder(case_dir);
    const auto case_start = Clock::now();
    const Json summary = run_case(manifest, c, options, case_dir);
    if (summary["status"] == "interrupted") {  // no summary: --resume runs the case again
      progress << "interrupted; run again with --resume to finish the remaining cases\n";
      outcome.interrupted = true;
      break;
    }
    write_summary(summary_path, summary);
    ran_seconds += std::chrono::duration<double>(Clock::now() - case_start).count();
    ++outcome.ran;
    if (summary["status"] == "error") ++outcome.failed;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    const double left = ran_seconds / outcome.ran * static_cast<double>(mine.size() - k - 1);
    progress << summary["status"].get<std::string>();
    if (summary.contains("iterations"))
      progress << ", " << summary["iterations"].get<int>() << " iterations, "
               << format_seconds(summary["seconds"].get<double>());
    if (summary["status"] == "error" || summary["status"] == "missing")
      progress << " (" << summary["message"].get<std::string>() << ")";
    progress << "; elapsed " << format_seconds(elapsed) << ", about " << format_seconds(left) << " left\n";
  }
  return outcome;
}

void merge_experiments(const std::vector<std::string>& sources, const std::string& out_dir, std::ostream& progress) {
  if (sources.empty()) throw OptionsError("merge needs at least one results folder");
  std::string manifest_text;
  for (const std::string& source : sources) {
    const std::string path = join_path(source, "manifest.json");
    if (!fs::exists(path)) throw InputError(source + ": not a results folder (no manifest.json)");
    const std::string text = read_text_file(path);
    if (manifest_text.empty()) manifest_text = text;
    if (text != manifest_text) throw InputError(source + ": holds results of a different manifest than " + sources[0]);
  }
  Manifest manifest = parse_manifest(manifest_text, join_path(sources[0], "manifest.json"));
  claim_folder(manifest, out_dir);
  int copied = 0;
  for (const std::string& source : sources) {
    const fs::path cases = fs::path(source) / "cases";
    if (!fs::exists(cases)) continue;
    for (const auto& entry : fs::directory_iterator(cases)) {
      const fs::path summary = entry.path() / "summary.json";
      if (!fs::exists(summary)) continue;  // an unfinished case
      const fs::path target = fs::path(out_dir) / "cases" / entry.path().filename();
      if (fs::exists(target) && fs::equivalent(entry.path(), target)) continue;  // merging into a source
      if (fs::exists(target / "summary.json")) {
        const Json a = read_json_file(summary.string()), b = read_json_file((target / "summary.json").string());
        if (a["status"] != b["status"] || a.value("iterations", -1) != b.value("iterations", -1))
          throw InputError(source + ": case " + entry.path().filename().string() +
                           " is also in another folder with a different result");
        continue;
      }
      create_output_folder(target.string());
      for (const auto& file : fs::directory_iterator(entry.path()))
        fs::copy_file(file.path(), target / file.path().filename(), fs::copy_options::overwrite_existing);
      ++copied;
    }
  }
  progress << "merged " << copied << " cases into " << out_dir << '\n';
}

}  // namespace akvf
