#include "solvers/supernodal_solve.h"

#include <tbb/parallel_invoke.h>

#include <cholmod.h>  // SuiteSparse_long
#include <algorithm>
#include <cstddef>
#include <numeric>

namespace akvf {

namespace {

// y[i] -= a x[i], i < n.
inline void subtract_scaled(double a, const double* __restrict x, double* __restrict y, int n) {
  for (int i = 0; i < n; ++i) y[i] -= a * x[i];
}

// sum_i x[i] y[i], i < n, in four interleaved partial sums (so the compiler
// can keep them in vector registers; the order is fixed, so is the result).
inline double dot(const double* __restrict x, const double* __restrict y, int n) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    s0 += x[i] * y[i];
    s1 += x[i + 1] * y[i + 1];
    s2 += x[i + 2] * y[i + 2];
    s3 += x[i + 3] * y[i + 3];
  }
  for (; i < n; ++i) s0 += x[i] * y[i];
  return (s0 + s2) + (s1 + s3);
}

}  // namespace

template <class Index>
SupernodalSolve<Index>::SupernodalSolve(const SupernodalStructure<Index>& structure) : s_(structure) {
  const int n_super = static_cast<int>(s_.supernodes);
  const int n = s_.columns();
  const SupernodalTree tree = supernodal_tree(s_);
  // A supernode's work: the entries of its block (each is read once).
  std::vector<double> work(n_super);
  for (int node = 0; node < n_super; ++node) {
    const BlockShape b = block_shape(s_, node);
    work[node] = 0.5 * b.columns * (b.columns + 1) + double(b.rows - b.columns) * b.columns;
  }
  const std::vector<char> owner = split_subtrees(tree, work, 1.0);
  const double total = std::accumulate(work.begin(), work.end(), 0.0);
  double top_entries = 0;
  for (int node = 0; node < n_super; ++node) {
    (owner[node] == kTop ? top_ : group_[static_cast<int>(owner[node])]).push_back(node);
    if (owner[node] == kTop) top_entries += work[node];
  }
  top_share_ = total > 0 ? top_entries / total : 0;
  column_owner_.resize(n);
  for (int j = 0; j < n; ++j) column_owner_[j] = owner[tree.column_node[j]];
  top_updates_.assign(n, 0);
  int widest = 0;
  for (int node = 0; node < n_super; ++node) widest = std::max(widest, block_shape(s_, node).rows);
  for (auto& scratch : scratch_) scratch.resize(widest);
}

// L y = z over one group's supernodes (group 2 = the top). A supernode's
// block is column-major with its diagonal triangle on top, so column j below
// the diagonal, L(j+1.., j), is one contiguous run covering both the
// triangle's rows and the rows below it: one pass subtract_scaled per
// column over w = [y; updates of the rows below] (module comment).
template <class Index>
void SupernodalSolve<Index>::forward(const double* values, int group, double* z) {
  const std::vector<int>& order = group == kTop ? top_ : group_[group];
  double* w = scratch_[group == kGroup1 ? 1 : 0].data();
  for (int node : order) {
    const BlockShape b = block_shape(s_, node);
    const double* L = values + s_.value_start[node];
    double* y = z + b.first_column;
    std::copy(y, y + b.columns, w);
    std::fill(w + b.columns, w + b.rows, 0.0);
    for (int j = 0; j < b.columns; ++j) {
      const double* column = L + static_cast<std::size_t>(j) * b.rows;
      w[j] /= column[j];
      subtract_scaled(w[j], column + j + 1, w + j + 1, b.rows - j - 1);
    }
    std::copy(w, w + b.columns, y);
    const Index* below = s_.pattern + s_.pattern_start[node] + b.columns;
    const double* update = w + b.columns;  // minus L(below, :) y
    for (int i = 0; i < b.rows - b.columns; ++i) {
      const Index row = below[i];
      if (group == kGroup1 && column_owner_[row] == kTop)
        top_updates_[row] -= update[i];  // group 0 may be writing z[row] now
      else
        z[row] += update[i];
    }
  }
}

// L^T x = y over supernodes `order`, last first: with w = [x; the known x
// of the rows below], x_j = (w_j - L(j+1.., j) . w(j+1..)) / L(j, j) for j
// from the last column down, one dot per contiguous column run.
template <class Index>
void SupernodalSolve<Index>::backward(const double* values, const std::vector<int>& order, double* z,
                                      std::vector<double>* scratch) const {
  double* w = scratch->data();
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const int node = *it;
    const BlockShape b = block_shape(s_, node);
    const double* L = values + s_.value_start[node];
    double* x = z + b.first_column;
    const Index* below = s_.pattern + s_.pattern_start[node] + b.columns;
    std::copy(x, x + b.columns, w);
    for (int i = 0; i < b.rows - b.columns; ++i) w[b.columns + i] = z[below[i]];
    for (int j = b.columns - 1; j >= 0; --j) {
      const double* column = L + static_cast<std::size_t>(j) * b.rows;
      w[j] = (w[j] - dot(column + j + 1, w + j + 1, b.rows - j - 1)) / column[j];
    }
    std::copy(w, w + b.columns, x);
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
