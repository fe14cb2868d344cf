#include "akvf/internal/seam_cutting.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include "akvf/catalog.h"
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
// A peak with less than this share of the largest peak's excess over 4 is
// left to a later round: it may be the shoulder of the larger one, which
// that one's seam relieves.
constexpr double kPeakShare = 0.5;

// Where the round's seams start: the interior vertices of the charts above
// the bound whose energy (the area-weighted mean of their faces') is above
// it too, at least their interior neighbours' (the peaks of the distortion)
// and at least kPeakShare of the largest peak's excess, most distorted
// first; if there is none, the most distorted interior vertex.
std::vector<int> seam_starts(const ParamSetup& setup, const Eigen::VectorXd& energy,
                             const std::vector<double>& chart_energy, double bound) {
  const TriMesh& mesh = setup.disk.mesh;
  const int nv = mesh.num_vertices();
  const Eigen::VectorXd& weight = setup.objective->weights();
  std::vector<double> sum(nv, 0), area(nv, 0);
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      sum[mesh.F(f, k)] += weight[f] * energy[f];
      area[mesh.F(f, k)] += weight[f];
    }
  std::vector<double> mean(nv);
  for (int v = 0; v < nv; ++v) mean[v] = sum[v] / area[v];
  std::vector<char> interior(nv, 1);
  for (const auto& loop : setup.disk.boundary_loops)
    for (int v : loop) interior[v] = 0;
  std::vector<char> candidate = interior;
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.F(f, k);
      if (chart_energy[setup.disk.face_chart[f]] <= bound) candidate[v] = 0;
      for (int w : {mesh.F(f, (k + 1) % 3), mesh.F(f, (k + 2) % 3)})
        if (interior[w] && mean[w] > mean[v]) candidate[v] = 0;
    }
  std::vector<int> starts;
  int most = -1;
  for (int v = 0; v < nv; ++v) {
    if (candidate[v] && mean[v] > bound) starts.push_back(v);
    if (candidate[v] && (most < 0 || mean[v] > mean[most])) most = v;
  }
  std::stable_sort(starts.begin(), starts.end(), [&](int a, int b) { return mean[a] > mean[b]; });
  if (starts.empty() && most >= 0) starts.push_back(most);
  if (starts.empty()) return starts;
  const double floor = 4 + kPeakShare * (mean[starts.front()] - 4);
  starts.erase(std::find_if(starts.begin(), starts.end(), [&](int v) { return mean[v] < floor; }), starts.end());
  return starts;
}

// Each copy of an input vertex that lies within `fraction` of its smallest
// triangle height of another copy (the two sides of a seam that has not
// opened, or barely) moved into its own
// triangles, so that the seam's sides no longer touch (the boundary barrier
// of global injectivity is infinite where they do): by `fraction` of the
// smallest height of its triangles, along the mean direction to their
// centroids, which flips none of them (a vertex moved by less than a
// triangle's height keeps to its side of the opposite edge).
void part_seam_sides(const TriMesh& mesh, const std::vector<int>& input_vertex, double fraction, Eigen::VectorXd* x) {
  const int nv = static_cast<int>(input_vertex.size());
  std::vector<Eigen::Vector2d> direction(nv, Eigen::Vector2d::Zero());
  std::vector<double> height(nv, std::numeric_limits<double>::infinity());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    Eigen::Vector2d p[3];
    for (int k = 0; k < 3; ++k) p[k] = x->segment<2>(2 * mesh.F(f, k));
    const double twice_area = (p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x();
    const Eigen::Vector2d centroid = (p[0] + p[1] + p[2]) / 3;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.F(f, k);
      direction[v] += centroid - p[k];
      height[v] = std::min(height[v], twice_area / (p[(k + 1) % 3] - p[(k + 2) % 3]).norm());
    }
  }
  // The copies of one input vertex, consecutive in `order`.
  std::vector<int> order(nv);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return input_vertex[a] < input_vertex[b]; });
  std::vector<Eigen::Vector2d> move(nv, Eigen::Vector2d::Zero());
  for (int i = 0, j = 0; i < nv; i = j) {
    for (j = i + 1; j < nv && input_vertex[order[j]] == input_vertex[order[i]];) ++j;
    for (int a = i; a < j; ++a)
      for (int b = i; b < j; ++b) {
        const int v = order[a], w = order[b];
        const double step = fraction * height[v];
        if (v != w && (x->segment<2>(2 * v) - x->segment<2>(2 * w)).norm() < step && direction[v].norm() > 0)
          move[v] = step * direction[v].normalized();
      }
  }
  for (int v = 0; v < nv; ++v) x->segment<2>(2 * v) += move[v];
}

// A round's row as the whole run's: later rounds continue the numbering and
// the clock of the earlier ones (`iterations`, `seconds` so far), and their
// row 0, the previous round's end, is left out (false).
bool shift_row(const IterationSummary& row, int iterations, double seconds, IterationSummary* moved) {
  if (iterations > 0 && row.iteration == 0) return false;
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

// A round that starts warm, from the last round's map (opened along new
// seams, which changes the energy only near them), is where akvf-newton
// would switch to its Newton phase: the curvature, not the flip-free bound,
// sets the step. It starts there, with that phase's settings.
ParamConfig warm(ParamConfig config) {
  if (config.preconditioner != "akvf-newton") return config;
  config.preconditioner = "newton";
  config.preconditioner_settings.newton = config.preconditioner_settings.newton_phase;
  config.preconditioner_settings.newton_filter = config.preconditioner_settings.newton_phase_filter;
  return config;
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
                        const std::vector<IterationCallback>& callbacks) {
  auto setup = std::make_shared<ParamSetup>(start);
  int iterations = 0;
  double seconds = 0;
  std::vector<IterationCallback> round_callbacks;
  for (const IterationCallback& callback : callbacks)
    round_callbacks.push_back(shifted(callback, &iterations, &seconds));
  OptimizerResult all;
  ParamRun run;
  // Each round may take max_iterations; the time limit is for all of them.
  auto optimize = [&](ParamConfig round) {
    round.optimizer.time_limit = std::max(config.optimizer.time_limit - seconds, 1e-9);
    run = optimize_from_start(*setup, round, round_callbacks);
    for (const IterationSummary& row : run.result.trace) {
      IterationSummary moved;
      if (shift_row(row, iterations, seconds, &moved)) all.trace.push_back(moved);
    }
    iterations = all.trace.back().iteration;
    seconds = all.trace.back().seconds;
    all.x = run.result.x;
    all.status = run.result.status;
    all.message = run.result.message;
  };
  SeamReport report;
  // Seams until the bound holds, optimizing after each: flip-free only, or
  // globally injective with the new seam's sides parted first.
  auto add_seams = [&](const ParamConfig& round) {
    double best = std::numeric_limits<double>::infinity();
    int since_best = 0;
    for (;;) {
      if (!is_normal_termination(all.status) || all.status == TerminationStatus::kUserStopped) return;
      const Eigen::VectorXd energy = face_symmetric_dirichlet(*setup, all.x);
      report.chart_distortion =
          chart_means(setup->objective->weights(), setup->disk.face_chart, setup->disk.num_charts(), energy);
      const auto worst = std::max_element(report.chart_distortion.begin(), report.chart_distortion.end());
      report.bound_met = *worst <= config.max_distortion;
      if (report.bound_met) return;
      if (*worst < best) {
        best = *worst;
        since_best = 0;
      } else if (++since_best == kFutileRounds) {
        report.stop_reason =
            std::to_string(kFutileRounds) + " rounds of seams in a row did not lower the largest chart energy";
        return;
      }
      const std::vector<std::vector<int>> paths =
          seam_paths(setup->disk.mesh, seam_starts(*setup, energy, report.chart_distortion, config.max_distortion));
      if (paths.empty()) {
        report.stop_reason = "no interior vertex is left to cut from";
        return;
      }
      report.seams += static_cast<int>(paths.size());
      const std::vector<int> source = open_seams(&setup->disk, paths);
      Eigen::VectorXd x(2 * source.size());
      for (std::size_t v = 0; v < source.size(); ++v) x.segment<2>(2 * v) = all.x.segment<2>(2 * source[v]);
      rebuild_problem(round, setup.get());
      if (round.global_injectivity) part_seam_sides(setup->disk.mesh, setup->disk.input_vertex, 0.1, &x);
      setup->x0 = x;
      optimize(warm(round));
    }
  };
  ParamConfig rough = config;
  rough.seams = false;
  rough.global_injectivity = false;
  rough.optimizer.gradient_tolerance = std::max(config.optimizer.gradient_tolerance, kRoundGradientTolerance);
  optimize(rough);
  setup->warm_start = {};  // its rows open the trace once
  add_seams(rough);
  if (is_normal_termination(all.status) && all.status != TerminationStatus::kUserStopped) {
    // To the requested gradient, as injective as asked. A flip-free map
    // whose boundary does not cross itself is injective (boundary_contact.h)
    // and the run goes on from it; one that crosses starts again from the
    // Tutte map of the opened charts.
    ParamConfig last = config;
    last.seams = false;
    Eigen::VectorXd x0 = all.x;
    if (last.global_injectivity) part_seam_sides(setup->disk.mesh, setup->disk.input_vertex, 0.1, &x0);
    if (last.global_injectivity && setup->boundary_contact->count_crossings(x0) > 0) {
      rebuild_problem(last, setup.get(), true);
    } else {
      setup->x0 = x0;
    }
    optimize(last);
    add_seams(last);
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
  return text + (report.stop_reason.empty() ? std::string() : ": " + report.stop_reason);
}

}  // namespace akvf
