#include "solvers/supernodal_factorization.h"

#include <cholmod.h>  // SuiteSparse_long
#include <algorithm>
#include <string>
#include <utility>

#include "solvers/dense_block_kernels.h"
#include "solvers/sparse_cholesky.h"

namespace akvf {

namespace {

// Below it a subtree is factored by one task (some 100 microseconds).
constexpr double kMinUnitFlops = 5e5;

// Flops of each supernode's work in the left-looking loop: its block's
// Cholesky factorization and the updates it receives.
template <class Index>
std::vector<double> supernode_flops(const SupernodalStructure<Index>& s, const std::vector<int>& column_node) {
  const int n_super = static_cast<int>(s.supernodes);
  std::vector<double> flops(n_super, 0.0);
  for (int d = 0; d < n_super; ++d) {
    const BlockShape b = block_shape(s, d);
    flops[d] += cholesky_flops(b.rows, b.columns);
    const Index end = s.pattern_start[d + 1];
    for (Index p = s.pattern_start[d] + b.columns; p < end;) {
      const int target = column_node[static_cast<std::size_t>(s.pattern[p])];
      Index q = p;
      while (q < end && column_node[static_cast<std::size_t>(s.pattern[q])] == target) ++q;
      flops[target] += update_flops(static_cast<int>(end - p), static_cast<int>(q - p), b.columns);
      p = q;
    }
  }
  return flops;
}

}  // namespace

template <class Index>
SupernodalFactorization<Index>::SupernodalFactorization(const SupernodalStructure<Index>& structure)
    : s_(structure), head_(static_cast<std::size_t>(structure.supernodes)), workspaces_([n = structure.columns()] {
        Workspace w;
        w.local_row.resize(n);
        return w;
      }) {
  const int n_super = static_cast<int>(s_.supernodes);
  const SupernodalTree tree = supernodal_tree(s_);
  schedule_ = TreeSchedule(tree, supernode_flops(s_, tree.column_node), kMinUnitFlops);
  column_node_ = tree.column_node;
  next_row_.resize(n_super);
  next_.resize(n_super);
  key_.resize(n_super);
}

template <class Index>
void SupernodalFactorization<Index>::link(int d, Index position, Key key) {
  next_row_[d] = position;
  if (position < s_.pattern_start[d + 1]) {
    const int target = column_node_[static_cast<std::size_t>(s_.pattern[position])];
    key_[d] = key;
    int head = head_[target].load(std::memory_order_relaxed);
    do {
      next_[d] = head;
    } while (!head_[target].compare_exchange_weak(head, d, std::memory_order_release, std::memory_order_relaxed));
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
void SupernodalFactorization<Index>::collect(int s, Workspace* w) const {
  const Index last_column = s_.first_column[s + 1];
  w->descendants.clear();
  for (int node = head_[s].load(std::memory_order_acquire); node >= 0; node = next_[node]) {
    const Index first = next_row_[node], end = s_.pattern_start[node + 1];
    Index inside = first;
    while (inside < end && s_.pattern[inside] < last_column) ++inside;
    w->descendants.push_back({node, first, static_cast<int>(inside - first), static_cast<int>(end - first)});
  }
  // CHOLMOD's order: its one list has the last linked first.
  std::sort(w->descendants.begin(), w->descendants.end(),
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
void SupernodalFactorization<Index>::advance(int s, const Workspace& w) {
  for (std::size_t i = 0; i < w.descendants.size(); ++i) {
    const Descendant& d = w.descendants[i];
    link(d.node, d.first + d.inside, {s, static_cast<int>(i)});
  }
}

template <class Index>
void SupernodalFactorization<Index>::factor_supernode(int s, const LowerTriangle& A, double* values) {
  if (stopped_.load(std::memory_order_relaxed)) return;
  const BlockShape b = block_shape(s_, s);
  const Index first_row = s_.pattern_start[s];
  Workspace& w = workspaces_.local();
  for (int i = 0; i < b.rows; ++i) w.local_row[static_cast<std::size_t>(s_.pattern[first_row + i])] = i;
  assemble(s, A, w.local_row, values);
  collect(s, &w);
  for (const Descendant& d : w.descendants) apply_update(d, s, &w, values);
  advance(s, w);
  const Key key{s, static_cast<int>(w.descendants.size())};  // s links after its descendants
  try {
    factor_block(s, values);
  } catch (...) {
    stopped_.store(true, std::memory_order_relaxed);
    throw;
  }
  link(s, first_row + b.columns, key);
}

template <class Index>
void SupernodalFactorization<Index>::factorize(const LowerTriangle& A, double* values) {
  if (A.n != s_.columns()) throw NumericalError("SupernodalFactorization: the matrix does not fit the analysis");
  for (std::atomic<int>& head : head_) head.store(-1, std::memory_order_relaxed);
  stopped_.store(false);
  schedule_.bottom_up([&](int unit) {
    for (const int* s = schedule_.nodes_begin(unit); s != schedule_.nodes_end(unit); ++s)
      factor_supernode(*s, A, values);
  });
}

template class SupernodalFactorization<int>;
template class SupernodalFactorization<SuiteSparse_long>;

}  // namespace akvf
