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
ElementMatrix<D, N>::ElementMatrix(const Eigen::MatrixXi& elements, int num_vertices) {
  auto built = std::make_shared<Pattern>();
  built->num_elements = static_cast<int>(elements.rows());
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
  std::vector<int>& offsets = built->gather_offsets;
  offsets.assign(nnz + 1, 0);
  for (int e : slot_entry) ++offsets[e + 1];
  for (int i = 0; i < nnz; ++i) offsets[i + 1] += offsets[i];
  built->gather_sources.resize(slot_entry.size());
  std::vector<int> fill(offsets.begin(), offsets.end() - 1);
  for (int s = 0; s < static_cast<int>(slot_entry.size()); ++s) built->gather_sources[fill[slot_entry[s]]++] = s;

  built->diagonal_entries.resize(n);
  // Rows are sorted within a column, so the diagonal is the last upper entry.
  for (int i = 0; i < n; ++i) built->diagonal_entries[i] = upper_.outerIndexPtr()[i + 1] - 1;
  pattern_ = std::move(built);
}

template <int D, int N>
ElementMatrix<D, N>::ElementMatrix(std::shared_ptr<const Pattern> pattern, Eigen::SparseMatrix<double> upper)
    : pattern_(std::move(pattern)), upper_(std::move(upper)) {}

template <int D, int N>
ElementMatrix<D, N> ElementMatrix<D, N>::with_pattern_of(const ElementMatrix& other) {
  Eigen::SparseMatrix<double> upper = other.upper_;
  std::fill(upper.valuePtr(), upper.valuePtr() + upper.nonZeros(), 0.0);
  return ElementMatrix(other.pattern_, std::move(upper));
}

template <int D, int N>
void ElementMatrix<D, N>::assemble(const LocalFunction& local) {
  const Pattern& pattern = *pattern_;
  element_buffer_.resize(static_cast<std::size_t>(kSlots) * pattern.num_elements);
  parallel_for_index(pattern.num_elements, 512, [&](int e) {
    Local M;
    local(e, &M);
    double* out = element_buffer_.data() + static_cast<std::size_t>(kSlots) * e;
    for (int j = 0; j < kLocalSize; ++j)
      for (int i = 0; i <= j; ++i) *out++ = M(i, j);
  });
  double* values = upper_.valuePtr();
  parallel_for_index(static_cast<int>(upper_.nonZeros()), 4096, [&](int e) {
    double sum = 0;
    for (int i = pattern.gather_offsets[e]; i < pattern.gather_offsets[e + 1]; ++i)
      sum += element_buffer_[pattern.gather_sources[i]];
    values[e] = sum;
  });
  double trace = 0;
  for (int e : pattern.diagonal_entries) trace += values[e];
  mean_diagonal_ = trace / static_cast<double>(pattern.diagonal_entries.size());
}

template <int D, int N>
void ElementMatrix<D, N>::add_to_diagonal(double shift) {
  for (int e : pattern_->diagonal_entries) upper_.valuePtr()[e] += shift;
}

template <int D, int N>
void ElementMatrix<D, N>::scale(double factor) {
  upper_ *= factor;
  mean_diagonal_ *= factor;
}

template <int D, int N>
void ElementMatrix<D, N>::add_to_diagonal(const Eigen::VectorXd& values) {
  const std::vector<int>& diagonal = pattern_->diagonal_entries;
  for (std::size_t i = 0; i < diagonal.size(); ++i) upper_.valuePtr()[diagonal[i]] += values[i];
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
