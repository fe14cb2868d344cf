#include "solvers/supernodal_solve.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cholmod.h>  // SuiteSparse_long
#include <algorithm>
#include <cstddef>
#include <numeric>

#include "solvers/supernodal_block_solve.h"

namespace akvf {

template <class Index>
SupernodalSolve<Index>::SupernodalSolve(const SupernodalStructure<Index>& structure)
    : s_(structure), tree_(supernodal_tree(structure)) {
  const int n_super = static_cast<int>(s_.supernodes);
  work_.resize(n_super);
  for (int node = 0; node < n_super; ++node) {
    const BlockShape b = block_shape(s_, node);
    work_[node] = 0.5 * b.columns * (b.columns + 1) + double(b.rows - b.columns) * b.columns;
  }
}

template <class Index>
void SupernodalSolve<Index>::split(int groups) {
  const int n_super = static_cast<int>(s_.supernodes);
  const std::vector<int> owner = split_subtrees(tree_, work_, groups);
  groups_.assign(groups, {});
  top_.clear();
  top_columns_.clear();
  double top_entries = 0;
  int widest = 0;
  for (int node = 0; node < n_super; ++node) {
    widest = std::max(widest, block_shape(s_, node).rows);
    if (owner[node] != kTop) {
      groups_[owner[node]].push_back(node);
      continue;
    }
    top_.push_back(node);
    top_entries += work_[node];
    for (Index j = s_.first_column[node]; j < s_.first_column[node + 1]; ++j)
      top_columns_.push_back(static_cast<int>(j));
  }
  const double total = std::accumulate(work_.begin(), work_.end(), 0.0);
  top_share_ = total > 0 ? top_entries / total : 0;
  column_top_.assign(s_.columns(), -1);
  for (std::size_t i = 0; i < top_columns_.size(); ++i) column_top_[top_columns_[i]] = static_cast<int>(i);
  top_updates_.assign(groups - 1, std::vector<double>(top_columns_.size(), 0.0));
  scratch_.assign(groups + 1, std::vector<double>(widest));
  affinity_ = std::make_unique<tbb::affinity_partitioner>();
}

template <class Index>
double SupernodalSolve<Index>::top_share(int groups) {
  if (static_cast<int>(groups_.size()) != groups) split(groups);
  return top_share_;
}

// Forward, on w = [y; minus the updates of the rows below]
// (forward_block), the updates then added to the rows below.
template <class Index>
template <class Value>
void SupernodalSolve<Index>::forward(const Value* values, int group, double* z) {
  double* w = scratch_[group == kTop ? groups_.size() : group].data();
  double* top_updates = group == kTop || group == 0 ? nullptr : top_updates_[group - 1].data();
  for (int node : members(group)) {
    const BlockShape b = block_shape(s_, node);
    const Value* L = values + s_.value_start[node];
    double* y = z + b.first_column;
    std::copy(y, y + b.columns, w);
    std::fill(w + b.columns, w + b.rows, 0.0);
    forward_block(b.rows, b.columns, L, w);
    std::copy(w, w + b.columns, y);
    const Index* below = s_.pattern + s_.pattern_start[node] + b.columns;
    const double* update = w + b.columns;  // minus L(below, :) y
    for (int i = 0; i < b.rows - b.columns; ++i) {
      const Index row = below[i];
      // A row below a group's supernode is the group's own or the top's
      // (group 0 writes those, the others keep theirs apart).
      const int top_index = top_updates ? column_top_[static_cast<std::size_t>(row)] : -1;
      if (top_index >= 0)
        top_updates[top_index] -= update[i];
      else
        z[row] += update[i];
    }
  }
}

// Backward, on w = [x; the known x of the rows below] (backward_block).
template <class Index>
template <class Value>
void SupernodalSolve<Index>::backward(const Value* values, int group, double* z) {
  double* w = scratch_[group == kTop ? groups_.size() : group].data();
  const std::vector<int>& order = members(group);
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const int node = *it;
    const BlockShape b = block_shape(s_, node);
    const Value* L = values + s_.value_start[node];
    double* x = z + b.first_column;
    const Index* below = s_.pattern + s_.pattern_start[node] + b.columns;
    std::copy(x, x + b.columns, w);
    for (int i = 0; i < b.rows - b.columns; ++i) w[b.columns + i] = z[below[i]];
    backward_block(b.rows, b.columns, L, w);
    std::copy(w, w + b.columns, x);
  }
}

template <class Index>
template <class Value>
void SupernodalSolve<Index>::solve(const Value* values, double* z) {
  const int threads = std::max(2, tbb::this_task_arena::max_concurrency());
  if (static_cast<int>(groups_.size()) != threads) split(threads);
  const tbb::blocked_range<int> groups(0, threads, 1);
  tbb::parallel_for(
      groups,
      [&](const tbb::blocked_range<int>& range) {
        for (int g = range.begin(); g != range.end(); ++g) forward(values, g, z);
      },
      *affinity_);
  for (std::size_t i = 0; i < top_columns_.size(); ++i)
    for (std::vector<double>& updates : top_updates_) {
      z[top_columns_[i]] -= updates[i];
      updates[i] = 0;
    }
  forward(values, kTop, z);
  backward(values, kTop, z);
  tbb::parallel_for(
      groups,
      [&](const tbb::blocked_range<int>& range) {
        for (int g = range.begin(); g != range.end(); ++g) backward(values, g, z);
      },
      *affinity_);
}

template class SupernodalSolve<int>;
template class SupernodalSolve<SuiteSparse_long>;
template void SupernodalSolve<int>::solve(const double*, double*);
template void SupernodalSolve<int>::solve(const SingleEntry*, double*);
template void SupernodalSolve<SuiteSparse_long>::solve(const double*, double*);
template void SupernodalSolve<SuiteSparse_long>::solve(const SingleEntry*, double*);

}  // namespace akvf
