#pragma once
// Charts split until their packing covers ParamConfig::min_coverage of the
// UV square (framework/mesh/chart_splitting.h): each round, of the charts
// in order of the area their convex hull leaves empty, the first whose best
// straight cut raises the packed coverage by 1 % over the best so far is
// cut; if none does, the cut that leaves the least hull area empty, up to
// two such cuts past the best packing, which is kept. With --cut seams only
// cuts whose pieces keep the distortion bound count; if several charts fall
// short, the cuts are also made without the bound, seams added where a
// piece is above it, and the seamed atlas cut again (kept if it packs
// tighter). A single chart is split only if its pieces reach min_coverage.
// The map is unchanged but for those seams; docs/design.md, "Cutting closed
// and higher-genus meshes".
#include "akvf/internal/parameterization.h"

namespace akvf {

// After a run with a cut (config.cut): if its packing covers less than
// config.min_coverage, run->seamed becomes the split problem (the final
// one's, its mesh opened along the cuts), run->result.x the map of it, and
// run->packing_splits the number of cuts; the final map's measures and,
// with seams, the per-chart distortion and seam length follow. Seams added
// for the packing continue run->result's trace; callbacks see their rows,
// which leave the trace again if that atlas is not kept.
void split_for_packing(const ParamSetup& setup, const ParamConfig& config,
                       const std::vector<IterationCallback>& callbacks, ParamRun* run);

}  // namespace akvf
