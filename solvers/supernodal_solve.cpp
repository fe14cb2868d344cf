#include "solvers/supernodal_solve.h"

#include <tbb/parallel_invoke.h>

#include <cholmod.h>  // SuiteSparse_long
#include <Eigen/Core>
#include <algorithm>
#include <numeric>

namespace akvf {

namespace {

using Block = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>>;

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

// L y = z over one group's supernodes (group 2 = the top).
template <class Index>
void SupernodalSolve<Index>::forward(const double* values, int group, double* z) {
  const std::vector<int>& order = group == kTop ? top_ : group_[group];
  std::vector<double>& scratch = scratch_[group == kGroup1 ? 1 : 0];
  for (int node : order) {
    const BlockShape b = block_shape(s_, node);
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
    const BlockShape b = block_shape(s_, node);
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
