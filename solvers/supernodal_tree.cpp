#include "solvers/supernodal_tree.h"

#include <cholmod.h>  // SuiteSparse_long

#include <algorithm>
#include <numeric>

namespace akvf {

namespace {

// Splits `roots` (subtree work w) into two groups, heaviest first into the
// lighter group; returns the heavier group's work and the assignment.
double balance(const std::vector<int>& roots, const std::vector<double>& w, std::vector<char>* group) {
  std::vector<int> order(roots.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return w[roots[a]] > w[roots[b]]; });
  double load[2] = {0, 0};
  group->assign(roots.size(), 0);
  for (int i : order) {
    const int g = load[1] < load[0] ? 1 : 0;
    (*group)[i] = static_cast<char>(g);
    load[g] += w[roots[i]];
  }
  return std::max(load[0], load[1]);
}

}  // namespace

template <class Index>
SupernodalTree supernodal_tree(const SupernodalStructure<Index>& s) {
  const int n_super = static_cast<int>(s.supernodes);
  SupernodalTree tree;
  tree.column_node.resize(s.columns());
  for (int node = 0; node < n_super; ++node)
    for (Index j = s.first_column[node]; j < s.first_column[node + 1]; ++j) tree.column_node[j] = node;
  tree.parent.assign(n_super, -1);
  tree.children.resize(n_super);
  for (int node = 0; node < n_super; ++node) {
    const BlockShape b = block_shape(s, node);
    if (b.rows > b.columns) {
      // The first row below the diagonal block is in the parent.
      tree.parent[node] = tree.column_node[static_cast<std::size_t>(s.pattern[s.pattern_start[node] + b.columns])];
      tree.children[tree.parent[node]].push_back(node);
    } else {
      tree.roots.push_back(node);
    }
  }
  return tree;
}

std::vector<char> split_subtrees(const SupernodalTree& tree, const std::vector<double>& work, double top_weight) {
  const int n_super = static_cast<int>(tree.parent.size());
  std::vector<double> subtree = work;
  for (int node = 0; node < n_super; ++node)  // children have smaller indices
    if (tree.parent[node] >= 0) subtree[tree.parent[node]] += subtree[node];

  std::vector<int> frontier = tree.roots, best_frontier = tree.roots;
  std::vector<char> group, best_group;
  double top_work = 0;
  double best_time = balance(frontier, subtree, &best_group);
  for (int step = 0; step < 256 && !frontier.empty(); ++step) {
    const auto heaviest =
        std::max_element(frontier.begin(), frontier.end(), [&](int a, int b) { return subtree[a] < subtree[b]; });
    const int node = *heaviest;
    frontier.erase(heaviest);
    top_work += work[node];
    frontier.insert(frontier.end(), tree.children[node].begin(), tree.children[node].end());
    const double time = top_weight * top_work + balance(frontier, subtree, &group);
    if (time < best_time) {
      best_time = time;
      best_frontier = frontier;
      best_group = group;
    }
  }

  // A frontier subtree belongs to its group, everything above it to the top.
  std::vector<char> owner(n_super, kTop);
  for (std::size_t i = 0; i < best_frontier.size(); ++i) owner[best_frontier[i]] = best_group[i];
  for (int node = n_super - 1; node >= 0; --node)
    if (owner[node] == kTop && tree.parent[node] >= 0 && owner[tree.parent[node]] != kTop)
      owner[node] = owner[tree.parent[node]];
  return owner;
}

template SupernodalTree supernodal_tree(const SupernodalStructure<int>&);
template SupernodalTree supernodal_tree(const SupernodalStructure<SuiteSparse_long>&);

}  // namespace akvf
