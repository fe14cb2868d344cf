#pragma once
// The supernodal elimination tree of a Cholesky factor in CHOLMOD's layout,
// and two ways to share it between threads: a task schedule for the numeric
// factorization (supernodal_factorization.h) and a split into groups of
// subtrees for the triangular solves (supernodal_solve.h).
//
// A supernode of the factorization needs only its descendants; disjoint
// subtrees are independent. TreeSchedule groups the tree into units, each
// worked on by one thread in increasing order (children have smaller
// indices): the supernodes whose subtrees hold more than a share of the
// work form chains, and each subtree below them is one unit. Units run as
// TBB tasks as soon as the units they need are done, on the threads of the
// calling arena (`--threads`, ThreadLimit).
#include <functional>
#include <vector>

namespace akvf {

// The supernodal structure of a factor, as CHOLMOD stores it (super, pi, px,
// s), with CHOLMOD's integers (int, or SuiteSparse_long for factors whose
// entries pass 2^31); the values are passed separately, as they change with
// each numeric factorization.
template <class Index>
struct SupernodalStructure {
  Index supernodes = 0;
  const Index* first_column = nullptr;   // super: supernode s has columns [first_column[s], first_column[s + 1])
  const Index* pattern_start = nullptr;  // pi: its row indices are pattern[pattern_start[s] .. pattern_start[s + 1])
  const Index* value_start = nullptr;    // px: its column-major block starts at values[value_start[s]]
  const Index* pattern = nullptr;        // s: rows of each supernode, its own columns first, then increasing

  int columns() const { return supernodes > 0 ? static_cast<int>(first_column[supernodes]) : 0; }
};

// A supernode's dense block: rows x columns, its columns starting at
// first_column. (Supernode sizes fit an int whatever the index width.)
struct BlockShape {
  int first_column, columns, rows;
};

template <class Index>
BlockShape block_shape(const SupernodalStructure<Index>& s, int node) {
  return {static_cast<int>(s.first_column[node]), static_cast<int>(s.first_column[node + 1] - s.first_column[node]),
          static_cast<int>(s.pattern_start[node + 1] - s.pattern_start[node])};
}

struct SupernodalTree {
  std::vector<int> column_node;            // the supernode of each column
  std::vector<int> parent;                 // of each supernode (larger index), -1 for a root
  std::vector<std::vector<int>> children;  // in increasing order
  std::vector<int> roots;
};

template <class Index>
SupernodalTree supernodal_tree(const SupernodalStructure<Index>& s);

class TreeSchedule {
 public:
  TreeSchedule() = default;
  // `work` is per supernode. A subtree of at most max(total / kUnits,
  // min_unit_work) is one unit: about kUnits subtrees balance the load on
  // dozens of threads, and min_unit_work keeps a task's work well above
  // its cost of a few microseconds. The units depend on the tree and the
  // work only, not on the number of threads.
  TreeSchedule(const SupernodalTree& tree, const std::vector<double>& work, double min_unit_work);

  // Calls visit(unit) for every unit, each after its child units (its
  // supernodes' descendants). Exceptions stop the units not yet started and
  // are rethrown.
  void bottom_up(const std::function<void(int)>& visit) const;

  int units() const { return static_cast<int>(unit_parent_.size()); }
  // Unit u's supernodes, in increasing order (its root, the largest, last).
  const int* nodes_begin(int u) const { return unit_nodes_.data() + unit_start_[u]; }
  const int* nodes_end(int u) const { return unit_nodes_.data() + unit_start_[u + 1]; }

  // The work on the tree's longest chain over the whole work: the share no
  // number of threads can shorten (speed-up at most its inverse).
  double critical_path_share() const { return critical_path_share_; }

  static constexpr int kUnits = 128;

 private:
  std::vector<int> unit_start_, unit_nodes_;  // unit u: unit_nodes_[unit_start_[u] .. unit_start_[u + 1])
  std::vector<int> unit_parent_;              // -1 for a root unit
  std::vector<int> child_count_;              // child units of each unit
  std::vector<int> leaf_units_;
  double critical_path_share_ = 0;
};

// Owner of each supernode for the triangular solves: one of `groups` groups
// of disjoint subtrees, or the top (kTop) above them. The tree is cut below
// the top so that the estimated time (top's work) + (heaviest group's work)
// is least (the heaviest subtree is expanded into its children, its root
// joining the top, up to 256 times, and the cut with the least time kept);
// each subtree below the cut goes whole to one group, the heaviest first to
// the lightest group. `work` is per supernode.
constexpr int kTop = -1;
std::vector<int> split_subtrees(const SupernodalTree& tree, const std::vector<double>& work, int groups);

}  // namespace akvf
