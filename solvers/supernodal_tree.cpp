#include "solvers/supernodal_tree.h"

#include <tbb/task_group.h>

#include <cholmod.h>  // SuiteSparse_long
#include <algorithm>
#include <atomic>
#include <iterator>
#include <memory>
#include <numeric>

namespace akvf {

namespace {

// Assigns `sorted` (subtree work w, heaviest first) to `groups` groups, each
// to the lightest group so far; returns the heaviest group's work and the
// assignment (in the order of `sorted`).
double balance(const std::vector<int>& sorted, const std::vector<double>& w, int groups, std::vector<int>* group) {
  std::vector<double> load(groups, 0.0);
  group->resize(sorted.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const int g = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    (*group)[i] = g;
    load[g] += w[sorted[i]];
  }
  return *std::max_element(load.begin(), load.end());
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

TreeSchedule::TreeSchedule(const SupernodalTree& tree, const std::vector<double>& work, double min_unit_work) {
  const int n_super = static_cast<int>(tree.parent.size());
  if (n_super == 0) return;
  std::vector<double> subtree = work, chain = work;
  for (int node = 0; node < n_super; ++node)  // children have smaller indices
    if (const int p = tree.parent[node]; p >= 0) {
      subtree[p] += subtree[node];
      chain[p] = std::max(chain[p], work[p] + chain[node]);
    }
  double total = 0, longest = 0;
  for (int root : tree.roots) {
    total += subtree[root];
    longest = std::max(longest, chain[root]);
  }
  critical_path_share_ = total > 0 ? longest / total : 0;

  // Parents first. A supernode whose subtree passes the limit is large:
  // large supernodes form chains (a large one joins its parent's chain when
  // it is the parent's only large child: the two could not run at once
  // anyway), and each subtree below them is one unit.
  const double limit = std::max(total / kUnits, min_unit_work);
  std::vector<int> large_children(n_super, 0);
  for (int node = 0; node < n_super; ++node)
    if (tree.parent[node] >= 0 && subtree[node] > limit) ++large_children[tree.parent[node]];
  std::vector<int> unit_of(n_super), unit_root;
  std::vector<char> is_chain;
  for (int node = n_super - 1; node >= 0; --node) {
    const int p = tree.parent[node];
    const bool large = subtree[node] > limit;
    if (p >= 0 && (large ? is_chain[unit_of[p]] && large_children[p] == 1 : !is_chain[unit_of[p]])) {
      unit_of[node] = unit_of[p];
      continue;
    }
    unit_of[node] = static_cast<int>(unit_root.size());
    unit_root.push_back(node);
    is_chain.push_back(large);
  }
  const int n_units = static_cast<int>(unit_root.size());
  unit_start_.assign(n_units + 1, 0);
  for (int node = 0; node < n_super; ++node) ++unit_start_[unit_of[node] + 1];
  std::partial_sum(unit_start_.begin(), unit_start_.end(), unit_start_.begin());
  unit_nodes_.resize(n_super);
  std::vector<int> fill(unit_start_.begin(), unit_start_.end() - 1);
  for (int node = 0; node < n_super; ++node) unit_nodes_[fill[unit_of[node]]++] = node;

  unit_parent_.resize(n_units);
  child_count_.assign(n_units, 0);
  for (int u = 0; u < n_units; ++u) {
    const int p = tree.parent[unit_root[u]];
    unit_parent_[u] = p >= 0 ? unit_of[p] : -1;
    if (p >= 0) ++child_count_[unit_parent_[u]];
  }
  for (int u = 0; u < n_units; ++u)
    if (child_count_[u] == 0) leaf_units_.push_back(u);
}

void TreeSchedule::bottom_up(const std::function<void(int)>& visit) const {
  const int n_units = units();
  if (n_units <= 1) {
    if (n_units == 1) visit(0);
    return;
  }
  // Each unit counts the child units not yet done; the task finishing the
  // last one goes on with the parent.
  const std::unique_ptr<std::atomic<int>[]> waiting(new std::atomic<int>[n_units]);
  for (int u = 0; u < n_units; ++u) waiting[u].store(child_count_[u], std::memory_order_relaxed);
  const auto climb = [&](int u) {
    for (;;) {
      visit(u);
      u = unit_parent_[u];
      if (u < 0 || waiting[u].fetch_sub(1, std::memory_order_acq_rel) != 1) return;
    }
  };
  tbb::task_group group;
  for (int u : leaf_units_) group.run([&climb, u] { climb(u); });
  group.wait();
}

std::vector<int> split_subtrees(const SupernodalTree& tree, const std::vector<double>& work, int groups) {
  const int n_super = static_cast<int>(tree.parent.size());
  std::vector<double> subtree = work;
  for (int node = 0; node < n_super; ++node)  // children have smaller indices
    if (tree.parent[node] >= 0) subtree[tree.parent[node]] += subtree[node];

  // The frontier, heaviest first (ties in the order the subtrees joined it):
  // the heaviest is expanded, and its children, sorted alike, merged in
  // after the subtrees as heavy that were there before them.
  const auto heavier = [&](int a, int b) { return subtree[a] > subtree[b]; };
  std::vector<int> frontier = tree.roots, merged, children;
  std::stable_sort(frontier.begin(), frontier.end(), heavier);
  std::vector<int> best_frontier = frontier, group, best_group;
  double top_work = 0;
  double best_time = balance(frontier, subtree, groups, &best_group);
  for (int step = 0; step < 256 && !frontier.empty(); ++step) {
    const int node = frontier.front();
    top_work += work[node];
    children = tree.children[node];
    std::stable_sort(children.begin(), children.end(), heavier);
    merged.clear();
    std::merge(frontier.begin() + 1, frontier.end(), children.begin(), children.end(), std::back_inserter(merged),
               heavier);
    frontier.swap(merged);
    const double time = top_work + balance(frontier, subtree, groups, &group);
    if (time < best_time) {
      best_time = time;
      best_frontier = frontier;
      best_group = group;
    }
  }

  // A frontier subtree belongs to its group, everything above it to the top.
  std::vector<int> owner(n_super, kTop);
  for (std::size_t i = 0; i < best_frontier.size(); ++i) owner[best_frontier[i]] = best_group[i];
  for (int node = n_super - 1; node >= 0; --node)
    if (owner[node] == kTop && tree.parent[node] >= 0 && owner[tree.parent[node]] != kTop)
      owner[node] = owner[tree.parent[node]];
  return owner;
}

template SupernodalTree supernodal_tree(const SupernodalStructure<int>&);
template SupernodalTree supernodal_tree(const SupernodalStructure<SuiteSparse_long>&);

}  // namespace akvf
