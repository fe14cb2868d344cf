#include "framework/optimization/element_matrix.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "framework/mesh/vertex_graph.h"

namespace akvf {

namespace {

template <class Body>
void parallel_for_index(int n, int grain, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<int>(0, n, grain), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i != r.end(); ++i) body(i);
  });
}

}  // namespace

template <int D>
Eigen::SparseMatrix<double> block_upper_pattern(const UpperVertexGraph& graph) {
  const int num_vertices = graph.num_vertices();
  const int n = D * num_vertices;
  const auto neighbors_of = [&](int v) { return graph.column_start[v + 1] - graph.column_start[v]; };
  // Column D v + c holds the D rows of each neighbor u < v, then D v + 0..c.
  std::vector<int> outer(n + 1, 0);
  for (int v = 0; v < num_vertices; ++v)
    for (int c = 0; c < D; ++c)
      outer[D * v + c + 1] = outer[D * v + c] + (neighbors_of(v) > 0 ? D * (neighbors_of(v) - 1) + c + 1 : 0);
  Eigen::SparseMatrix<double> upper(n, n);
  upper.resizeNonZeros(outer[n]);
  std::copy(outer.begin(), outer.end(), upper.outerIndexPtr());
  std::fill(upper.valuePtr(), upper.valuePtr() + outer[n], 0.0);
  int* rows = upper.innerIndexPtr();
  parallel_for_index(num_vertices, 4096, [&](int v) {
    for (int c = 0; c < D; ++c) {
      int* row = rows + outer[D * v + c];
      for (int k = 0; k < neighbors_of(v); ++k) {
        const int u = graph.row[graph.column_start[v] + k];
        for (int r = 0; r < (u < v ? D : c + 1); ++r) *row++ = D * u + r;
      }
    }
  });
  return upper;
}

template <int D, int N>
ElementMatrix<D, N>::ElementMatrix(const Eigen::MatrixXi& elements, int num_vertices) {
  auto built = std::make_shared<Pattern>();
  built->num_elements = static_cast<int>(elements.rows());
  const int n = D * num_vertices;
  const int ne = static_cast<int>(elements.rows());

  // The vertex graph's upper triangle: for each vertex v the vertices u <= v
  // that share an element with it (v itself last), in increasing order.
  UpperVertexGraph graph = upper_vertex_graph(elements, num_vertices);
  const auto neighbors_of = [&](int v) { return graph.column_start[v + 1] - graph.column_start[v]; };
  {
    Eigen::SparseMatrix<double> pattern = block_upper_pattern<D>(graph);
    upper_.swap(pattern);  // no copy (Eigen 3.4's move assignment copies)
  }
  const int* outer = upper_.outerIndexPtr();

  // Where each local slot (i <= j, in this loop order) lands among the
  // nonzeros: the k-th neighbor's rows start at D k in its column.
  // The neighbor index is looked up once per pair of corners.
  std::vector<int> slot_entry(static_cast<std::size_t>(kSlots) * ne);
  parallel_for_index(ne, 1024, [&](int e) {
    int vertex[N], neighbor[N][N];  // neighbor[a][b]: the smaller one's index in the larger one's column
    for (int a = 0; a < N; ++a) vertex[a] = elements(e, a);
    for (int b = 0; b < N; ++b)
      for (int a = 0; a <= b; ++a) {
        const int low = std::min(vertex[a], vertex[b]), high = std::max(vertex[a], vertex[b]);
        const int* first = graph.row.data() + graph.column_start[high];
        neighbor[a][b] = neighbor[b][a] =
            static_cast<int>(std::lower_bound(first, first + neighbors_of(high), low) - first);
      }
    int* entry = slot_entry.data() + static_cast<std::size_t>(kSlots) * e;
    for (int j = 0; j < kLocalSize; ++j)
      for (int i = 0; i <= j; ++i) {
        const int a = i / D, b = j / D;
        // The entry of dofs (D vertex[a] + i % D, D vertex[b] + j % D) in
        // the upper triangle: the column is the larger dof's.
        const int dof_i = D * vertex[a] + i % D, dof_j = D * vertex[b] + j % D;
        const int low = std::min(dof_i, dof_j), high = std::max(dof_i, dof_j);
        *entry++ = outer[high] + D * neighbor[a][b] + low % D;
      }
  });
  graph = {};
  // Invert it: for each nonzero, its contributing slots in increasing order
  // (so each sum has a fixed order whatever the thread count) ...
  const int nnz = static_cast<int>(upper_.nonZeros());
  std::vector<int> offsets(nnz + 1, 0);
  for (int e : slot_entry) ++offsets[e + 1];
  for (int i = 0; i < nnz; ++i) offsets[i + 1] += offsets[i];
  std::vector<int> by_entry(slot_entry.size());
  {
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (int s = 0; s < static_cast<int>(slot_entry.size()); ++s) by_entry[fill[slot_entry[s]]++] = s;
  }
  std::vector<int>().swap(slot_entry);
  // ... then regroup each nonzero's run of slots in one chunk by chunk,
  // keeping the nonzeros and the slots in increasing order within a chunk.
  const long chunk_slots = static_cast<long>(kChunkElements) * kSlots;
  const int chunks = (ne + kChunkElements - 1) / kChunkElements;
  const auto for_each_run = [&](auto&& visit) {  // visit(nonzero, chunk, first, last) over by_entry
    for (int i = 0; i < nnz; ++i)
      for (int k = offsets[i]; k < offsets[i + 1];) {
        const int chunk = static_cast<int>(by_entry[k] / chunk_slots);
        int end = k;
        while (end < offsets[i + 1] && by_entry[end] / chunk_slots == chunk) ++end;
        visit(i, chunk, k, end);
        k = end;
      }
  };
  std::vector<int> runs(chunks + 1, 0), slots_before(chunks + 1, 0);
  for_each_run([&](int, int chunk, int first, int last) {
    ++runs[chunk + 1];
    slots_before[chunk + 1] += last - first;
  });
  for (int c = 0; c < chunks; ++c) {
    runs[c + 1] += runs[c];
    slots_before[c + 1] += slots_before[c];
  }
  built->chunk_touched = runs;
  built->touched.resize(runs[chunks]);
  built->source_offsets.resize(runs[chunks] + 1);
  built->sources.resize(by_entry.size());
  std::vector<int> next_run(runs.begin(), runs.end() - 1), next_slot(slots_before.begin(), slots_before.end() - 1);
  for_each_run([&](int nonzero, int chunk, int first, int last) {
    const int t = next_run[chunk]++;
    built->touched[t] = nonzero;
    built->source_offsets[t] = next_slot[chunk];
    for (int k = first; k < last; ++k)
      built->sources[next_slot[chunk]++] = static_cast<int>(by_entry[k] - chunk * chunk_slots);
  });
  built->source_offsets[runs[chunks]] = static_cast<int>(by_entry.size());

  built->diagonal_entries.resize(n);
  // Rows are sorted within a column, so the diagonal is the last upper entry.
  for (int i = 0; i < n; ++i) built->diagonal_entries[i] = upper_.outerIndexPtr()[i + 1] - 1;
  pattern_ = std::move(built);
}

template <int D, int N>
ElementMatrix<D, N>::ElementMatrix(std::shared_ptr<const Pattern> pattern) : pattern_(std::move(pattern)) {}

template <int D, int N>
ElementMatrix<D, N>::ElementMatrix(ElementMatrix&& other) noexcept
    : pattern_(std::move(other.pattern_)),
      element_buffer_(std::move(other.element_buffer_)),
      mean_diagonal_(other.mean_diagonal_) {
  upper_.swap(other.upper_);
}

template <int D, int N>
ElementMatrix<D, N>& ElementMatrix<D, N>::operator=(ElementMatrix&& other) noexcept {
  pattern_ = std::move(other.pattern_);
  upper_.swap(other.upper_);
  element_buffer_.swap(other.element_buffer_);
  mean_diagonal_ = other.mean_diagonal_;
  return *this;
}

template <int D, int N>
ElementMatrix<D, N> ElementMatrix<D, N>::with_pattern_of(const ElementMatrix& other) {
  ElementMatrix matrix(other.pattern_);
  matrix.upper_ = other.upper_;
  std::fill(matrix.upper_.valuePtr(), matrix.upper_.valuePtr() + matrix.upper_.nonZeros(), 0.0);
  return matrix;
}

template <int D, int N>
ElementMatrix<D, N> ElementMatrix<D, N>::taking_storage_of(ElementMatrix* donor) {
  ElementMatrix matrix(donor->pattern_);
  matrix.upper_.swap(donor->upper_);
  std::fill(matrix.upper_.valuePtr(), matrix.upper_.valuePtr() + matrix.upper_.nonZeros(), 0.0);
  return matrix;
}

template <int D, int N>
bool ElementMatrix<D, N>::same_pattern(const ElementMatrix& other) const {
  return pattern_ == other.pattern_ ||
         (upper_.rows() == other.upper_.rows() && upper_.nonZeros() == other.upper_.nonZeros());
}

template <int D, int N>
void ElementMatrix<D, N>::assemble(const LocalFunction& local) {
  const Pattern& pattern = *pattern_;
  const int chunks = static_cast<int>(pattern.chunk_touched.size()) - 1;
  element_buffer_.resize(static_cast<std::size_t>(kSlots) * std::min(pattern.num_elements, kChunkElements));
  double* values = upper_.valuePtr();
  std::fill(values, values + upper_.nonZeros(), 0.0);
  for (int c = 0; c < chunks; ++c) {
    const int first = c * kChunkElements, count = std::min(kChunkElements, pattern.num_elements - first);
    parallel_for_index(count, 512, [&](int k) {
      Local M;
      local(first + k, &M);
      double* out = element_buffer_.data() + static_cast<std::size_t>(kSlots) * k;
      for (int j = 0; j < kLocalSize; ++j)
        for (int i = 0; i <= j; ++i) *out++ = M(i, j);
    });
    const int begin = pattern.chunk_touched[c];
    parallel_for_index(pattern.chunk_touched[c + 1] - begin, 4096, [&](int k) {
      const int t = begin + k;
      double sum = values[pattern.touched[t]];
      for (int i = pattern.source_offsets[t]; i < pattern.source_offsets[t + 1]; ++i)
        sum += element_buffer_[pattern.sources[i]];
      values[pattern.touched[t]] = sum;
    });
  }
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

template Eigen::SparseMatrix<double> block_upper_pattern<2>(const UpperVertexGraph&);
template Eigen::SparseMatrix<double> block_upper_pattern<3>(const UpperVertexGraph&);
template class ElementMatrix<2, 3>;
template class ElementMatrix<3, 4>;

}  // namespace akvf
