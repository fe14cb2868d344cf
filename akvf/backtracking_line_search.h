#pragma once
// Backtracking line search of §5.3 (after Smith and Schaefer 2015): start at
// alpha_0 = min(1, 0.8 alpha_max), where alpha_max is the flip-free bound,
// and shrink alpha <- rho alpha until the first Wolfe (Armijo) condition
//   E(x + alpha d) <= E(x) + c1 alpha grad E(x)^T d
// holds. An inverted element makes E infinite, so no accepted step flips.
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
