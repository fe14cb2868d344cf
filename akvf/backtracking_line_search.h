#pragma once
// Backtracking line search of §5.3 (after Smith and Schaefer 2015): start at
// alpha_0 = min(1, 0.8 alpha_max), where alpha_max is the flip-free bound,
// and shrink alpha <- rho alpha until the first Wolfe (Armijo) condition
//   E(x + alpha d) <= E(x) + c1 alpha grad E(x)^T d
// holds. An inverted element makes E infinite, so no accepted step flips.
// When alpha_0 is the unit step, each failed trial is followed by one at
// the same alpha along the path that follows the elements' turns
// (Objective::rotation_following_term), taken if the straight segment to it
// is flip-free and it meets the condition (LineSearchSummary::turn).
#include "akvf/line_search.h"

namespace akvf {

class BacktrackingLineSearch final : public LineSearch {
 public:
  explicit BacktrackingLineSearch(LineSearchSettings settings = {});
  std::string name() const override { return "backtracking"; }

 private:
  LineSearchSummary do_search(const LineSearchInput& input) const override;
  LineSearchSettings settings_;
};

}  // namespace akvf
