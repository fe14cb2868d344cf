#include "framework/optimization/element_matrix.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace akvf {

namespace {

template <class Body>
void parallel_for_index(int n, int grain, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<int>(0, n, grain), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i != r.end(); ++i) body(i);
  });
}

}  // namespace

template <int D, int N>
ElementMatrix<D, N>::ElementMatrix(const Eigen::MatrixXi& elements, int num_vertices) : elements_(elements) {
  const int n = D * num_vertices;
  const int ne = static_cast<int>(elements.rows());
  // Global dof of local dof i of element e.
  auto dof = [&](int e, int i) { return D * elements(e, i / D) + i % D; };
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(static_cast<std::size_t>(kSlots) * ne);
  for (int e = 0; e < ne; ++e)
    for (int j = 0; j < kLocalSize; ++j)
      for (int i = 0; i <= j; ++i) {
        const int a = dof(e, i), b = dof(e, j);
        pattern.emplace_back(std::min(a, b), std::max(a, b), 0.0);
      }
  upper_.resize(n, n);
  upper_.setFromTriplets(pattern.begin(), pattern.end());
  upper_.makeCompressed();

  // Where each local slot (i <= j, in the loop order above) lands among the nonzeros.
  std::vector<int> slot_entry(pattern.size());
  const int* rows = upper_.innerIndexPtr();
  for (std::size_t s = 0; s < pattern.size(); ++s) {
    const int begin = upper_.outerIndexPtr()[pattern[s].col()], end = upper_.outerIndexPtr()[pattern[s].col() + 1];
    slot_entry[s] = static_cast<int>(std::lower_bound(rows + begin, rows + end, pattern[s].row()) - rows);
  }
  // Invert it: for each nonzero, its contributing slots in increasing order,
  // so the gather sums in a fixed order whatever the thread count.
  const int nnz = static_cast<int>(upper_.nonZeros());
  gather_offsets_.assign(nnz + 1, 0);
  for (int e : slot_entry) ++gather_offsets_[e + 1];
  for (int i = 0; i < nnz; ++i) gather_offsets_[i + 1] += gather_offsets_[i];
  gather_sources_.resize(slot_entry.size());
  std::vector<int> fill(gather_offsets_.begin(), gather_offsets_.end() - 1);
  for (int s = 0; s < static_cast<int>(slot_entry.size()); ++s) gather_sources_[fill[slot_entry[s]]++] = s;

  diagonal_entries_.resize(n);
  // Rows are sorted within a column, so the diagonal is the last upper entry.
  for (int i = 0; i < n; ++i) diagonal_entries_[i] = upper_.outerIndexPtr()[i + 1] - 1;
  element_buffer_.resize(slot_entry.size());
}

template <int D, int N>
void ElementMatrix<D, N>::assemble(const LocalFunction& local) {
  parallel_for_index(static_cast<int>(elements_.rows()), 512, [&](int e) {
    Local M;
    local(e, &M);
    double* out = element_buffer_.data() + static_cast<std::size_t>(kSlots) * e;
    for (int j = 0; j < kLocalSize; ++j)
      for (int i = 0; i <= j; ++i) *out++ = M(i, j);
  });
  double* values = upper_.valuePtr();
  parallel_for_index(static_cast<int>(upper_.nonZeros()), 4096, [&](int e) {
    double sum = 0;
    for (int i = gather_offsets_[e]; i < gather_offsets_[e + 1]; ++i) sum += element_buffer_[gather_sources_[i]];
    values[e] = sum;
  });
  double trace = 0;
  for (int e : diagonal_entries_) trace += values[e];
  mean_diagonal_ = trace / static_cast<double>(diagonal_entries_.size());
}

template <int D, int N>
void ElementMatrix<D, N>::add_to_diagonal(double shift) {
  for (int e : diagonal_entries_) upper_.valuePtr()[e] += shift;
}

template <int D, int N>
void ElementMatrix<D, N>::scale(double factor) {
  upper_ *= factor;
  mean_diagonal_ *= factor;
}

template <int D, int N>
void ElementMatrix<D, N>::add_to_diagonal(const Eigen::VectorXd& values) {
  for (std::size_t i = 0; i < diagonal_entries_.size(); ++i) upper_.valuePtr()[diagonal_entries_[i]] += values[i];
}

template <int D, int N>
Eigen::SparseMatrix<double> ElementMatrix<D, N>::full() const {
  Eigen::SparseMatrix<double> strict_lower = upper_.transpose();
  strict_lower.prune([](int row, int col, double) { return row > col; });
  return upper_ + strict_lower;
}

template class ElementMatrix<2, 3>;
template class ElementMatrix<3, 4>;

}  // namespace akvf
