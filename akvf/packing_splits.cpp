#include "akvf/internal/packing_splits.h"

#include <algorithm>
#include <numeric>

#include "akvf/internal/seam_cutting.h"
#include "framework/mesh/chart_layout.h"
#include "framework/mesh/chart_splitting.h"
#include "framework/mesh/plane_geometry.h"
#include "framework/mesh/seam_opening.h"

namespace akvf {

namespace {

// Each round packs the charts once per cut it tries (at most
// kChartsPerRound x kCutsPerChart): the rounds are bounded so that a large
// atlas stays within seconds.
constexpr int kMaxSplits = 32;
// A cut adds seams: it is kept only if the packing then covers 1 % more
// (relative) than the best before.
constexpr double kLeastGain = 1.01;
// The cuts of a chart, least waste first, each round packs to compare.
constexpr int kCutsPerChart = 4;
// The charts each round tries, most wasteful first (until one cut of one
// raises the coverage).
constexpr int kChartsPerRound = 4;
// Cuts made past the best packing when none gains: two, so that a chart
// both wide and tall can be cut across each way before the square shrinks.
constexpr int kLookAhead = 2;

double packed_coverage(const DiskMesh& disk, Eigen::MatrixXd UV, double gutter) {
  pack_charts(disk.mesh.F, disk.face_chart, disk.num_charts(), &UV, true, gutter);
  return square_coverage(disk.mesh.F, UV);
}

}  // namespace

void split_for_packing(const ParamSetup& setup, const ParamConfig& config, ParamRun* run) {
  if (!config.cut || !(config.min_coverage > 0) || run->result.x.size() == 0) return;
  const ParamSetup& start = final_setup(setup, *run);
  DiskMesh disk = start.disk;
  Eigen::MatrixXd UV = unstack_uv(run->result.x);
  // A cut frees at most the area its chart's hull leaves empty, so a chart
  // that leaves less than the gain asked of the square (least_waste below)
  // cannot give it. The square is at least the map's area: if no chart
  // leaves that share of it, no packing is even tried.
  const double area = map_area(disk.mesh.F, UV);
  std::vector<double> waste = chart_waste(disk.mesh.F, UV, disk.face_chart, disk.num_charts());
  if (*std::max_element(waste.begin(), waste.end()) < (kLeastGain - 1) * area) return;
  double coverage = packed_coverage(disk, UV, start.gutter);
  // Faces keep their rows through the cuts: their energies and areas too.
  const Eigen::VectorXd energy = config.seams ? face_symmetric_dirichlet(start, run->result.x) : Eigen::VectorXd();
  const Eigen::VectorXd& weight = start.objective->weights();
  // The best packing so far; up to kLookAhead cuts past it are made when no
  // cut raises its coverage: a chart wide and tall may need a cut across
  // each before the square shrinks.
  DiskMesh best_disk = disk;
  Eigen::MatrixXd best_uv = UV;
  double best_coverage = coverage;
  int splits = 0, best_splits = 0;
  while (splits < kMaxSplits && splits - best_splits <= kLookAhead && best_coverage < config.min_coverage) {
    const int charts = disk.num_charts();
    if (splits > 0) waste = chart_waste(disk.mesh.F, UV, disk.face_chart, charts);
    std::vector<int> order(charts);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return waste[a] > waste[b]; });
    // The cut that raises the coverage most, if one raises it kLeastGain
    // over the best; else the one that leaves the least hull area empty.
    double gained = 0, freed = 0;
    DiskMesh next_disk;
    Eigen::MatrixXd next_uv;
    const double least_waste = (kLeastGain - 1) * area / best_coverage;
    for (int i = 0; i < std::min(charts, kChartsPerRound) && gained == 0 && waste[order[i]] >= least_waste; ++i) {
      const int chart = order[i];
      const auto keeps_bound = [&](const ChartSplit& s) {
        if (!config.seams) return true;
        const std::vector<double> mean = chart_means(weight, s.face_chart, s.num_charts, energy);
        for (int c = 0; c < s.num_charts; ++c)
          if ((c == chart || c >= charts) && mean[c] > config.max_distortion) return false;
        return true;
      };
      for (const ChartSplit& cut :
           straight_splits(disk.mesh.F, UV, disk.face_chart, charts, chart, kCutsPerChart, keeps_bound)) {
        DiskMesh trial = disk;
        const std::vector<int> source = split_charts(&trial, cut.face_chart, cut.num_charts);
        Eigen::MatrixXd trial_uv(static_cast<Eigen::Index>(source.size()), 2);
        for (std::size_t v = 0; v < source.size(); ++v) trial_uv.row(v) = UV.row(source[v]);
        const double trial_coverage = packed_coverage(trial, trial_uv, start.gutter);
        const bool gains = trial_coverage >= kLeastGain * std::max(best_coverage, gained);
        const bool frees = gained == 0 && waste[chart] - cut.waste > freed;
        if (!gains && !frees) continue;
        if (gains) {
          gained = trial_coverage;
          coverage = trial_coverage;
        } else {
          freed = waste[chart] - cut.waste;
          coverage = trial_coverage;
        }
        next_disk = std::move(trial);
        next_uv = std::move(trial_uv);
      }
    }
    if (gained == 0 && freed == 0) break;
    disk = std::move(next_disk);
    UV = std::move(next_uv);
    ++splits;
    if (gained > 0) {
      best_disk = disk;
      best_uv = UV;
      best_coverage = coverage;
      best_splits = splits;
    }
  }
  disk = std::move(best_disk);
  UV = std::move(best_uv);
  coverage = best_coverage;
  splits = best_splits;
  // One chart (a disk, or seams that bound the distortion in one) is kept
  // whole unless its pieces reach the coverage: a partial gain is not worth
  // turning it into an atlas.
  if (splits == 0 || (start.disk.num_charts() == 1 && coverage < config.min_coverage)) return;
  auto split_setup = std::make_shared<ParamSetup>(start);
  split_setup->disk = std::move(disk);
  rebuild_problem(config, split_setup.get());
  split_setup->x0 = stack_uv(UV);
  run->result.x = split_setup->x0;
  measure_final_map(*split_setup, run);
  if (config.seams) {
    run->seams.chart_distortion =
        chart_means(weight, split_setup->disk.face_chart, split_setup->disk.num_charts(), energy);
    run->seams.seam_length = split_setup->disk.cut_length * split_setup->normalization.scale;
  }
  run->packing_splits = splits;
  run->seamed = std::move(split_setup);
}

}  // namespace akvf
