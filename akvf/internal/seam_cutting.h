#pragma once
// `--cut seams`: seams added until the distortion is bounded. From the first
// cut's converged map, while a chart's symmetric Dirichlet energy exceeds
// the bound, the chart is opened along the shortest path from its most
// distorted interior vertex (the area-weighted mean energy of its faces) to
// its boundary, and the map is re-optimized from the previous one (both
// sides of the new seam start where the path was). The rounds are flip-free
// only (a seam opens with its two sides at distance 0, where the boundary
// barrier of global injectivity is infinite); with global injectivity asked
// for, a final map whose boundary crosses itself is optimized once more from
// the Tutte map of the opened charts.
#include <string>
#include <vector>

#include "akvf/internal/parameterization.h"

namespace akvf {

ParamRun run_with_seams(const ParamSetup& setup, const ParamConfig& config,
                        const std::vector<IterationCallback>& callbacks);

// What the seams did, in words: "12 seams added; seams 3.21 sqrt(area) long
// in all; symmetric Dirichlet at most 4.2 in every chart (largest 4.187)".
std::string seam_description(const SeamReport& report, double max_distortion);

}  // namespace akvf
