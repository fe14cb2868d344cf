#pragma once
// The supernodal elimination tree of a Cholesky factor in CHOLMOD's layout,
// and its split into two groups of disjoint subtrees (worked on by two cores
// at once) and the supernodes above them (the top). Shared by the
// triangular solves (supernodal_solve.h) and the numeric factorization
// (supernodal_factorization.h), which weigh the supernodes differently.
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

// Who works on a supernode: one of the two groups, or the top.
enum SubtreeOwner : char { kGroup0 = 0, kGroup1 = 1, kTop = 2 };

struct SupernodalTree {
  std::vector<int> column_node;  // the supernode of each column
  std::vector<int> parent;       // of each supernode (larger index), -1 for a root
  std::vector<std::vector<int>> children;
  std::vector<int> roots;
};

template <class Index>
SupernodalTree supernodal_tree(const SupernodalStructure<Index>& s);

// Owner of each supernode: the tree is cut below the top so that the
// estimated time top_weight * (top's work) + (heavier group's work) is
// least (the heaviest subtree is expanded into its children, its root
// joining the top, up to 256 times, and the cut with the least time kept);
// each subtree below the cut goes whole to one group, the heaviest first
// to the lighter group. `work` is per supernode. top_weight is 1 when the
// top runs on one core, less when it is shared between both.
std::vector<char> split_subtrees(const SupernodalTree& tree, const std::vector<double>& work, double top_weight);

}  // namespace akvf
