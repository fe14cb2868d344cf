#pragma once
// L-BFGS through ceres::GradientProblemSolver: the quasi-Newton baseline of
// Smith and Schaefer 2015. Ceres runs its own line search (Wolfe, cubic
// interpolation); an evaluation at a configuration with an inverted element
// is reported to Ceres as failed (E = +infinity), so its line search backs
// off. Our stopping rules (gradient tolerance, time limit) and callbacks run
// from a Ceres iteration callback; the result has the same trace and
// statuses as minimize().
#include "akvf/optimizer.h"

namespace akvf {

struct LbfgsOptions {
  int memory = 20;  // L-BFGS rank (Ceres' max_lbfgs_rank)
};

OptimizerResult minimize_lbfgs(const Objective& objective, Eigen::VectorXd x, const OptimizerOptions& options,
                               const LbfgsOptions& lbfgs = {}, const std::vector<IterationCallback>& callbacks = {});

}  // namespace akvf
