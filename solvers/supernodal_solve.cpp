#include "solvers/supernodal_solve.h"

#include <tbb/parallel_invoke.h>

#include <Eigen/Core>
#include <algorithm>
#include <cholmod.h>  // SuiteSparse_long
#include <numeric>

namespace akvf {

namespace {

using Block = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>>;

struct BlockShape {
  int first_column, columns, rows;
};

// Supernode sizes fit an int whatever the index width (a supernode's block
// has rows x columns entries, far fewer than 2^31).
template <class Index>
BlockShape shape(const SupernodalStructure<Index>& s, int node) {
  return {static_cast<int>(s.first_column[node]), static_cast<int>(s.first_column[node + 1] - s.first_column[node]),
          static_cast<int>(s.pattern_start[node + 1] - s.pattern_start[node])};
}

// Splits `roots` (subtree work w) into two groups, longest first into the
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
SupernodalSolve<Index>::SupernodalSolve(const SupernodalStructure<Index>& structure) : s_(structure) {
  const int n_super = static_cast<int>(s_.supernodes);
  const int n = n_super > 0 ? static_cast<int>(s_.first_column[n_super]) : 0;
  std::vector<int> column_node(n);
  for (int node = 0; node < n_super; ++node)
    for (Index j = s_.first_column[node]; j < s_.first_column[node + 1]; ++j) column_node[j] = node;

  // The supernodal elimination tree (parents have larger indices), the work
  // of each supernode (entries of its block) and of each subtree.
  std::vector<int> parent(n_super, -1);
  std::vector<double> work(n_super), subtree(n_super);
  std::vector<std::vector<int>> children(n_super);
  std::vector<int> roots;
  for (int node = 0; node < n_super; ++node) {
    const BlockShape b = shape(s_, node);
    work[node] = 0.5 * b.columns * (b.columns + 1) + double(b.rows - b.columns) * b.columns;
    subtree[node] += work[node];
    if (b.rows > b.columns) {
      parent[node] = column_node[static_cast<std::size_t>(s_.pattern[s_.pattern_start[node] + b.columns])];
      subtree[parent[node]] += subtree[node];
      children[parent[node]].push_back(node);
    } else {
      roots.push_back(node);
    }
  }
  const double total = std::accumulate(work.begin(), work.end(), 0.0);

  // Expand the heaviest subtree into its children (its root joins the top)
  // while that lowers the estimated time, top + heavier group; keep the best.
  std::vector<int> frontier = roots, best_frontier = roots;
  std::vector<char> group, best_group;
  double top_work = 0;
  double best_time = balance(frontier, subtree, &best_group);
  for (int step = 0; step < 256 && !frontier.empty(); ++step) {
    const auto heaviest =
        std::max_element(frontier.begin(), frontier.end(), [&](int a, int b) { return subtree[a] < subtree[b]; });
    const int node = *heaviest;
    frontier.erase(heaviest);
    top_work += work[node];
    frontier.insert(frontier.end(), children[node].begin(), children[node].end());
    const double time = top_work + balance(frontier, subtree, &group);
    if (time < best_time) {
      best_time = time;
      best_frontier = frontier;
      best_group = group;
    }
  }

  // Owners: a frontier subtree belongs to its group, everything above to the top.
  std::vector<char> owner(n_super, kTop);
  for (std::size_t i = 0; i < best_frontier.size(); ++i) owner[best_frontier[i]] = best_group[i];
  for (int node = n_super - 1; node >= 0; --node)
    if (owner[node] == kTop && parent[node] >= 0 && owner[parent[node]] != kTop) owner[node] = owner[parent[node]];
  double top_entries = 0;
  for (int node = 0; node < n_super; ++node) {
    (owner[node] == kTop ? top_ : group_[static_cast<int>(owner[node])]).push_back(node);
    if (owner[node] == kTop) top_entries += work[node];
  }
  top_share_ = total > 0 ? top_entries / total : 0;
  column_owner_.resize(n);
  for (int j = 0; j < n; ++j) column_owner_[j] = owner[column_node[j]];
  top_updates_.assign(n, 0);
  int widest = 0;
  for (int node = 0; node < n_super; ++node) widest = std::max(widest, shape(s_, node).rows);
  for (auto& scratch : scratch_) scratch.resize(widest);
}

// L y = z over one group's supernodes (group 2 = the top).
template <class Index>
void SupernodalSolve<Index>::forward(const double* values, int group, double* z) {
  const std::vector<int>& order = group == kTop ? top_ : group_[group];
  std::vector<double>& scratch = scratch_[group == kGroup1 ? 1 : 0];
  for (int node : order) {
    const BlockShape b = shape(s_, node);
    const Block L(values + s_.value_start[node], b.rows, b.columns, Eigen::OuterStride<>(b.rows));
    Eigen::Map<Eigen::VectorXd> y(z + b.first_column, b.columns);
    L.topRows(b.columns).triangularView<Eigen::Lower>().solveInPlace(y);
    const int below_count = b.rows - b.columns;
    const Index* below = s_.pattern + s_.pattern_start[node] + b.columns;
    Eigen::Map<Eigen::VectorXd> update(scratch.data(), below_count);
    update.noalias() = L.bottomRows(below_count) * y;
    for (int i = 0; i < below_count; ++i) {
      const Index row = below[i];
      if (group == kGroup1 && column_owner_[row] == kTop)
        top_updates_[row] += update[i];  // group 0 may be writing z[row] now
      else
        z[row] -= update[i];
    }
  }
}

// L^T x = y over supernodes `order`, last first.
template <class Index>
void SupernodalSolve<Index>::backward(const double* values, const std::vector<int>& order, double* z,
                               std::vector<double>* scratch) const {
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const int node = *it;
    const BlockShape b = shape(s_, node);
    const Block L(values + s_.value_start[node], b.rows, b.columns, Eigen::OuterStride<>(b.rows));
    Eigen::Map<Eigen::VectorXd> x(z + b.first_column, b.columns);
    const int below_count = b.rows - b.columns;
    const Index* below = s_.pattern + s_.pattern_start[node] + b.columns;
    Eigen::Map<Eigen::VectorXd> known(scratch->data(), below_count);
    for (int i = 0; i < below_count; ++i) known[i] = z[below[i]];
    x.noalias() -= L.bottomRows(below_count).transpose() * known;
    L.topRows(b.columns).triangularView<Eigen::Lower>().transpose().solveInPlace(x);
  }
}

template <class Index>
void SupernodalSolve<Index>::solve(const double* values, double* z) {
  tbb::parallel_invoke([&] { forward(values, kGroup0, z); }, [&] { forward(values, kGroup1, z); });
  for (int node : top_)
    for (Index j = s_.first_column[node]; j < s_.first_column[node + 1]; ++j) {
      z[j] -= top_updates_[j];
      top_updates_[j] = 0;
    }
  forward(values, kTop, z);
  backward(values, top_, z, &scratch_[0]);
  tbb::parallel_invoke([&] { backward(values, group_[0], z, &scratch_[0]); },
                       [&] { backward(values, group_[1], z, &scratch_[1]); });
}

template class SupernodalSolve<int>;
template class SupernodalSolve<SuiteSparse_long>;

}  // namespace akvf
