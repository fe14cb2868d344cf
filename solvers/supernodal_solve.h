#pragma once
// Triangular solves with a supernodal Cholesky factor L (CHOLMOD's layout),
// z = (L L^T)^-1 z, on any number of threads.
//
// CHOLMOD's own solve calls BLAS dtrsv/dgemv per supernode, and OpenBLAS
// takes a lock and a buffer at each call: with thousands of small supernodes
// that overhead is most of the solve. Here each supernode is swept column
// by column (one contiguous run per column through the diagonal triangle
// and the rows below, supernodal_solve.cpp). The supernodal elimination tree is split into as many groups
// of disjoint subtrees of similar work as the calling arena has slots (at
// least two; a global thread limit runs them on fewer threads), and the
// rest above them (the top, solved on one thread). The groups are solved
// concurrently (forward: groups, then top; backward: top, then groups),
// each group's backward pass on the thread that did its forward pass where
// TBB can (its affinity partitioner), so that a factor that fits in the
// caches is read from them the second time (a task graph like the
// factorization's loses that: docs/notes/2026-11-26-performance.md). Group 0 writes its updates
// of top rows into z, the others into buffers of their own, subtracted in
// group order after all groups finish: the result has the same bits for a
// given arena size (one slot as two), and agrees to rounding across sizes.
#include <tbb/partitioner.h>

#include <memory>
#include <vector>

#include "solvers/supernodal_block_solve.h"  // SingleEntry
#include "solvers/supernodal_tree.h"

namespace akvf {

template <class Index>
class SupernodalSolve {
 public:
  SupernodalSolve() = default;
  // Keeps the structure (which must outlive this object); the tree is split
  // at the first solve, and again when the number of threads changes.
  explicit SupernodalSolve(const SupernodalStructure<Index>& structure);

  // z = (L L^T)^-1 z, with L's values in CHOLMOD's supernodal layout, as
  // doubles or as SingleEntry (supernodal_block_solve.h); z and the sums in
  // double.
  template <class Value>
  void solve(const Value* values, double* z);

  // Share of the factor's entries in the top part (solved on one thread)
  // with `groups` groups.
  double top_share(int groups);

 private:
  void split(int groups);
  // L y = z over a group's supernodes (kTop: the top's).
  template <class Value>
  void forward(const Value* values, int group, double* z);
  // L^T x = y over a group's supernodes (kTop: the top's), last first.
  template <class Value>
  void backward(const Value* values, int group, double* z);
  const std::vector<int>& members(int group) const { return group == kTop ? top_ : groups_[group]; }

  SupernodalStructure<Index> s_;
  SupernodalTree tree_;
  std::vector<double> work_;              // per supernode: the entries of its block
  std::vector<std::vector<int>> groups_;  // supernodes, in increasing order
  std::vector<int> top_;
  std::vector<int> column_top_;                          // index of a top column among the top's columns, or -1
  std::vector<int> top_columns_;                         // the top's columns, in increasing order
  std::vector<std::vector<double>> top_updates_;         // per group but the first, its updates of the top's columns
  std::vector<std::vector<double>> scratch_;             // a supernode's rows, per group (last: the top)
  std::unique_ptr<tbb::affinity_partitioner> affinity_;  // per split
  double top_share_ = 0;
};

}  // namespace akvf
