#include "akvf/internal/seam_cutting.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "akvf/catalog.h"
#include "framework/mesh/overlap_free_pieces.h"
#include "framework/mesh/seam_opening.h"

namespace akvf {

namespace {

constexpr const char* kBoundedEnergy = "symmetric-dirichlet";
// Seams stop when this many in a row did not lower the largest chart
// energy: more would lengthen the seams without bounding the distortion.
constexpr int kFutileRounds = 10;
// The rounds that place seams only need to show where the distortion
// peaks, not the converged map.
constexpr double kRoundGradientTolerance = 1e-2;
// A peak with less than this share of the largest interior peak's excess
// over 4 is left to a later round: it may be the shoulder of the larger
// one, which that one's seam relieves.
constexpr double kPeakShare = 0.5;
// A seam's sides are parted by this share of their triangles' smallest
// height before a globally injective run: apart, yet far from flipping.
constexpr double kPartingShare = 0.1;

// A vertex's energy: the area-weighted mean of its faces'.
std::vector<double> vertex_means(const ParamSetup& setup, const Eigen::VectorXd& energy) {
  const TriMesh& mesh = setup.disk.mesh;
  const Eigen::VectorXd& weight = setup.objective->weights();
  std::vector<double> sum(mesh.num_vertices(), 0), area(mesh.num_vertices(), 0);
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      sum[mesh.F(f, k)] += weight[f] * energy[f];
      area[mesh.F(f, k)] += weight[f];
    }
  for (int v = 0; v < mesh.num_vertices(); ++v) sum[v] /= area[v];
  return sum;
}

// Where the round's seams start: in each chart above the bound, its
// vertices whose energy (the area-weighted mean of their faces') is above
// the bound too, at least all their neighbours' (the peaks of the
// distortion) and at least kPeakShare of the chart's largest interior
// peak's excess (a peak can only be the shoulder of one in its own chart),
// or, if there is none, of its largest peak on the boundary, or, if there is
// none either, its most distorted interior vertex; most distorted first. A
// peak on the boundary counts if it has an interior neighbour to cut toward
// (a seam's tip is such a peak, where the distortion the seam has not
// relieved concentrates): were boundary vertices left out, the interior
// vertex beside each would count as a peak below them, and every round
// would add one-edge seams all along the boundary. They are not the share's
// measure while an interior peak is above the bound: a tip's energy grows
// as the mesh is refined (a crack tip's energy density grows as 1/r toward
// it), and measured against it the interior peaks would wait while the
// tips grow one edge a round.
std::vector<int> seam_starts(const ParamSetup& setup, const std::vector<double>& mean,
                             const std::vector<double>& chart_energy, double bound) {
  const TriMesh& mesh = setup.disk.mesh;
  const int nv = mesh.num_vertices();
  std::vector<char> interior(nv, 1);
  for (const auto& loop : setup.disk.boundary_loops)
    for (int v : loop) interior[v] = 0;
  std::vector<char> candidate = interior;
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      for (int j = 1; j < 3; ++j)
        if (interior[mesh.F(f, (k + j) % 3)]) candidate[mesh.F(f, k)] = 1;
  std::vector<int> chart_of(nv, 0);
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.F(f, k);
      chart_of[v] = setup.disk.face_chart[f];
      if (chart_energy[setup.disk.face_chart[f]] <= bound) candidate[v] = 0;
      for (int w : {mesh.F(f, (k + 1) % 3), mesh.F(f, (k + 2) % 3)})
        if (mean[w] > mean[v]) candidate[v] = 0;
    }
  // Per chart above the bound: its largest interior peak and its largest
  // boundary peak above the bound, and its most distorted interior vertex.
  const std::size_t num_charts = chart_energy.size();
  std::vector<int> interior_peak(num_charts, -1), boundary_peak(num_charts, -1), most(num_charts, -1);
  auto raise = [&](int* largest, int v) {
    if (*largest < 0 || mean[v] > mean[*largest]) *largest = v;
  };
  for (int v = 0; v < nv; ++v) {
    const int c = chart_of[v];
    if (chart_energy[c] <= bound) continue;
    if (interior[v]) raise(&most[c], v);
    if (candidate[v] && mean[v] > bound) raise(interior[v] ? &interior_peak[c] : &boundary_peak[c], v);
  }
  std::vector<int> starts;
  for (int v = 0; v < nv; ++v) {
    const int c = chart_of[v];
    const int p = interior_peak[c] >= 0 ? interior_peak[c] : boundary_peak[c];
    if (p < 0 ? v == most[c] : candidate[v] && mean[v] >= 4 + kPeakShare * (mean[p] - 4)) starts.push_back(v);
  }
  std::stable_sort(starts.begin(), starts.end(), [&](int a, int b) { return mean[a] > mean[b]; });
  return starts;
}

// A round's row as the whole run's: later rounds continue the numbering and
// the clock of the earlier ones (`iterations`, `seconds` so far), and their
// row 0, the previous round's end, is left out (false) unless the round
// starts elsewhere (`restart`).
bool shift_row(const IterationSummary& row, int iterations, double seconds, IterationSummary* moved,
               bool restart = false) {
  if (iterations > 0 && row.iteration == 0 && !restart) return false;
  *moved = row;
  moved->iteration += iterations;
  moved->seconds += seconds;
  return true;
}

IterationCallback shifted(const IterationCallback& callback, const int* iterations, const double* seconds) {
  return [=](const IterationSummary& row, const Eigen::VectorXd& x) {
    IterationSummary moved;
    return shift_row(row, *iterations, *seconds, &moved) ? callback(moved, x) : CallbackAction::kContinue;
  };
}

// The next run starts at x, the last map on the opened mesh: as it is when
// the run is only flip-free (returns true); else with the seams' sides
// parted, if the boundary then does not cross itself (true: a flip-free map
// whose boundary does not cross itself is injective, boundary_contact.h),
// or from the Tutte map of the opened charts (false).
bool start_at(const ParamConfig& round, Eigen::VectorXd x, ParamSetup* setup) {
  if (round.global_injectivity) {
    part_seam_sides(setup->disk, kPartingShare, &x);
    if (setup->boundary_contact->count_crossings(x) > 0) {
      rebuild_problem(round, setup, true);
      return false;
    }
  }
  setup->x0 = std::move(x);
  return true;
}

}  // namespace

Eigen::VectorXd face_symmetric_dirichlet(const ParamSetup& setup, const Eigen::VectorXd& x) {
  const DistortionObjective2D& objective = *setup.objective;
  if (objective.density().name() == kBoundedEnergy) return objective.face_distortion(x);
  const DistortionObjective2D sd(objective.elements(), objective.rest(), energies_2d().create(kBoundedEnergy, {}),
                                 objective.num_vertices());
  return sd.face_distortion(x);
}

std::vector<double> chart_means(const Eigen::VectorXd& weight, const std::vector<int>& face_chart, int num_charts,
                                const Eigen::VectorXd& energy) {
  std::vector<double> sum(num_charts, 0), area(num_charts, 0);
  for (int f = 0; f < energy.size(); ++f) {
    sum[face_chart[f]] += weight[f] * energy[f];
    area[face_chart[f]] += weight[f];
  }
  for (int c = 0; c < num_charts; ++c) sum[c] /= area[c];
  return sum;
}

ParamRun run_with_seams(const ParamSetup& start, const ParamConfig& config,
                        const std::vector<IterationCallback>& callbacks, const ParamRun* earlier) {
  auto setup = std::make_shared<ParamSetup>(start);
  OptimizerResult all;
  SeamReport report;
  if (earlier) {
    all.trace = earlier->result.trace;
    report.seams = earlier->seams.seams;
    report.overlap_pieces = earlier->seams.overlap_pieces;
    report.parted_charts = earlier->seams.parted_charts;
  }
  int iterations = all.trace.empty() ? 0 : all.trace.back().iteration;
  double seconds = all.trace.empty() ? 0 : all.trace.back().seconds;
  const int first_iteration = iterations;
  std::vector<IterationCallback> round_callbacks;
  for (const IterationCallback& callback : callbacks)
    round_callbacks.push_back(shifted(callback, &iterations, &seconds));
  ParamRun run;
  // Each round may take max_iterations; the time limit is for all of them.
  // `restart`: from a map other than the last round's end, whose row 0 the
  // trace then keeps.
  auto optimize = [&](ParamConfig round, bool near_minimum = false, bool restart = false) {
    round.optimizer.time_limit = std::max(config.optimizer.time_limit - seconds, 1e-9);
    run = optimize_from_start(*setup, round, round_callbacks, near_minimum);
    for (const IterationSummary& row : run.result.trace) {
      IterationSummary moved;
      if (shift_row(row, iterations, seconds, &moved, restart)) all.trace.push_back(moved);
    }
    iterations = all.trace.back().iteration;
    seconds = all.trace.back().seconds;
    all.x = run.result.x;
    all.status = run.result.status;
    all.message = run.result.message;
  };
  // Each chart's energy into the report; returns every face's.
  auto measure_charts = [&] {
    Eigen::VectorXd energy = face_symmetric_dirichlet(*setup, all.x);
    report.chart_distortion =
        chart_means(setup->objective->weights(), setup->disk.face_chart, setup->disk.num_charts(), energy);
    report.bound_met =
        *std::max_element(report.chart_distortion.begin(), report.chart_distortion.end()) <= config.max_distortion;
    return energy;
  };
  auto running = [&] { return !stop_on_signal(&all) && is_normal_termination(all.status); };
  // The run goes on from the map `from` on the mesh just opened, whose
  // vertex v copies source[v] of the mesh before.
  auto go_on = [&](const ParamConfig& round, const std::vector<int>& source, const Eigen::VectorXd& from) {
    Eigen::VectorXd x(2 * source.size());
    for (std::size_t v = 0; v < source.size(); ++v) x.segment<2>(2 * v) = from.segment<2>(2 * source[v]);
    rebuild_problem(round, setup.get());
    // The last round's map, opened along new seams, changes the energy
    // only near them: near the minimum.
    optimize(round, start_at(round, x, setup.get()));
  };
  // Seams until the bound holds, optimizing after each: flip-free only, or
  // globally injective with the new seam's sides parted first.
  auto add_seams = [&](const ParamConfig& round, int iteration_limit) {
    double best = std::numeric_limits<double>::infinity();
    int since_best = 0;
    while (running()) {
      const Eigen::VectorXd energy = measure_charts();
      if (report.bound_met) return;
      const double worst = *std::max_element(report.chart_distortion.begin(), report.chart_distortion.end());
      if (worst < best) {
        best = worst;
        since_best = 0;
      } else if (++since_best == kFutileRounds) {
        report.stop_reason =
            std::to_string(kFutileRounds) + " rounds of seams in a row did not lower the largest chart energy";
        return;
      }
      if (iterations >= iteration_limit) {
        report.stop_reason = "the globally injective rounds took as many iterations as the flip-free ones";
        return;
      }
      const std::vector<double> mean = vertex_means(*setup, energy);
      const std::vector<std::vector<int>> paths =
          seam_paths(setup->disk.mesh, seam_starts(*setup, mean, report.chart_distortion, config.max_distortion), mean,
                     config.max_distortion);
      if (paths.empty()) {
        report.stop_reason = "no vertex is left to cut from";
        return;
      }
      report.seams += static_cast<int>(paths.size());
      go_on(round, open_seams(&setup->disk, paths), all.x);
    }
  };
  // The charts still above the bound parted in two through their most
  // distorted vertex, until every chart meets it: a single triangle, where
  // parting ends, maps isometrically.
  auto add_reason = [&](const std::string& reason) {
    report.stop_reason += (report.stop_reason.empty() ? "" : "; ") + reason;
  };
  auto part_charts = [&](const ParamConfig& round) {
    double best = std::numeric_limits<double>::infinity();
    int since_best = 0;
    while (running()) {
      const Eigen::VectorXd energy = measure_charts();
      if (report.bound_met) {
        report.stop_reason.clear();  // the seams' reason, the bound now met
        return;
      }
      const double worst = *std::max_element(report.chart_distortion.begin(), report.chart_distortion.end());
      if (worst < best) {
        best = worst;
        since_best = 0;
      } else if (++since_best == kFutileRounds) {
        add_reason(std::to_string(kFutileRounds) +
                   " rounds of parting in a row did not lower the largest chart energy");
        return;
      }
      const std::vector<double> mean = vertex_means(*setup, energy);
      std::vector<int> through(setup->disk.num_charts(), -1);
      for (int f = 0; f < setup->disk.mesh.num_faces(); ++f) {
        const int c = setup->disk.face_chart[f];
        for (int k = 0; k < 3 && report.chart_distortion[c] > config.max_distortion; ++k) {
          const int v = setup->disk.mesh.F(f, k);
          if (through[c] < 0 || mean[v] > mean[through[c]]) through[c] = v;
        }
      }
      const Eigen::VectorXd from = all.x;
      int parted = 0;
      const std::vector<int> source = split_through(&setup->disk, through, &parted);
      if (parted == 0) {
        add_reason("no chart above it can be parted");
        return;
      }
      report.parted_charts += parted;
      go_on(round, source, from);
    }
  };
  ParamConfig rough = config;
  rough.seams = false;
  rough.global_injectivity = false;
  rough.optimizer.gradient_tolerance = std::max(config.optimizer.gradient_tolerance, kRoundGradientTolerance);
  optimize(rough);
  setup->warm_start = {};  // its rows open the trace once
  add_seams(rough, std::numeric_limits<int>::max());
  // The flip-free end, kept where it met the bound for the pieces below.
  const int iterations_flip_free = iterations - first_iteration;
  const SeamReport flip_free_report = report;
  std::optional<ParamSetup> flip_free;
  if (config.global_injectivity && report.bound_met) flip_free = *setup;
  const Eigen::VectorXd flip_free_x = all.x;
  if (running()) {
    // To the requested gradient, as injective as asked.
    ParamConfig last = config;
    last.seams = false;
    start_at(last, all.x, setup.get());
    optimize(last);
    // Where the flip-free map met the bound, the globally injective seam
    // rounds get as many iterations as the flip-free ones took: more means
    // the boundary barrier, not the distortion, is what the seams fight,
    // and the pieces below end sooner.
    add_seams(last, flip_free ? iterations + iterations_flip_free : std::numeric_limits<int>::max());
    if (running() && !report.bound_met && flip_free) {
      // The flip-free map met the bound, but no globally injective map of
      // its charts was found that does (the barrier holds apart the sides
      // of seams the flip-free map left touching). Taken flip-free to the
      // gradient asked, it is kept if it still meets the bound and its
      // boundary crosses itself nowhere: then it is injective as it is
      // (start_at).
      *setup = *flip_free;
      report = flip_free_report;
      ParamConfig polish = last;
      polish.global_injectivity = false;
      setup->x0 = flip_free_x;
      optimize(polish, true, true);
      measure_charts();
      if (running() && !(report.bound_met && setup->boundary_contact->count_crossings(all.x) == 0)) {
        // Else its charts are cut where the flip-free map lies over
        // itself, and each piece goes on from it.
        *setup = *flip_free;
        report = flip_free_report;
        std::vector<int> pieces;
        const int count = overlap_free_pieces(setup->disk.mesh.F, unstack_uv(flip_free_x), setup->disk.face_chart,
                                              setup->disk.num_charts(), &pieces);
        report.overlap_pieces = count - setup->disk.num_charts();
        go_on(last, split_charts(&setup->disk, pieces, count), flip_free_x);
        add_seams(last, std::numeric_limits<int>::max());
      }
    }
    part_charts(last);
  }
  report.seam_length = setup->disk.cut_length * setup->normalization.scale;
  run.result = all;
  run.seams = report;
  measure_final_map(*setup, &run);
  run.seamed = setup;
  return run;
}

std::string seam_description(const SeamReport& report, double max_distortion) {
  const double largest = report.chart_distortion.empty()
                             ? 0
                             : *std::max_element(report.chart_distortion.begin(), report.chart_distortion.end());
  const bool one = report.chart_distortion.size() == 1;
  char text[200];
  std::snprintf(text, sizeof text,
                "%d %s added, %.3g sqrt(area) of seams in all; symmetric Dirichlet %s %.7g %s (%s%.4g)", report.seams,
                report.seams == 1 ? "seam" : "seams", report.seam_length, report.bound_met ? "at most" : "above",
                max_distortion,
                one                ? "in the chart"
                : report.bound_met ? "in every chart"
                                   : "in a chart",
                one ? "" : "largest ", largest);
  std::string pieces;
  if (report.overlap_pieces > 0)
    pieces += "; " + std::to_string(report.overlap_pieces) + " charts added where the flip-free map lay over itself";
  if (report.parted_charts > 0)
    pieces += "; " + std::to_string(report.parted_charts) + " charts parted in two to meet the bound";
  return text + pieces + (report.stop_reason.empty() ? std::string() : ": " + report.stop_reason);
}

}  // namespace akvf
