#pragma once
// Backtracking line search of §5.3 (after Smith and Schaefer 2015): start at
// alpha_0 = min(1, 0.8 alpha_max), where alpha_max is the flip-free bound,
// and shrink alpha <- rho alpha until the first Wolfe (Armijo) condition
//   E(x + alpha d) <= E(x) + c1 alpha grad E(x)^T d
// holds.
#include "framework/line_search.h"

namespace akvf {

struct BacktrackingOptions {
  double c1 = 1e-5;                // sufficient-decrease constant
  double rho = 0.9;                // shrink factor per rejected step
  double max_step_fraction = 0.8;  // alpha_0 <= fraction * alpha_max
  double max_initial_step = 1.0;   // alpha_0 <= this
  int max_evaluations = 300;       // rho^300 ~ 2e-14: below that the step is noise
};

class BacktrackingLineSearch final : public LineSearch {
 public:
  explicit BacktrackingLineSearch(BacktrackingOptions options = {});
  std::string name() const override { return "backtracking"; }

 private:
  LineSearchSummary do_search(const LineSearchInput& input) const override;
  BacktrackingOptions options_;
};

}  // namespace akvf
