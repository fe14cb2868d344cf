#pragma once
// Numeric supernodal Cholesky factorization A = L L^T on the symbolic
// structure of CHOLMOD's analysis, on any number of threads.
//
// The algorithm is CHOLMOD's left-looking supernodal one (Chen, Davis, Hager
// and Rajamanickam 2008, as in cholmod_super_numeric): for each supernode s
// in order, its block is set to A's columns, every earlier supernode d whose
// rows reach s's columns subtracts its update L_d(rows >= s, :) L_d(rows in
// s, :)^T (into a buffer, scattered into s's block), then the diagonal
// block is factored and the rows below it solved (dense_block_kernels.h:
// CHOLMOD's BLAS and LAPACK calls, dsyrk, dgemm, dpotrf and dtrsm, for large
// blocks, plain loops for small ones). CHOLMOD 3 runs that loop on one core.
// Here a supernode needs only its descendants, so disjoint subtrees are
// factored at once, scheduled as a task graph over the elimination tree
// (supernodal_tree.h, TreeSchedule) on the calling arena's threads.
// Each supernode's updates are applied in CHOLMOD's order (the last linked
// first: every link is keyed by when CHOLMOD's one loop would have made it),
// and each block operation's arithmetic depends on its shape only, so the
// factor has the same bits whatever the number of threads and their timing
// (tests/test_sparse_cholesky.cpp). The small blocks' loops round
// differently from BLAS, so the factor agrees with CHOLMOD's to rounding
// (tested: the solution within 1e-10 of CHOLMOD's). Splitting one
// supernode's work between the cores (an update's rows, or the rows of its
// triangular solve) changed the shapes of the BLAS calls and gained nothing
// on two cores; on many cores the top separators' blocks bound the speed-up
// (TreeSchedule::critical_path_share, docs/performance.md).
#include <tbb/enumerable_thread_specific.h>

#include <atomic>
#include <vector>

#include "solvers/supernodal_tree.h"

namespace akvf {

// The lower triangle of A in compressed columns (int indices), in the
// factor's (permuted) numbering; entry p's value is value[source[p]] (A's
// values in another order: no copy of them is made).
struct LowerTriangle {
  int n = 0;
  const int* column_start = nullptr;
  const int* row = nullptr;
  const double* value = nullptr;
  const int* source = nullptr;
};

template <class Index>
class SupernodalFactorization {
 public:
  // Schedules the elimination tree (the structure must outlive this object).
  explicit SupernodalFactorization(const SupernodalStructure<Index>& structure);

  // Fills values (structure.value_start[supernodes] entries, CHOLMOD's
  // supernodal layout) with L. Throws NotPositiveDefinite (naming the
  // column) when a pivot is not positive.
  void factorize(const LowerTriangle& A, double* values);

  // The flops on the elimination tree's longest chain over all flops.
  double critical_path_share() const { return schedule_.critical_path_share(); }

 private:
  // An update of the supernode being built by supernode `node`: its rows
  // [first, first + rows) of the pattern, the first `inside` of them in the
  // target's columns.
  struct Descendant {
    int node;
    Index first;
    int inside, rows;
  };
  // When a supernode was linked to the list of the next supernode it
  // updates: while supernode `node` was worked on, as its `order`-th link
  // (its descendants in their order, then itself).
  struct Key {
    int node, order;
    bool operator>(const Key& other) const { return node != other.node ? node > other.node : order > other.order; }
  };
  // What one thread needs: the local row of each row of the supernode being
  // built, its descendants, the update buffer.
  struct Workspace {
    std::vector<int> local_row;  // by global row; valid for the rows of the supernode being built
    std::vector<Descendant> descendants;
    std::vector<int> relative;  // the update's rows as local rows of the target
    std::vector<double> update;
  };

  // Assembles s, applies its descendants' updates and factors it, unless
  // another thread met a non-positive pivot: then the factorization costs
  // the work up to its first bad pivot (projected Newton's exact Hessian
  // far from the minimum), not a whole factorization.
  void factor_supernode(int s, const LowerTriangle& A, double* values);
  void assemble(int s, const LowerTriangle& A, const std::vector<int>& local_row, double* values) const;
  // s's descendants, in CHOLMOD's order.
  void collect(int s, Workspace* w) const;
  void apply_update(const Descendant& d, int s, Workspace* w, double* values) const;
  // s's diagonal block into L11 L11^T, the rows below into L21 = A21 L11^-T.
  void factor_block(int s, double* values) const;
  // After s's descendants were applied: each is linked to the supernode it updates next.
  void advance(int s, const Workspace& w);
  // Pushes d on the list of the supernode holding row pattern[position]
  // (lock-free: threads in disjoint subtrees may push on one list).
  void link(int d, Index position, Key key);

  SupernodalStructure<Index> s_;
  std::vector<int> column_node_;
  TreeSchedule schedule_;
  // Per factorization: each supernode's next row to update (an index into
  // the pattern), and the linked lists of supernodes waiting to update each
  // supernode, with the keys of their links.
  std::vector<Index> next_row_;
  std::vector<std::atomic<int>> head_;
  std::vector<int> next_;
  std::vector<Key> key_;
  tbb::enumerable_thread_specific<Workspace> workspaces_;
  std::atomic<bool> stopped_{false};  // a thread met a non-positive pivot in this factorization
};

}  // namespace akvf
