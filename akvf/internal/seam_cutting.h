#pragma once
// `--cut seams`: seams added until every chart's symmetric Dirichlet energy
// is at most ParamConfig::max_distortion. Rounds of flip-free runs, each
// opening the charts from the peaks of the distortion to their boundary
// (framework/mesh/seam_opening.h) and starting from the previous map, then
// a run to the requested gradient, globally injective if asked (from the
// Tutte map of the opened charts if the flip-free map crosses itself);
// docs/design.md, "Seams that bound the distortion".
#include <string>
#include <vector>

#include "akvf/internal/parameterization.h"

namespace akvf {

// With `earlier`, the run goes on from it: its trace continued (numbering
// and clock), its seams counted, its time counted against the time limit.
ParamRun run_with_seams(const ParamSetup& setup, const ParamConfig& config,
                        const std::vector<IterationCallback>& callbacks, const ParamRun* earlier = nullptr);

// The symmetric Dirichlet energy of each face of setup's mesh at x.
Eigen::VectorXd face_symmetric_dirichlet(const ParamSetup& setup, const Eigen::VectorXd& x);

// Per chart of face_chart (num_charts of them), the mean of the faces'
// `energy` weighted by `weight` (their areas).
std::vector<double> chart_means(const Eigen::VectorXd& weight, const std::vector<int>& face_chart, int num_charts,
                                const Eigen::VectorXd& energy);

// What the seams did, in words: "102 seams added, 4.45 sqrt(area) of seams in
// all; symmetric Dirichlet at most 4.2 in every chart (largest 4.189)".
std::string seam_description(const SeamReport& report, double max_distortion);

}  // namespace akvf
