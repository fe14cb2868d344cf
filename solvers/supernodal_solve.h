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

namespace akvf {

// The supernodal structure of a factor, as CHOLMOD stores it (super, pi, px,
// s), with CHOLMOD's integers (int, or SuiteSparse_long for factors whose
// entries pass 2^31); the values are passed to solve(), as they change with
// each numeric factorization.
template <class Index>
struct SupernodalStructure {
  Index supernodes = 0;
  const Index* first_column = nullptr;   // super: supernode s has columns [first_column[s], first_column[s + 1])
  const Index* pattern_start = nullptr;  // pi: its row indices are pattern[pattern_start[s] .. pattern_start[s + 1])
  const Index* value_start = nullptr;    // px: its column-major block starts at values[value_start[s]]
  const Index* pattern = nullptr;        // s
};

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
  enum Owner : char { kGroup0 = 0, kGroup1 = 1, kTop = 2 };
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
