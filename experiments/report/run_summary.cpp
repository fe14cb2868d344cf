#include "experiments/report/run_summary.h"

#include <tbb/global_control.h>

#include <malloc.h>
#include <algorithm>
#include <fstream>
#include <thread>

#include "framework/process/output_file.h"
#include "git_version.h"  // AKVF_VERSION: `git describe` at build time (experiments/CMakeLists.txt)
#include "solvers/sparse_cholesky.h"

namespace akvf {

namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

}  // namespace

// VmHWM restarts from the current resident size, so the memory an earlier
// case freed must leave the process first: glibc keeps freed heap pages
// (and CHOLMOD's, hypre's) resident until malloc_trim returns them.
void reset_peak_memory() {
  malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";  // 5 clears VmHWM
}

double peak_memory_mb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // reported in kB
  return 0;
}

Json machine_record() {
  Json machine;
  machine["cpu"] = cpu_model();
  machine["cores"] = std::thread::hardware_concurrency();
  machine["threads"] = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  machine["versions"] = {{"akvf", AKVF_VERSION},
                         {"eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) +
                                       "." + std::to_string(EIGEN_MINOR_VERSION)},
                         {"cholmod", cholmod_version()},
                         {"compiler", __VERSION__}};
  return machine;
}

Json run_record(const OptimizerResult& result, double lower_bound, int vertices, int elements) {
  const IterationSummary& last = result.trace.back();
  int max_flips = 0;
  for (const IterationSummary& row : result.trace) max_flips = std::max(max_flips, row.flips);
  Json record;
  record["status"] = to_string(result.status);
  record["message"] = result.message;
  record["reached"] = result.status == TerminationStatus::kConverged;
  record["iterations"] = last.iteration;
  record["seconds"] = last.seconds;
  record["final_energy"] = last.energy;
  record["lower_bound"] = lower_bound;
  record["grad_norm"] = last.grad_norm;
  record["max_flips"] = max_flips;
  record["vertices"] = vertices;
  record["elements"] = elements;
  record["peak_memory_mb"] = peak_memory_mb();
  return record;
}

Json linear_algebra_record(const PreconditionerStatistics& statistics, const std::string& report) {
  return Json{{"factorizations", statistics.factorizations},
              {"reused_solves", statistics.reused_solves},
              {"cg_solves", statistics.cg_solves},
              {"cg_iterations", statistics.cg_iterations},
              {"symbolic_analyses", statistics.symbolic_analyses},
              {"multigrid_setups", statistics.multigrid_setups},
              {"report", report}};
}

Json cut_record(const DiskMesh& disk, int packing_splits) {
  return {{"charts", disk.num_charts()},
          {"cut_edges", disk.cut_edges},
          {"packing_splits", packing_splits},
          {"genus", disk.chart_genus},
          {"boundary_loops", disk.chart_input_loops}};
}

Json seam_record(const SeamReport& seams, double max_distortion) {
  return {{"added", seams.seams},
          {"seam_length", seams.seam_length},
          {"max_distortion", max_distortion},
          {"chart_distortion", seams.chart_distortion},
          {"bound_met", seams.bound_met},
          {"stop_reason", seams.stop_reason},
          {"overlap_pieces", seams.overlap_pieces},
          {"parted_charts", seams.parted_charts}};
}

Json repair_record(const DiskMesh& disk) {
  const ManifoldRepair& repair = disk.repair;
  const int index_base = disk.mesh.index_base;
  Json opened = Json::array();
  for (const auto& [a, b] : repair.first_opened) opened.push_back({a + index_base, b + index_base});
  Json split = Json::array();
  for (const int v : repair.first_split) split.push_back(v + index_base);
  Json first_set_aside = Json::array();
  for (std::size_t i = 0; i < std::min<std::size_t>(disk.removed_faces.size(), 5); ++i)
    first_set_aside.push_back(disk.removed_faces[i] + index_base);
  Json welded = Json::array();
  for (const int v : disk.welding.first_welded) welded.push_back(v + index_base);
  Json record = {{"welded_vertices", disk.welding.welded}, {"first_welded_vertices", welded},
                 {"opened_edges", repair.opened_edges},    {"split_vertices", repair.split_vertices},
                 {"added_copies", repair.added_copies},    {"first_opened_edges", opened},
                 {"first_split_vertices", split}};
  Json reversed = Json::array();
  for (std::size_t i = 0; i < std::min<std::size_t>(disk.reoriented_faces.size(), 5); ++i) {
    const int f = disk.reoriented_faces[i];
    reversed.push_back((disk.input_face.empty() ? f : disk.input_face[f]) + index_base);
  }
  record["reversed_faces"] = disk.reoriented_faces.size();
  record["first_reversed_faces"] = reversed;
  Json orientation_cuts = Json::array();
  for (std::size_t i = 0; i < std::min<std::size_t>(disk.orientation_cuts.size(), 5); ++i)
    orientation_cuts.push_back(
        {disk.orientation_cuts[i].first + index_base, disk.orientation_cuts[i].second + index_base});
  record["orientation_cut_edges"] = disk.orientation_cuts.size();
  record["first_orientation_cut_edges"] = orientation_cuts;
  record["set_aside_faces"] = disk.removed_faces.size();
  record["first_set_aside_faces"] = first_set_aside;
  return record;
}

Json single_run_summary(const std::string& problem, const std::string& mesh_file, const Json& settings,
                        const Json& record) {
  Json summary;
  summary["problem"] = problem;
  summary["mesh_file"] = mesh_file;
  summary["settings"] = settings;
  summary.update(record);
  summary["machine"] = machine_record();
  return summary;
}

void write_summary(const std::string& path, const Json& summary) {
  write_file_atomically(path, [&](std::ostream& out) { out << summary.dump(2) << '\n'; });
}

}  // namespace akvf
