#pragma once
// Bisection on the weak Wolfe conditions, as in SLIM's code: with alpha in a
// bracket [lo, hi] (hi = 0.8 alpha_max, the flip-free bound),
//   Armijo fails (or an element inverts)  -> hi = alpha,
//   curvature grad E(x + alpha d)^T d < c2 grad E(x)^T d fails -> lo = alpha,
// and alpha moves to the bracket's midpoint (or doubles while hi is
// unbounded), until both hold. If the evaluations run out after some step
// satisfied Armijo, that step is taken; otherwise the search fails.
#include "akvf/line_search.h"

namespace akvf {

class WolfeBisectionLineSearch final : public LineSearch {
 public:
  explicit WolfeBisectionLineSearch(LineSearchSettings settings = {}, double c2 = 0.9);
  std::string name() const override { return "wolfe-bisection"; }

 private:
  LineSearchSummary do_search(const LineSearchInput& input) const override;
  LineSearchSettings settings_;
  double c2_;
};

}  // namespace akvf
