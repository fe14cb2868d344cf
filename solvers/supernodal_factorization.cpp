#include "solvers/supernodal_factorization.h"

#include <tbb/parallel_for_each.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include <cholmod.h>  // SuiteSparse_long
#include <algorithm>
#include <string>
#include <utility>

#include "solvers/dense_block_kernels.h"
#include "solvers/sparse_cholesky.h"

namespace akvf {

namespace {

// Flops of a supernode with c columns and b rows below them: its diagonal
// block (c^3 / 3), the rows below (b c^2) and its updates of later
// supernodes (b^2 c).
double supernode_flops(const BlockShape& shape) {
  const double c = shape.columns, b = shape.rows - shape.columns;
  return c * c * c / 3 + b * c * c + b * b * c;
}

}  // namespace

template <class Index>
SupernodalFactorization<Index>::SupernodalFactorization(const SupernodalStructure<Index>& structure) : s_(structure) {
  const int n_super = static_cast<int>(s_.supernodes);
  SupernodalTree tree = supernodal_tree(s_);
  column_node_ = std::move(tree.column_node);
  std::vector<double> work(n_super);
  for (int node = 0; node < n_super; ++node) work[node] = supernode_flops(block_shape(s_, node));
  // The top counts about half: its branches are worked on concurrently.
  const std::vector<char> owner = split_subtrees(tree, work, 0.5);
  top_children_.resize(n_super);
  for (int node = 0; node < n_super; ++node) {
    if (owner[node] != kTop) {
      group_[static_cast<int>(owner[node])].push_back(node);
      continue;
    }
    if (tree.parent[node] < 0)
      top_roots_.push_back(node);
    else
      top_children_[tree.parent[node]].push_back(node);  // a top node's parent is in the top
  }
  next_row_.resize(n_super);
  next_.resize(n_super);
  key_.resize(n_super);
  for (Workspace& w : workspace_) w.local_row.resize(s_.columns());
}

template <class Index>
void SupernodalFactorization<Index>::link(int d, Index position, int worker, Key key) {
  next_row_[d] = position;
  if (position < s_.pattern_start[d + 1]) {
    const int target = column_node_[static_cast<std::size_t>(s_.pattern[position])];
    next_[d] = head_[worker][target];
    head_[worker][target] = d;
    key_[d] = key;
  }
}

template <class Index>
void SupernodalFactorization<Index>::assemble(int s, const LowerTriangle& A, const std::vector<int>& local_row,
                                              double* values) const {
  const BlockShape b = block_shape(s_, s);
  double* block = values + s_.value_start[s];
  std::fill(block, block + static_cast<std::size_t>(b.rows) * b.columns, 0.0);
  for (int j = 0; j < b.columns; ++j) {
    const int column = b.first_column + j;
    double* target = block + static_cast<std::size_t>(j) * b.rows;
    for (int p = A.column_start[column]; p < A.column_start[column + 1]; ++p)
      target[local_row[A.row[p]]] += A.value[A.source[p]];
  }
}

template <class Index>
void SupernodalFactorization<Index>::collect(int s, int worker) {
  const Index last_column = s_.first_column[s + 1];
  Workspace& w = workspace_[worker];
  w.descendants.clear();
  for (const std::vector<int>& head : head_)
    for (int node = head[s]; node >= 0; node = next_[node]) {
      const Index first = next_row_[node], end = s_.pattern_start[node + 1];
      Index inside = first;
      while (inside < end && s_.pattern[inside] < last_column) ++inside;
      w.descendants.push_back({node, first, static_cast<int>(inside - first), static_cast<int>(end - first)});
    }
  // CHOLMOD's order: its one list has the last linked first.
  std::sort(w.descendants.begin(), w.descendants.end(),
            [&](const Descendant& a, const Descendant& b) { return key_[a.node] > key_[b.node]; });
}

template <class Index>
void SupernodalFactorization<Index>::apply_update(const Descendant& d, int s, Workspace* w, double* values) const {
  const BlockShape db = block_shape(s_, d.node), sb = block_shape(s_, s);
  const Index* rows = s_.pattern + d.first;
  const int m = d.rows, columns = d.inside;
  w->relative.resize(m);
  for (int i = 0; i < m; ++i) w->relative[i] = w->local_row[rows[i]];
  if (w->update.size() < static_cast<std::size_t>(m) * columns) w->update.resize(static_cast<std::size_t>(m) * columns);
  double* C = w->update.data();

  // C = L_d(rows, :) L_d(rows inside s, :)^T, lower part.
  const double* Ld = values + s_.value_start[d.node] + (d.first - s_.pattern_start[d.node]);
  block_update(m, columns, db.columns, Ld, db.rows, C);

  double* block = values + s_.value_start[s];
  for (int j = 0; j < columns; ++j) {
    double* target = block + static_cast<std::size_t>(rows[j] - sb.first_column) * sb.rows;
    const double* source = C + static_cast<std::size_t>(j) * m;
    for (int i = j; i < m; ++i) target[w->relative[i]] -= source[i];
  }
}

template <class Index>
void SupernodalFactorization<Index>::factor_block(int s, double* values) const {
  const BlockShape b = block_shape(s_, s);
  const int bad = block_cholesky(b.rows, b.columns, values + s_.value_start[s]);
  if (bad >= 0)
    throw NotPositiveDefinite("matrix is not positive definite (non-positive pivot at column " +
                              std::to_string(b.first_column + bad) + ")");
}

template <class Index>
void SupernodalFactorization<Index>::advance(int s, int worker) {
  const std::vector<Descendant>& descendants = workspace_[worker].descendants;
  for (std::size_t i = 0; i < descendants.size(); ++i)
    link(descendants[i].node, descendants[i].first + descendants[i].inside, worker, {s, static_cast<int>(i)});
}

template <class Index>
void SupernodalFactorization<Index>::factor_supernode(int s, int worker, const LowerTriangle& A, double* values) {
  const BlockShape b = block_shape(s_, s);
  const Index first_row = s_.pattern_start[s];
  Workspace& w = workspace_[worker];
  for (int i = 0; i < b.rows; ++i) w.local_row[static_cast<std::size_t>(s_.pattern[first_row + i])] = i;
  assemble(s, A, w.local_row, values);
  collect(s, worker);
  for (const Descendant& d : w.descendants) apply_update(d, s, &w, values);
  advance(s, worker);
  const Key key{s, static_cast<int>(w.descendants.size())};  // s links after its descendants
  factor_block(s, values);
  link(s, first_row + b.columns, worker, key);
}

template <class Index>
void SupernodalFactorization<Index>::factor_unless_stopped(int s, int worker, const LowerTriangle& A, double* values) {
  if (stopped_.load(std::memory_order_relaxed)) return;
  try {
    factor_supernode(s, worker, A, values);
  } catch (...) {
    stopped_.store(true, std::memory_order_relaxed);
    throw;
  }
}

template <class Index>
void SupernodalFactorization<Index>::factor_top(int s, const LowerTriangle& A, double* values) {
  // Branches of the top are disjoint: they run concurrently (a supernode
  // needs only its descendants, all finished before it starts).
  const std::vector<int>& children = top_children_[s];
  if (children.size() == 1)
    factor_top(children.front(), A, values);
  else if (children.size() > 1)
    tbb::parallel_for_each(children.begin(), children.end(), [&](int child) { factor_top(child, A, values); });
  factor_unless_stopped(s, tbb::this_task_arena::current_thread_index(), A, values);
}

template <class Index>
void SupernodalFactorization<Index>::factorize(const LowerTriangle& A, double* values) {
  if (A.n != s_.columns()) throw NumericalError("SupernodalFactorization: the matrix does not fit the analysis");
  for (auto& head : head_) head.assign(static_cast<std::size_t>(s_.supernodes), -1);
  stopped_.store(false);
  // Two workers, so that each has its own lists and workspace (the arena's
  // thread index names the worker).
  tbb::task_arena arena(2);
  arena.execute([&] {
    tbb::parallel_invoke(
        [&] {
          for (int s : group_[0]) factor_unless_stopped(s, 0, A, values);
        },
        [&] {
          for (int s : group_[1]) factor_unless_stopped(s, 1, A, values);
        });
    tbb::parallel_for_each(top_roots_.begin(), top_roots_.end(), [&](int root) { factor_top(root, A, values); });
  });
}

template class SupernodalFactorization<int>;
template class SupernodalFactorization<SuiteSparse_long>;

}  // namespace akvf
