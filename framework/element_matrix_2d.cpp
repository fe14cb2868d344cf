#include "framework/element_matrix_2d.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace akvf {

namespace {

// Local slot layout of one face with corners (c0, c1, c2):
//   slots 0..11: the off-diagonal block of edge k (k = 0: c0-c1, 1: c1-c2,
//                2: c2-c0) as 4 entries (a, b) -> 4k + 2a + b, stored for the
//                ordered pair (min, max) vertex so it lies in the upper triangle;
//   slots 12..20: the diagonal block of corner k, entries (0,0), (0,1), (1,1).
struct SlotTarget {
  int row, col;
};

void slot_targets(const Eigen::MatrixXi& F, int f, SlotTarget out[21]) {
  for (int k = 0; k < 3; ++k) {
    const int p = F(f, k), q = F(f, (k + 1) % 3);
    const int lo = std::min(p, q), hi = std::max(p, q);
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) out[4 * k + 2 * a + b] = {2 * lo + a, 2 * hi + b};
    const int v = F(f, k);
    out[12 + 3 * k + 0] = {2 * v, 2 * v};
    out[12 + 3 * k + 1] = {2 * v, 2 * v + 1};
    out[12 + 3 * k + 2] = {2 * v + 1, 2 * v + 1};
  }
}

template <class Body>
void parallel_for_index(int n, int grain, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<int>(0, n, grain), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i != r.end(); ++i) body(i);
  });
}

}  // namespace

ElementMatrix2D::ElementMatrix2D(const Eigen::MatrixXi& F, int num_vertices) : F_(F) {
  const int n = 2 * num_vertices;
  const int nf = static_cast<int>(F.rows());
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(static_cast<std::size_t>(kSlotsPerFace) * nf);
  SlotTarget targets[kSlotsPerFace];
  for (int f = 0; f < nf; ++f) {
    slot_targets(F, f, targets);
    for (const auto& t : targets) pattern.emplace_back(t.row, t.col, 0.0);
  }
  upper_.resize(n, n);
  upper_.setFromTriplets(pattern.begin(), pattern.end());
  upper_.makeCompressed();

  // Where each face slot lands among the nonzeros.
  std::vector<int> slot_entry(static_cast<std::size_t>(kSlotsPerFace) * nf);
  for (int f = 0; f < nf; ++f) {
    slot_targets(F, f, targets);
    for (int s = 0; s < kSlotsPerFace; ++s) {
      const int* rows = upper_.innerIndexPtr();
      const int begin = upper_.outerIndexPtr()[targets[s].col], end = upper_.outerIndexPtr()[targets[s].col + 1];
      slot_entry[kSlotsPerFace * f + s] =
          static_cast<int>(std::lower_bound(rows + begin, rows + end, targets[s].row) - rows);
    }
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
  face_buffer_.resize(slot_entry.size());
}

void ElementMatrix2D::assemble(const LocalFunction& local) {
  const int nf = static_cast<int>(F_.rows());
  parallel_for_index(nf, 512, [&](int f) {
    Local M;
    local(f, &M);
    double* out = face_buffer_.data() + kSlotsPerFace * f;
    for (int k = 0; k < 3; ++k) {
      const int a = k, b = (k + 1) % 3;
      // The block of the edge's (min, max) vertex pair, in the upper triangle.
      const bool in_order = F_(f, a) < F_(f, b);
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c)
          out[4 * k + 2 * r + c] = in_order ? M(std::min(2 * a + r, 2 * b + c), std::max(2 * a + r, 2 * b + c))
                                            : M(std::min(2 * b + r, 2 * a + c), std::max(2 * b + r, 2 * a + c));
      out[12 + 3 * k + 0] = M(2 * k, 2 * k);
      out[12 + 3 * k + 1] = M(2 * k, 2 * k + 1);
      out[12 + 3 * k + 2] = M(2 * k + 1, 2 * k + 1);
    }
  });
  double* values = upper_.valuePtr();
  parallel_for_index(static_cast<int>(upper_.nonZeros()), 4096, [&](int e) {
    double sum = 0;
    for (int i = gather_offsets_[e]; i < gather_offsets_[e + 1]; ++i) sum += face_buffer_[gather_sources_[i]];
    values[e] = sum;
  });
  double trace = 0;
  for (int e : diagonal_entries_) trace += values[e];
  mean_diagonal_ = trace / static_cast<double>(diagonal_entries_.size());
}

void ElementMatrix2D::add_to_diagonal(double shift) {
  for (int e : diagonal_entries_) upper_.valuePtr()[e] += shift;
}

Eigen::SparseMatrix<double> ElementMatrix2D::full() const {
  Eigen::SparseMatrix<double> strict_lower = upper_.transpose();
  strict_lower.prune([](int row, int col, double) { return row > col; });
  return upper_ + strict_lower;
}

}  // namespace akvf
