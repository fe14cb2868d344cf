#include "framework/optimization/element_matrix.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

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
  built->entries = std::move(slot_entry);
  // The slots adding to each vertex's columns (the larger dof's vertex).
  built->additions_before.assign(num_vertices + 1, 0);
  for (int e = 0; e < ne; ++e)
    for (int b = 0; b < N; ++b)
      for (int a = 0; a <= b; ++a)
        built->additions_before[std::max(elements(e, a), elements(e, b)) + 1] += a == b ? D * (D + 1) / 2 : D * D;
  for (int v = 0; v < num_vertices; ++v) built->additions_before[v + 1] += built->additions_before[v];
  built->nonzeros = static_cast<int>(upper_.nonZeros());

  built->diagonal_entries.resize(n);
  // Rows are sorted within a column, so the diagonal is the last upper entry.
  for (int i = 0; i < n; ++i) built->diagonal_entries[i] = upper_.outerIndexPtr()[i + 1] - 1;
  pattern_ = std::move(built);
  parts_ = split_nonzeros(*pattern_, upper_.outerIndexPtr(), tbb::this_task_arena::max_concurrency());
}

template <int D, int N>
std::shared_ptr<const typename ElementMatrix<D, N>::Parts> ElementMatrix<D, N>::split_nonzeros(const Pattern& pattern,
                                                                                               const int* outer,
                                                                                               int count) {
  auto parts = std::make_shared<Parts>();
  // Bounds at the first columns of vertices that give each part about as
  // many additions (slots) as the others.
  const std::vector<long>& before = pattern.additions_before;
  const int num_vertices = static_cast<int>(before.size()) - 1;
  parts->bounds.assign(count + 1, pattern.nonzeros);
  parts->bounds[0] = 0;
  for (int p = 1; p < count; ++p) {
    const long share = before.back() * p / count;
    const int v = static_cast<int>(std::lower_bound(before.begin(), before.end(), share) - before.begin());
    parts->bounds[p] = std::max(parts->bounds[p - 1], v < num_vertices ? outer[D * v] : pattern.nonzeros);
  }
  // Each element goes to the parts from its lowest nonzero's to its
  // highest's, marked (~e) where some of its slots lie outside the part.
  const auto part_of = [&](int entry) {
    return static_cast<int>(std::upper_bound(parts->bounds.begin() + 1, parts->bounds.end() - 1, entry) -
                            (parts->bounds.begin() + 1));
  };
  const auto for_each_part = [&](int e, auto&& visit) {
    const int* entry = pattern.entries.data() + static_cast<std::size_t>(kSlots) * e;
    const auto [low, high] = std::minmax_element(entry, entry + kSlots);
    const int first = part_of(*low), last = part_of(*high);
    for (int p = first; p <= last; ++p) visit(p, first == last ? e : ~e);
  };
  parts->offsets.assign(count + 1, 0);
  for (int e = 0; e < pattern.num_elements; ++e) for_each_part(e, [&](int p, int) { ++parts->offsets[p + 1]; });
  for (int p = 0; p < count; ++p) parts->offsets[p + 1] += parts->offsets[p];
  parts->items.resize(parts->offsets[count]);
  std::vector<int> next(parts->offsets.begin(), parts->offsets.end() - 1);
  for (int e = 0; e < pattern.num_elements; ++e)
    for_each_part(e, [&](int p, int item) { parts->items[next[p]++] = item; });
  return parts;
}

template <int D, int N>
ElementMatrix<D, N>::ElementMatrix(std::shared_ptr<const Pattern> pattern, std::shared_ptr<const Parts> parts)
    : pattern_(std::move(pattern)), parts_(std::move(parts)) {}

template <int D, int N>
ElementMatrix<D, N>::ElementMatrix(ElementMatrix&& other) noexcept
    : pattern_(std::move(other.pattern_)), parts_(std::move(other.parts_)), mean_diagonal_(other.mean_diagonal_) {
  upper_.swap(other.upper_);
}

template <int D, int N>
ElementMatrix<D, N>& ElementMatrix<D, N>::operator=(ElementMatrix&& other) noexcept {
  pattern_ = std::move(other.pattern_);
  parts_ = std::move(other.parts_);
  upper_.swap(other.upper_);
  mean_diagonal_ = other.mean_diagonal_;
  return *this;
}

template <int D, int N>
ElementMatrix<D, N> ElementMatrix<D, N>::with_pattern_of(const ElementMatrix& other) {
  ElementMatrix matrix(other.pattern_, other.parts_);
  matrix.upper_ = other.upper_;
  std::fill(matrix.upper_.valuePtr(), matrix.upper_.valuePtr() + matrix.upper_.nonZeros(), 0.0);
  return matrix;
}

template <int D, int N>
ElementMatrix<D, N> ElementMatrix<D, N>::taking_storage_of(ElementMatrix* donor) {
  ElementMatrix matrix(donor->pattern_, donor->parts_);
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
  assemble_parts<1>([&](const int* elements, int, Local* locals) { local(elements[0], locals); });
}

template <int D, int N>
void ElementMatrix<D, N>::assemble_batches(const LocalBatchFunction& locals) {
  assemble_parts<kBatch>(locals);
}

template <int D, int N>
template <int Batch, class ComputeLocals>
void ElementMatrix<D, N>::assemble_parts(const ComputeLocals& compute) {
  const Pattern& pattern = *pattern_;
  const int count = tbb::this_task_arena::max_concurrency();
  if (static_cast<int>(parts_->bounds.size()) != count + 1)
    parts_ = split_nonzeros(pattern, upper_.outerIndexPtr(), count);
  const Parts& parts = *parts_;
  double* values = upper_.valuePtr();
  parallel_for_index(count, 1, [&](int p) {
    const int low = parts.bounds[p], high = parts.bounds[p + 1];
    std::fill(values + low, values + high, 0.0);
    Local batch[Batch];
    int elements[Batch];
    for (int first = parts.offsets[p]; first < parts.offsets[p + 1]; first += Batch) {
      const int size = std::min(Batch, parts.offsets[p + 1] - first);
      for (int i = 0; i < size; ++i) {
        const int item = parts.items[first + i];
        elements[i] = item >= 0 ? item : ~item;
      }
      compute(elements, size, batch);
      for (int i = 0; i < size; ++i) {
        const Local& M = batch[i];
        const int* entry = pattern.entries.data() + static_cast<std::size_t>(kSlots) * elements[i];
        if (parts.items[first + i] >= 0) {
          for (int j = 0; j < kLocalSize; ++j)
            for (int r = 0; r <= j; ++r) values[*entry++] += M(r, j);
        } else {
          for (int j = 0; j < kLocalSize; ++j)
            for (int r = 0; r <= j; ++r, ++entry)
              if (*entry >= low && *entry < high) values[*entry] += M(r, j);
        }
      }
    }
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

template Eigen::SparseMatrix<double> block_upper_pattern<2>(const UpperVertexGraph&);
template Eigen::SparseMatrix<double> block_upper_pattern<3>(const UpperVertexGraph&);
template class ElementMatrix<2, 3>;
template class ElementMatrix<3, 4>;

}  // namespace akvf
