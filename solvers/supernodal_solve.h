#pragma once
// Triangular solves with a supernodal Cholesky factor L (CHOLMOD's layout),
// z = (L L^T)^-1 z, on two cores where the elimination tree allows.
//
// CHOLMOD's own solve calls BLAS dtrsv/dgemv per supernode, and OpenBLAS
// takes a lock and a buffer at each call: with thousands of small supernodes
// that overhead is most of the solve. Here the same arithmetic runs through
// Eigen maps. The supernodal elimination tree is split once, at analysis,
// into two groups of disjoint subtrees of similar work and the rest above
// them (the top): the groups are solved concurrently (forward: groups, then
// top; backward: top, then groups). Group 1 sends its updates of top rows
// through a buffer that is subtracted after both groups finish, so the
// arithmetic, and the result, do not depend on the number of threads.
#include <vector>

#include "solvers/supernodal_tree.h"

namespace akvf {

template <class Index>
class SupernodalSolve {
 public:
  SupernodalSolve() = default;
  // Splits the elimination tree (the structure must outlive this object).
  explicit SupernodalSolve(const SupernodalStructure<Index>& structure);

  // z = (L L^T)^-1 z, with L's values in CHOLMOD's supernodal layout.
  void solve(const double* values, double* z);

  // Share of the factor's entries in the top part (solved on one core).
  double top_share() const { return top_share_; }

 private:
  void forward(const double* values, int group, double* z);
  void backward(const double* values, const std::vector<int>& order, double* z, std::vector<double>* scratch) const;

  SupernodalStructure<Index> s_;
  std::vector<int> group_[2], top_;  // supernodes, in increasing order
  std::vector<char> column_owner_;   // Owner of each column
  std::vector<double> scratch_[2];   // rows below a diagonal block, per group
  std::vector<double> top_updates_;  // group 1's updates of top rows
  double top_share_ = 0;
};

}  // namespace akvf
