// akvf_speed: time to a solution per method, in units of one numeric
// Cholesky factorization of the rest Killing operator of the same mesh,
// measured in the same run (the unit cancels the machine's speed).
//
//   2D: every disk mesh in DATA/tri with at least 10 000 faces (--min-faces;
//       --refine-to N first subdivides the smaller ones to N), with one
//       energy (--energy, symmetric Dirichlet by default); seconds of
//       optimizer time to the run's own stop (the default gradient tolerance:
//       1e-3, 1e-4 for arap),
//       and to within 1e-6 relative of the lowest energy any method reaches
//       or 1e-12 (the "to 1e-6" columns: the speed comparison across
//       methods; within()). Each run goes on to 1e-3 of its own tolerance,
//       since near a minimum the energy's gap falls as the gradient norm
//       squared, so that a method whose own stop lies above the target can
//       still reach it; its own stop is its first iterate below its
//       tolerance (the iterates do not depend on the tolerance).
//   3D: the SLIM cube at both sizes (cube_4k.obj, cube_40k.obj, slim-cube
//       preset) and four lifted tet meshes (octopus-low.mesh, bar.tet and
//       the two cubes: the bottom 5 % of the vertices by height fixed, the
//       top 5 % lifted by 20 % of the height, w = 1e5); seconds to reach
//       within 1e-4 relative of the lowest energy any method reaches.
//
// The unit: K (Eq. 5, area-scaled) at the initial map in 2D, K (Eq. 9-10) +
// 1e-4 I at the rest shape in 3D, analyzed once, then the median of 5
// numeric factorizations (in 2D before each round of --repeat, each run in
// its round's unit, and the medians of those shown): ours (all threads,
// what the runs use), and
// CHOLMOD alone (its default analysis, simplicial below its supernodal
// switch, its one-core factorization), the unit issue 14's targets were
// first set in.
// With --energy arap, where CGAL was found at configure time, the method
// `cgal` (in the default list) runs CGAL's ARAP parameterizer on the same
// normalized mesh (experiments/bench/cgal_arap.h): its own start and stopping
// rule, its time from its own clock, its final map's energy evaluated as
// ours, and its inverted triangles counted in its start and every iterate. Its
// final energy counts as the lowest only when that map is flip-free.
//
// Prints a Markdown table.
//
// Usage: akvf_speed [--data DIR] [--methods default,akvf,newton,slim[,cgal]] [--energy NAME] [--repeat N]
//                   [--min-faces N] [--refine-to N] [--only 2d|3d]
// A method M+sweep=X is M with --local-sweep X (0: none), 2D only.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "akvf/akvf.h"
#include "akvf/internal/options.h"
#include "akvf/internal/parameterization.h"
#include "akvf/internal/slim_cube.h"
#include "akvf/mesh_io.h"
#include "akvf/rest_geometry.h"
#include "akvf/tet_mesh_io.h"
#include "akvf/threads.h"
#include "framework/mesh/mesh_subdivision.h"
#include "preconditioners/killing_operator_2d.h"
#include "preconditioners/killing_operator_3d.h"
#include "solvers/sparse_cholesky.h"
#ifdef AKVF_SPEED_WITH_CGAL
#include "experiments/bench/cgal_arap.h"
#endif

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

struct Unit {
  double ours = 0, cholmod = 0;  // seconds
};

// The unit's matrix, analyzed once by each factorization; measure() times
// 5 numeric factorizations by each and gives their medians. In 2D it is
// measured before each round of runs, and each run is divided by its
// round's unit, so that a stretch of a slower machine slows both.
class UnitClock {
 public:
  UnitClock(const Eigen::SparseMatrix<double>& upper, int block_size) : upper_(upper) {
    cholmod_.use_cholmod_alone(true);
    for (akvf::SparseCholesky* cholesky : {&ours_, &cholmod_}) cholesky->analyze(upper_, block_size);
  }
  Unit measure() {
    const akvf::ThreadLimit threads(0);
    return {median_seconds(&ours_), median_seconds(&cholmod_)};
  }

 private:
  double median_seconds(akvf::SparseCholesky* cholesky) {
    std::vector<double> seconds;
    for (int i = 0; i < 5; ++i) {
      const auto start = Clock::now();
      cholesky->factorize(upper_);
      seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    return median(seconds);
  }
  Eigen::SparseMatrix<double> upper_;
  akvf::SparseCholesky ours_, cholmod_;
};

std::unique_ptr<UnitClock> unit_clock_2d(const akvf::TriMesh& mesh) {
  const akvf::ThreadLimit threads(0);
  const akvf::ParamSetup setup = akvf::prepare_parameterization(mesh, "mesh", akvf::ParamConfig{});
  const akvf::DistortionObjective2D& objective = *setup.objective;
  akvf::ElementMatrix2D K(objective.elements(), objective.num_vertices());
  akvf::assemble_killing_operator_2d(objective.elements(), setup.x0, objective.rest().area, true, &K);
  K.add_to_diagonal(1e-8 * K.mean_diagonal());
  return std::make_unique<UnitClock>(K.upper(), 2);
}

Unit unit_3d(const akvf::TetMesh& mesh) {
  akvf::ElementMatrix3D K(mesh.T, mesh.num_vertices());
  akvf::assemble_killing_operator_3d(mesh.T, akvf::stack_rows(mesh.V), &K);
  K.add_to_diagonal(1e-4);
  return UnitClock(K.upper(), 3).measure();
}

struct Row {
  std::string method;
  int iterations = 0;
  double seconds = 0;
  std::string status;
  double energy = 0;
  // 2D: iterations and seconds to within 1e-6 of the lowest energy (-1: never).
  int gap_iterations = -1;
  double gap_seconds = -1;
  // seconds and gap_seconds in units (the medians of the runs' own, in 2D).
  Unit units{}, gap_units{};
};

double median_of(const std::vector<Unit>& units, double Unit::*part) {
  std::vector<double> values;
  for (const Unit& unit : units) values.push_back(unit.*part);
  return median(values);
}

// Seconds in units of `unit`.
Unit in_units(double seconds, const Unit& unit) { return {seconds / unit.ours, seconds / unit.cholmod}; }

// The median of each run's seconds in its round's units.
Unit median_units(const std::vector<double>& seconds, const std::vector<Unit>& round_units) {
  std::vector<double> ours, cholmod;
  for (std::size_t i = 0; i < seconds.size(); ++i) {
    const Unit run = in_units(seconds[i], round_units[i]);
    ours.push_back(run.ours);
    cholmod.push_back(run.cholmod);
  }
  return {median(ours), median(cholmod)};
}

// Where a run that went on to a tighter tolerance would have stopped at
// `tolerance`: its first row below it (not counting the warm start's), or its
// end when no row is.
Row own_stop(const std::string& method, const akvf::ParameterizeResult& result, double tolerance) {
  for (const auto& row : result.trace)
    if (!row.warm_start && row.grad_norm < tolerance)
      return {method, row.iteration, row.seconds, "converged", row.energy};
  return {method, result.iterations(), result.statistics.seconds, akvf::to_string(result.status), result.energy()};
}

// `energy` is within `gap` relative of `lowest`, or within 1e-12: near an
// isometry every energy here grows as the square of the singular values'
// distance from 1, so 1e-12 is a map within about 1e-6 of the lowest one in
// stretch. It decides only where the lowest energy is that of a near
// isometry (ARAP on a flat strip: 1e-14), where a relative gap would ask for
// the last bits of whichever run went deepest.
bool within(double energy, double lowest, double gap) { return energy - lowest <= gap * std::abs(lowest) + 1e-12; }

// The first trace row within `gap` of `lowest` (within()), or nullptr. The
// symmetric Dirichlet warm start's rows (another energy) do not count.
const akvf::IterationSummary* first_within(const std::vector<akvf::IterationSummary>& trace, double lowest,
                                           double gap) {
  for (const auto& row : trace)
    if (!row.warm_start && within(row.energy, lowest, gap)) return &row;
  return nullptr;
}

void print_rows(const std::string& mesh, long elements, const Unit& unit, const std::vector<Row>& rows, bool with_gap) {
  double best = std::numeric_limits<double>::infinity(), best_gap = best;
  for (const Row& r : rows) {
    if (r.status == "converged" || r.status == "reached") best = std::min(best, r.seconds);
    if (r.gap_seconds >= 0) best_gap = std::min(best_gap, r.gap_seconds);
  }
  for (const Row& r : rows) {
    char line[600];
    int n = std::snprintf(line, sizeof line,
                          "| %s | %ld | %.1f | %.1f | %s | %d | %.3f | %.1f | %.1f | %.2f | %s | %.10g |", mesh.c_str(),
                          elements, 1e3 * unit.ours, 1e3 * unit.cholmod, r.method.c_str(), r.iterations, r.seconds,
                          r.units.ours, r.units.cholmod, r.seconds / best, r.status.c_str(), r.energy);
    if (with_gap) {
      if (r.gap_seconds >= 0)
        std::snprintf(line + n, sizeof line - n, " %d | %.3f | %.1f | %.2f |", r.gap_iterations, r.gap_seconds,
                      r.gap_units.cholmod, r.gap_seconds / best_gap);
      else
        std::snprintf(line + n, sizeof line - n, " - | - | - | - |");
    }
    std::cout << line << std::endl;
  }
}

std::string method_name(const std::string& method, const std::string& default_name) {
  return method == "default" ? default_name : method;
}

// "METHOD+sweep=X": METHOD with --local-sweep X (0: none); plain METHOD
// takes the option's default.
struct MethodVariant {
  std::string method;
  std::optional<double> local_sweep;
};
MethodVariant method_variant(const std::string& spec) {
  const std::string marker = "+sweep=";
  const std::size_t at = spec.find(marker);
  if (at == std::string::npos) return {spec, std::nullopt};
  return {spec.substr(0, at), std::stod(spec.substr(at + marker.size()))};
}

#ifdef AKVF_SPEED_WITH_CGAL
// CGAL's ARAP parameterizer on the mesh the ARAP runs optimize (cut, scaled
// to unit area), its map scored by our ARAP energy; lowers `lowest` when its
// final map is flip-free.
Row cgal_arap_row(const akvf::TriMesh& mesh, double* lowest) {
  akvf::ParamConfig config;
  config.energy = "arap";
  config.global_injectivity = false;
  const akvf::ParamSetup setup = akvf::prepare_parameterization(mesh, "mesh", config);
  akvf::TriMesh rest = setup.disk.mesh;
  akvf::normalize_to_unit_area(&rest);
  const akvf::bench::CgalArapRun run = akvf::bench::run_cgal_arap(rest.V, rest.F);
  Row row{"cgal (own start and stop)", run.iterations, run.seconds, "", std::numeric_limits<double>::quiet_NaN()};
  if (run.uv.size() == 0) {
    row.status = "failed: " + run.error;
    return row;
  }
  Eigen::VectorXd x(2 * run.uv.rows());
  for (int i = 0; i < run.uv.rows(); ++i) x.segment<2>(2 * i) = run.uv.row(i).transpose();
  row.energy = setup.objective->value(x);
  const int inverted = setup.objective->count_inverted(x);
  row.status = "inverted: start " + std::to_string(run.initial_inverted) + ", iterates at most " +
               std::to_string(run.max_iterate_inverted) + ", final " + std::to_string(inverted) +
               (run.post_processed ? " (after CGAL's post-processing)" : "") +
               (run.error.empty() ? "" : "; CGAL's error: " + run.error);
  if (inverted == 0 && std::isfinite(row.energy)) {
    *lowest = std::min(*lowest, row.energy);
    row.gap_iterations = run.iterations;  // kept if it is within 1e-6 of the lowest
    row.gap_seconds = run.seconds;
  }
  return row;
}
#endif

// The midpoint subdivisions (each triangle into four) that bring `faces`
// to at least `refine_to` (0: none).
int refinement_rounds(long long faces, int refine_to) {
  int rounds = 0;
  while (faces > 0 && faces < refine_to) {
    faces *= 4;
    ++rounds;
  }
  return rounds;
}

void run_2d(const std::filesystem::path& data, const std::vector<std::string>& methods, const std::string& energy,
            int repeat, int min_faces, int refine_to) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(data / "tri")) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::cout << "Energy: " << energy << "\n\n"
            << "| mesh | faces | unit (ms) | CHOLMOD unit (ms) | method | iterations | seconds | units | CHOLMOD units "
               "| / best | status | energy | iterations to 1e-6 | seconds to 1e-6 | CHOLMOD units to 1e-6 | / best |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& file : files) {
    akvf::TriMesh mesh;
    try {
      mesh = akvf::read_triangle_mesh(file.string());
    } catch (const akvf::Error&) {
      continue;
    }
    std::string label = file.filename().string();
    if (const int rounds = refinement_rounds(mesh.num_faces(), refine_to); rounds > 0) {
      mesh = akvf::subdivide_midpoint(mesh, rounds);
      label += " x" + std::to_string(1 << (2 * rounds));
    }
    if (mesh.num_faces() < min_faces) continue;
    std::unique_ptr<UnitClock> unit_clock;
    try {
      unit_clock = unit_clock_2d(mesh);
    } catch (const akvf::Error& e) {
      std::cerr << label << ": skipped (" << e.what() << ")\n";
      continue;
    }
    std::vector<Row> rows;
    std::vector<std::string> ours;  // the methods of this library, in the order given
    double lowest = std::numeric_limits<double>::infinity();
    std::vector<Row> peers;
    for (const std::string& method : methods) {
      if (method != "cgal") {
        ours.push_back(method);
        continue;
      }
#ifdef AKVF_SPEED_WITH_CGAL
      peers.push_back(cgal_arap_row(mesh, &lowest));
#endif
    }
    // The repeats go round the methods (one run of each, then the next
    // round), so that a slow stretch of the machine falls on all of them.
    std::vector<std::vector<std::vector<akvf::IterationSummary>>> traces(ours.size());  // per method, per repeat
    std::vector<std::vector<double>> run_seconds(ours.size());
    std::vector<Row> stops(ours.size());
    std::vector<Unit> round_units;
    for (int i = 0; i < repeat; ++i) {
      round_units.push_back(unit_clock->measure());
      for (std::size_t m = 0; m < ours.size(); ++m) {
        akvf::ParameterizeOptions options;
        options.energy = energy;
        const MethodVariant variant = method_variant(ours[m]);
        options.preconditioner = method_name(variant.method, options.preconditioner);
        options.local_sweep = variant.local_sweep;
        // The flip-free problem the peers (TinyAD, libigl's SLIM) solve; the
        // cost of global injectivity is measured in docs/design.md.
        options.injectivity = akvf::Injectivity::kLocal;
        const double tolerance = akvf::param_config(options).optimizer.gradient_tolerance;
        options.grad_tol = 1e-3 * tolerance;
        const akvf::ParameterizeResult result = akvf::parameterize(mesh.V, mesh.F, options);
        const std::string name =
            variant.method == "default"
                ? "default (" + akvf::ParameterizeOptions{}.preconditioner + ")" + ours[m].substr(variant.method.size())
                : ours[m];
        stops[m] = own_stop(name, result, tolerance);
        run_seconds[m].push_back(stops[m].seconds);
        for (const auto& row : result.trace)
          if (!row.warm_start) lowest = std::min(lowest, row.energy);
        traces[m].push_back(result.trace);
      }
    }
    const Unit unit{median_of(round_units, &Unit::ours), median_of(round_units, &Unit::cholmod)};
    for (std::size_t m = 0; m < ours.size(); ++m) {
      rows.push_back(stops[m]);
      rows.back().seconds = median(run_seconds[m]);
      rows.back().units = median_units(run_seconds[m], round_units);
    }
    for (std::size_t m = 0; m < rows.size(); ++m) {
      std::vector<double> seconds;
      for (const auto& trace : traces[m])
        if (const akvf::IterationSummary* row = first_within(trace, lowest, 1e-6)) {
          seconds.push_back(row->seconds);
          rows[m].gap_iterations = row->iteration;
        }
      if (seconds.size() == traces[m].size()) {
        rows[m].gap_seconds = median(seconds);
        rows[m].gap_units = median_units(seconds, round_units);
      }
    }
    for (Row& peer : peers) {
      if (!within(peer.energy, lowest, 1e-6)) peer.gap_iterations = -1, peer.gap_seconds = -1;
      peer.units = in_units(peer.seconds, unit);
      peer.gap_units = in_units(peer.gap_seconds, unit);
      rows.push_back(peer);
    }
    print_rows(label, mesh.num_faces(), unit, rows, true);
  }
}

// Bottom 5 % of the vertices by height fixed, top 5 % lifted by 20 % of the height.
akvf::PositionConstraints lifted(const akvf::TetMesh& mesh) {
  std::vector<int> order(mesh.num_vertices());
  for (int v = 0; v < mesh.num_vertices(); ++v) order[v] = v;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return mesh.V(a, 2) < mesh.V(b, 2); });
  const int count = std::max(1, mesh.num_vertices() / 20);
  const double height = mesh.V.col(2).maxCoeff() - mesh.V.col(2).minCoeff();
  akvf::PositionConstraints constraints;
  constraints.targets.resize(2 * count, 3);
  for (int i = 0; i < count; ++i) {
    const int low = order[i], high = order[mesh.num_vertices() - 1 - i];
    constraints.vertices.push_back(low);
    constraints.targets.row(2 * i) = mesh.V.row(low);
    constraints.vertices.push_back(high);
    constraints.targets.row(2 * i + 1) = mesh.V.row(high) + Eigen::RowVector3d(0, 0, 0.2 * height);
  }
  return constraints;
}

void run_3d(const std::filesystem::path& data, const std::vector<std::string>& methods, int repeat) {
  struct Case {
    std::string file, label;
    bool cube;
  };
  const std::vector<Case> cases = {
      {"cube_4k.obj", "cube_4k (slim-cube)", true}, {"octopus-low.mesh", "octopus-low (lifted)", false},
      {"bar.tet", "bar (lifted)", false},           {"cube_40k.obj", "cube_40k (slim-cube)", true},
      {"cube_4k.obj", "cube_4k (lifted)", false},   {"cube_40k.obj", "cube_40k (lifted)", false}};
  std::cout << "\n| tet mesh | tets | unit (ms) | CHOLMOD unit (ms) | method | iterations to 1e-4 | seconds | units | "
               "CHOLMOD units | / best | status | energy |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Case& c : cases) {
    const std::filesystem::path path = data / "tet" / c.file;
    if (!std::filesystem::exists(path)) continue;
    const akvf::TetMesh mesh = akvf::read_tet_mesh(path.string());
    const akvf::PositionConstraints constraints = c.cube ? akvf::slim_cube_constraints(mesh) : lifted(mesh);
    // The unit at the rest shape scaled to volume 1, as the run sees it.
    akvf::TetMesh unit_mesh = mesh;
    const double volume_scale = 1.0 / std::cbrt(akvf::rest_tets(mesh).total_volume);
    unit_mesh.V *= volume_scale;
    const Unit unit = unit_3d(unit_mesh);
    const auto run = [&](const std::string& method) {
      akvf::DeformOptions options;
      options.preconditioner = method_name(method, options.preconditioner);
      options.max_iters = 200;
      return akvf::deform(mesh.V, mesh.T, constraints, options);
    };
    // The repeats go round the methods, as in 2D; every run counts for the
    // lowest energy any reaches.
    std::vector<std::vector<akvf::DeformResult>> results(methods.size());
    double lowest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < repeat; ++i)
      for (std::size_t m = 0; m < methods.size(); ++m) {
        results[m].push_back(run(methods[m]));
        for (const auto& row : results[m].back().trace) lowest = std::min(lowest, row.energy);
      }
    std::vector<Row> rows;
    for (std::size_t m = 0; m < methods.size(); ++m) {
      Row row;
      row.method = methods[m] == "default" ? "default (" + akvf::DeformOptions{}.preconditioner + ")" : methods[m];
      row.status = "not reached";
      row.iterations = results[m].front().iterations();
      row.seconds = results[m].front().statistics.seconds;
      row.energy = results[m].front().energy();
      std::vector<double> seconds;
      for (const akvf::DeformResult& r : results[m])
        if (const akvf::IterationSummary* trace_row = first_within(r.trace, lowest, 1e-4)) {
          seconds.push_back(trace_row->seconds);
          row.iterations = trace_row->iteration;
          row.status = "reached";
          row.energy = trace_row->energy;
        }
      if (!seconds.empty()) row.seconds = median(seconds);
      row.units = in_units(row.seconds, unit);
      rows.push_back(row);
    }
    print_rows(c.label, mesh.num_tets(), unit, rows, false);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path data = std::getenv("AKVF_DATA_DIR") ? std::getenv("AKVF_DATA_DIR") : "../shared/meshes";
  std::vector<std::string> methods = {"default", "akvf", "newton", "slim"};
  bool methods_given = false;
  int repeat = 1, min_faces = 10000, refine_to = 0;
  std::string only, energy = akvf::ParameterizeOptions{}.energy;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "akvf_speed: " << arg << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "--data") {
      data = value();
    } else if (arg == "--methods") {
      methods.clear();
      methods_given = true;
      std::stringstream list(value());
      for (std::string m; std::getline(list, m, ',');) methods.push_back(m);
    } else if (arg == "--energy") {
      energy = value();
    } else if (arg == "--repeat") {
      repeat = std::max(1, std::atoi(value().c_str()));
    } else if (arg == "--min-faces") {
      min_faces = std::atoi(value().c_str());
    } else if (arg == "--refine-to") {
      refine_to = std::atoi(value().c_str());
    } else if (arg == "--only") {
      only = value();
    } else {
      std::cerr << "usage: akvf_speed [--data DIR] [--methods default,akvf,newton,slim[,cgal]] [--energy NAME] "
                   "[--repeat N] [--min-faces N] [--refine-to N] [--only 2d|3d]\n"
                   "  --energy NAME  the 2D runs' energy (default symmetric-dirichlet; `akvf list` names them)\n"
                   "  --min-faces N  the 2D meshes of at least N faces (default 10000)\n"
                   "  --refine-to N  2D meshes of fewer faces midpoint-subdivided (each triangle into four,\n"
                   "                 the surface unchanged) until they have N, before --min-faces (default 0)\n"
                   "  --repeat N     N runs of each method, taken in turn, and their median time (default 1)\n"
                   "  cgal           CGAL's ARAP parameterizer, 2D with --energy arap only; in the default list\n"
                   "                 then, where this build found CGAL\n"
                   "  M+sweep=X      method M with akvf param --local-sweep X (0: none; plain M: auto), 2D only\n";
      return arg == "--help" || arg == "-h" ? 0 : 2;
    }
  }
  if (!akvf::energies_2d().contains(energy)) {
    std::cerr << "akvf_speed: unknown energy '" << energy << "' (`akvf list` names them)\n";
    return 2;
  }
  const bool has_cgal =
#ifdef AKVF_SPEED_WITH_CGAL
      true;
#else
      false;
#endif
  if (!methods_given && energy == "arap" && has_cgal) methods.push_back("cgal");
  if (std::find(methods.begin(), methods.end(), "cgal") != methods.end()) {
    if (!has_cgal) {
      std::cerr << "akvf_speed: this build has no CGAL (install libcgal-dev: bash scripts/setup.sh, then rebuild)\n";
      return 2;
    }
    if (energy != "arap") {
      std::cerr << "akvf_speed: the method cgal runs CGAL's ARAP parameterizer; use it with --energy arap\n";
      return 2;
    }
  }
  if (!std::filesystem::is_directory(data / "tri")) {
    std::cerr << "akvf_speed: meshes not found in " << data.string() << " (set AKVF_DATA_DIR or --data)\n";
    return 2;
  }
  try {
    if (only != "3d") run_2d(data, methods, energy, repeat, min_faces, refine_to);
    std::vector<std::string> methods_3d;  // CGAL's peer and the sweeps are 2D only
    std::copy_if(methods.begin(), methods.end(), std::back_inserter(methods_3d),
                 [](const std::string& m) { return m != "cgal" && !method_variant(m).local_sweep; });
    if (only != "2d") run_3d(data, methods_3d, repeat);
  } catch (const akvf::Error& e) {
    std::cerr << "akvf_speed: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
