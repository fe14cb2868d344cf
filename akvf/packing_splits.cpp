#include "akvf/internal/packing_splits.h"

#include <algorithm>
#include <numeric>

#include <tbb/parallel_for.h>

#include "akvf/internal/seam_cutting.h"
#include "framework/mesh/chart_layout.h"
#include "framework/mesh/chart_splitting.h"
#include "framework/mesh/plane_geometry.h"
#include "framework/mesh/seam_opening.h"
#include "framework/process/interrupt.h"

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

// The coverage of the charts packed on the coarse grid: the trials compare
// layouts; the outputs' layout, on the fine grid, covers about as much or
// more.
double packed_coverage(const DiskMesh& disk, Eigen::MatrixXd UV, double gutter) {
  pack_charts(disk.mesh.F, disk.face_chart, disk.num_charts(), &UV, true, gutter, PackingGrid::kCoarse);
  return square_coverage(disk.mesh.F, UV);
}

// An atlas cut for the packing: its charts, map and packed coverage (-1:
// not packed).
struct PackingCuts {
  DiskMesh disk;
  Eigen::MatrixXd uv;
  double coverage = -1;
  int splits = 0;
};

// The rounds of cuts from `from` (splits counted on from its own; coverage
// left as it was where no packing is tried): with `bound`, only cuts whose
// pieces keep config.max_distortion (energy: every face's, weight: its
// area) count.
PackingCuts cut_for_packing(PackingCuts from, double gutter, const ParamConfig& config, bool bound,
                            const Eigen::VectorXd& energy, const Eigen::VectorXd& weight) {
  DiskMesh& disk = from.disk;
  Eigen::MatrixXd& UV = from.uv;
  // A least-waste cut frees at most the area its chart's hull leaves empty,
  // so a chart that leaves less than the gain asked of the square
  // (least_waste below) is not tried for one; one chart that leaves less
  // is not even packed.
  const double area = map_area(disk.mesh.F, UV);
  std::vector<double> waste = chart_waste(disk.mesh.F, UV, disk.face_chart, disk.num_charts());
  // In an atlas, a round where no hull's waste gave a cut is tried again
  // with even pieces, largest chart first: convex charts too large or too
  // long for the square beside the others (two equal squares fill half of
  // it) pack closer cut through their middle. One chart is not cut so: its
  // pieces would serve the packing alone.
  const bool atlas = disk.num_charts() > 1;
  if (!atlas && waste[0] < (kLeastGain - 1) * area) return from;
  double coverage = packed_coverage(disk, UV, gutter);
  // The best packing so far; up to kLookAhead cuts past it are made when no
  // cut raises its coverage: a chart wide and tall may need a cut across
  // each before the square shrinks.
  PackingCuts best{disk, UV, coverage, from.splits};
  int splits = from.splits;
  bool even = false;
  while (splits < kMaxSplits && splits - best.splits <= kLookAhead && best.coverage < config.min_coverage &&
         !interrupt_requested()) {
    const int charts = disk.num_charts();
    if (splits > 0) waste = chart_waste(disk.mesh.F, UV, disk.face_chart, charts);
    const std::vector<double> size = even ? chart_areas(disk.mesh.F, UV, disk.face_chart, charts) : waste;
    std::vector<int> order(charts);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return size[a] > size[b]; });
    // The cut that raises the coverage most, if one raises it kLeastGain
    // over the best; else the one that leaves the least hull area empty.
    double gained = 0, freed = 0;
    DiskMesh next_disk;
    Eigen::MatrixXd next_uv;
    const double least_waste = (kLeastGain - 1) * area / best.coverage;
    for (int i = 0; i < std::min(charts, kChartsPerRound) && gained == 0 && (even || waste[order[i]] >= least_waste) &&
                    !interrupt_requested();
         ++i) {
      const int chart = order[i];
      const auto keeps_bound = [&](const ChartSplit& s) {
        if (!bound) return true;
        const std::vector<double> mean = chart_means(weight, s.face_chart, s.num_charts, energy);
        for (int c = 0; c < s.num_charts; ++c)
          if ((c == chart || c >= charts) && mean[c] > config.max_distortion) return false;
        return true;
      };
      // The cuts' packings on every core; compared in order, as one thread would.
      const std::vector<ChartSplit> cuts =
          straight_splits(disk.mesh.F, UV, disk.face_chart, charts, chart, kCutsPerChart, keeps_bound,
                          even ? SplitRank::kEvenPieces : SplitRank::kLeastWaste);
      const int count = static_cast<int>(cuts.size());
      std::vector<DiskMesh> trials(count, disk);
      std::vector<Eigen::MatrixXd> trial_uvs(count);
      std::vector<double> trial_coverages(count);
      tbb::parallel_for(0, count, [&](int t) {
        const std::vector<int> source = split_charts(&trials[t], cuts[t].face_chart, cuts[t].num_charts);
        trial_uvs[t].resize(static_cast<Eigen::Index>(source.size()), 2);
        for (std::size_t v = 0; v < source.size(); ++v) trial_uvs[t].row(v) = UV.row(source[v]);
        trial_coverages[t] = packed_coverage(trials[t], trial_uvs[t], gutter);
      });
      for (int t = 0; t < count; ++t) {
        const ChartSplit& cut = cuts[t];
        const double trial_coverage = trial_coverages[t];
        const bool gains = trial_coverage >= kLeastGain * std::max(best.coverage, gained);
        const bool frees = !even && gained == 0 && waste[chart] - cut.waste > freed;
        if (!gains && !frees) continue;
        if (gains)
          gained = trial_coverage;
        else
          freed = waste[chart] - cut.waste;
        coverage = trial_coverage;
        next_disk = std::move(trials[t]);
        next_uv = std::move(trial_uvs[t]);
      }
    }
    if (gained == 0 && freed == 0) {
      if (even || !atlas) break;
      even = true;
      continue;
    }
    even = false;
    disk = std::move(next_disk);
    UV = std::move(next_uv);
    ++splits;
    if (gained > 0) best = {disk, UV, coverage, splits};
  }
  return best;
}

// The problem `cut` split along `cuts` (made on it), starting at their map.
std::shared_ptr<ParamSetup> split_problem(const ParamSetup& cut, const ParamConfig& config, PackingCuts cuts) {
  auto split_setup = std::make_shared<ParamSetup>(cut);
  split_setup->disk = std::move(cuts.disk);
  rebuild_problem(config, split_setup.get());
  split_setup->x0 = stack_uv(cuts.uv);
  return split_setup;
}

// The run ends split along `cuts`, which were made on `cut` (the problem
// `cuts` are of, every face's symmetric Dirichlet energy `energy`).
void take_cuts(const ParamSetup& cut, const ParamConfig& config, PackingCuts cuts, const Eigen::VectorXd& energy,
               ParamRun* run) {
  run->packing_splits += cuts.splits;
  std::shared_ptr<ParamSetup> split_setup = split_problem(cut, config, std::move(cuts));
  run->result.x = split_setup->x0;
  measure_final_map(*split_setup, run);
  if (config.seams) {
    run->seams.chart_distortion =
        chart_means(cut.objective->weights(), split_setup->disk.face_chart, split_setup->disk.num_charts(), energy);
    run->seams.seam_length = split_setup->disk.cut_length * split_setup->normalization.scale;
  }
  run->seamed = std::move(split_setup);
}

// The cuts of run's final map (`bound`: keeping the distortion bound); its
// faces' symmetric Dirichlet energy in `energy` (with seams).
PackingCuts cuts_of_run(const ParamSetup& setup, const ParamConfig& config, const ParamRun& run, bool bound,
                        Eigen::VectorXd* energy) {
  const ParamSetup& last = final_setup(setup, run);
  *energy = config.seams ? face_symmetric_dirichlet(last, run.result.x) : Eigen::VectorXd();
  return cut_for_packing({last.disk, unstack_uv(run.result.x), -1, 0}, last.gutter, config, bound, *energy,
                         last.objective->weights());
}

// One chart (a disk, or seams that bound the distortion in one) is kept
// whole unless its pieces reach the coverage: a partial gain is not worth
// turning it into an atlas.
bool worth_taking(const PackingCuts& cuts, int charts_before, double min_coverage) {
  return cuts.splits > 0 && (charts_before > 1 || cuts.coverage >= min_coverage);
}

}  // namespace

void split_for_packing(const ParamSetup& setup, const ParamConfig& config,
                       const std::vector<IterationCallback>& callbacks, ParamRun* run) {
  if (stop_on_signal(&run->result) || !config.cut || !(config.min_coverage > 0) || run->result.x.size() == 0) return;
  const ParamSetup& start = final_setup(setup, *run);
  const int charts = start.disk.num_charts();
  Eigen::VectorXd energy;
  const PackingCuts cuts = cuts_of_run(setup, config, *run, config.seams, &energy);
  if (config.seams && charts > 1 && cuts.coverage < config.min_coverage) {
    // The bound may be what stops the cuts: a chart just under it with its
    // distortion in its extremities, which a cut would leave in a piece of
    // their own. The cuts go on without it, seams are added where a piece
    // is above it (run_with_seams, going on from the cut map), the seamed
    // atlas is cut again as above, and kept if it packs tighter. Not for
    // one chart: seams there would serve the packing alone.
    PackingCuts free_cuts = cut_for_packing(cuts, start.gutter, config, false, energy, start.objective->weights());
    if (free_cuts.splits > cuts.splits && free_cuts.coverage >= kLeastGain * cuts.coverage) {
      const int free_splits = free_cuts.splits;
      ParamRun again = run_with_seams(*split_problem(start, config, std::move(free_cuts)), config, callbacks, run);
      if (stop_asked(again.result.status)) {
        // Stopped there: the map before these seams, with the stop reported.
        run->result.status = again.result.status;
        run->result.message = again.result.message;
      } else if (again.seams.bound_met && is_normal_termination(again.result.status)) {
        again.packing_splits = free_splits;
        Eigen::VectorXd again_energy;
        PackingCuts recut = cuts_of_run(*again.seamed, config, again, true, &again_energy);
        if (recut.coverage < 0)
          recut.coverage = packed_coverage(again.seamed->disk, unstack_uv(again.result.x), again.seamed->gutter);
        if (recut.coverage >= kLeastGain * cuts.coverage) {
          const std::shared_ptr<const ParamSetup> seamed = again.seamed;
          if (recut.splits > 0) take_cuts(*seamed, config, std::move(recut), again_energy, &again);
          stop_on_signal(&again.result);
          *run = std::move(again);
          return;
        }
      }
    }
  }
  // A signal during the cuts ends them; those made so far are kept.
  stop_on_signal(&run->result);
  if (worth_taking(cuts, charts, config.min_coverage)) take_cuts(start, config, cuts, energy, run);
}

}  // namespace akvf
