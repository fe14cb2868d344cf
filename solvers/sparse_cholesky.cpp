#include "solvers/sparse_cholesky.h"

#include <cholmod.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

#include "framework/process/error.h"
#include "solvers/supernodal_solve.h"

namespace akvf {

// How the matrix reaches CHOLMOD. Given the upper triangle of A and a
// fill-reducing permutation P (found once by cholmod_analyze), we keep the
// lower triangle of P A P^T ourselves, in the compressed form CHOLMOD's
// supernodal factorization reads directly when the ordering is natural
// (stype < 0). cholmod_factorize on A with a permutation would instead build a
// permuted transpose, with its allocations, at every call; here each
// factorization only scatters the values through a fixed index map.
//
// The pattern part (permutation, lower triangle's indices, index map) is
// immutable after the analysis and shared by copies of it (copy_analysis:
// akvf-newton's Newton phase and the cache of symbolic_analysis_cache.h), and
// the values are allocated at the first factorization, so an analysis kept
// for later costs no values (at 10 M triangles the lower triangle's values
// are 0.6 GB and its indices 0.9 GB).
struct PermutedPattern {
  std::vector<int> permutation;  // row a of P A P^T is row permutation[a] of A
  std::vector<int> lower_column_start, lower_row;
  std::vector<int> value_map;  // nonzero k of the upper input -> its slot in the lower triangle
};

struct SparseCholesky::Impl {
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  cholmod_dense* rhs = nullptr;
  cholmod_dense* solution = nullptr;
  cholmod_dense* workspace_y = nullptr;
  cholmod_dense* workspace_e = nullptr;

  std::shared_ptr<const PermutedPattern> pattern;
  std::vector<double> lower_value;  // empty until the first factorization
  std::vector<double> permuted_rhs;
  std::unique_ptr<SupernodalSolve> supernodal_solver;  // reset with each analysis

  Impl() {
    cholmod_start(&common);
    common.print = 0;  // errors are reported through exceptions, not stderr
  }
  ~Impl() {
    cholmod_free_factor(&factor, &common);
    cholmod_free_dense(&rhs, &common);
    cholmod_free_dense(&solution, &common);
    cholmod_free_dense(&workspace_y, &common);
    cholmod_free_dense(&workspace_e, &common);
    cholmod_finish(&common);
  }

  static cholmod_sparse view(int n, int* column_start, int* row, double* value, int stype) {
    cholmod_sparse A{};
    A.nrow = A.ncol = static_cast<size_t>(n);
    A.nzmax = static_cast<size_t>(column_start[n]);
    A.p = column_start;
    A.i = row;
    A.x = value;
    A.stype = stype;
    A.itype = CHOLMOD_INT;
    A.xtype = CHOLMOD_REAL;
    A.dtype = CHOLMOD_DOUBLE;
    A.sorted = 1;
    A.packed = 1;
    return A;
  }

  // CHOLMOD reads the indices only (const_cast: its structs are not const).
  cholmod_sparse lower_view() {
    const int n = static_cast<int>(pattern->permutation.size());
    cholmod_sparse A = view(n, const_cast<int*>(pattern->lower_column_start.data()),
                            const_cast<int*>(pattern->lower_row.data()), lower_value.data(), -1);
    if (lower_value.empty()) A.xtype = CHOLMOD_PATTERN;
    return A;
  }

  void check(const char* what) {
    if (common.status < CHOLMOD_OK)
      throw NumericalError(std::string("CHOLMOD ") + what + " failed (status " + std::to_string(common.status) + ")");
  }

  // Our supernodal triangular solves (solvers/supernodal_solve.h), set up
  // for the factor's structure at the first solve after an analysis.
  SupernodalSolve& supernodal_solve() {
    if (!supernodal_solver)
      supernodal_solver = std::make_unique<SupernodalSolve>(SupernodalStructure{
          static_cast<int>(factor->nsuper), static_cast<const int*>(factor->super), static_cast<const int*>(factor->pi),
          static_cast<const int*>(factor->px), static_cast<const int*>(factor->s)});
    return *supernodal_solver;
  }

  // The upper-triangular pattern of the graph whose nodes are the blocks of
  // block_size consecutive unknowns (block size 1: the pattern of `upper`).
  static void block_pattern(const Eigen::SparseMatrix<double>& upper, int block_size, std::vector<int>* column_start,
                            std::vector<int>* row) {
    const int blocks = static_cast<int>(upper.rows()) / block_size;
    const int* start = upper.outerIndexPtr();
    const int* rows = upper.innerIndexPtr();
    column_start->assign(1, 0);
    row->clear();
    std::vector<int> last_seen(blocks, -1);
    for (int J = 0; J < blocks; ++J) {
      const std::size_t first = row->size();
      for (int j = J * block_size; j < (J + 1) * block_size; ++j)
        for (int k = start[j]; k < start[j + 1]; ++k) {
          const int I = rows[k] / block_size;
          if (I <= J && last_seen[I] != J) {
            last_seen[I] = J;
            row->push_back(I);
          }
        }
      std::sort(row->begin() + static_cast<std::ptrdiff_t>(first), row->end());
      column_start->push_back(static_cast<int>(row->size()));
    }
  }

  // The lower triangle of P A P^T from the pattern of `upper`.
  static std::shared_ptr<const PermutedPattern> permuted_lower(const Eigen::SparseMatrix<double>& upper,
                                                               std::vector<int> permutation) {
    const int n = static_cast<int>(upper.rows());
    auto built = std::make_shared<PermutedPattern>();
    std::vector<int>& lower_column_start = built->lower_column_start;
    std::vector<int>& lower_row = built->lower_row;
    std::vector<int>& value_map = built->value_map;
    std::vector<int> inverse(n);
    for (int a = 0; a < n; ++a) inverse[permutation[a]] = a;
    const int* start = upper.outerIndexPtr();
    const int* rows = upper.innerIndexPtr();
    struct Entry {
      int column, row, source;
    };
    std::vector<Entry> entries;
    entries.reserve(upper.nonZeros());
    for (int j = 0; j < n; ++j)
      for (int k = start[j]; k < start[j + 1]; ++k) {
        const int a = inverse[rows[k]], b = inverse[j];
        entries.push_back({std::min(a, b), std::max(a, b), k});
      }
    // Sorted by (column, row) in linear time: a stable counting sort by row,
    // then one by column.
    const auto stable_bucket_sort = [n](std::vector<Entry>& items, int Entry::*key) {
      std::vector<int> offset(n + 1, 0);
      for (const Entry& e : items) ++offset[e.*key + 1];
      for (int i = 0; i < n; ++i) offset[i + 1] += offset[i];
      std::vector<Entry> sorted(items.size());
      for (const Entry& e : items) sorted[offset[e.*key]++] = e;
      items.swap(sorted);
    };
    stable_bucket_sort(entries, &Entry::row);
    stable_bucket_sort(entries, &Entry::column);
    lower_column_start.assign(n + 1, 0);
    lower_row.resize(entries.size());
    value_map.resize(entries.size());
    for (std::size_t e = 0; e < entries.size(); ++e) {
      ++lower_column_start[entries[e].column + 1];
      lower_row[e] = entries[e].row;
      value_map[entries[e].source] = static_cast<int>(e);
    }
    for (int j = 0; j < n; ++j) lower_column_start[j + 1] += lower_column_start[j];
    built->permutation = std::move(permutation);
    return built;
  }
};

std::string cholmod_version() {
  return std::to_string(CHOLMOD_MAIN_VERSION) + "." + std::to_string(CHOLMOD_SUB_VERSION) + "." +
         std::to_string(CHOLMOD_SUBSUB_VERSION);
}

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::analyzed() const { return impl_->factor != nullptr; }

bool SparseCholesky::supernodal() const { return analyzed() && impl_->factor->is_super; }

double SparseCholesky::factor_nonzeros() const { return impl_->common.lnz; }

double SparseCholesky::factor_flops() const { return impl_->common.fl; }

double SparseCholesky::serial_solve_share() { return supernodal() ? impl_->supernodal_solve().top_share() : 1.0; }

void SparseCholesky::analyze(const Eigen::SparseMatrix<double>& upper, int block_size) {
  if (!upper.isCompressed() || upper.rows() != upper.cols())
    throw NumericalError("SparseCholesky: matrix must be square and compressed");
  if (block_size < 1 || upper.rows() % block_size != 0)
    throw NumericalError("SparseCholesky: block size must divide the matrix size");
  Impl& m = *impl_;
  cholmod_free_factor(&m.factor, &m.common);
  m.supernodal_solver.reset();
  const int n = static_cast<int>(upper.rows());

  // 1. CHOLMOD's own choice of fill-reducing ordering (AMD, or METIS when
  //    AMD fills in badly), postordered, found on the graph of the blocks
  //    (vertices) and expanded to their unknowns: the same elimination order
  //    as on the scalar graph, at a fraction of the analysis time.
  m.common.nmethods = 0;
  m.common.postorder = 1;
  std::vector<int> block_start, block_row;
  m.block_pattern(upper, block_size, &block_start, &block_row);
  const int blocks = n / block_size;
  cholmod_sparse A = Impl::view(blocks, block_start.data(), block_row.data(), nullptr, 1);
  A.xtype = CHOLMOD_PATTERN;
  cholmod_factor* ordering = cholmod_analyze(&A, &m.common);
  m.check("symbolic analysis");
  const int* perm = static_cast<const int*>(ordering->Perm);
  std::vector<int> permutation(n);
  for (int a = 0; a < blocks; ++a)
    for (int c = 0; c < block_size; ++c) permutation[a * block_size + c] = perm[a] * block_size + c;
  cholmod_free_factor(&ordering, &m.common);

  // 2. The permuted matrix, analyzed again in its natural order (the
  //    postorder is already part of the permutation).
  m.pattern = Impl::permuted_lower(upper, std::move(permutation));
  m.lower_value.clear();
  m.common.nmethods = 1;
  m.common.method[0].ordering = CHOLMOD_NATURAL;
  m.common.postorder = 0;
  cholmod_sparse B = m.lower_view();
  m.factor = cholmod_analyze(&B, &m.common);
  m.check("symbolic analysis of the permuted matrix");
}

void SparseCholesky::copy_analysis(const SparseCholesky& other) {
  const Impl& from = *other.impl_;
  if (!other.analyzed() || from.factor->xtype != CHOLMOD_PATTERN)
    throw NumericalError("SparseCholesky::copy_analysis: the source must be analyzed and not factored");
  Impl& m = *impl_;
  cholmod_free_factor(&m.factor, &m.common);
  m.supernodal_solver.reset();
  // The settings analyze() leaves, so that factorize() runs as after it.
  m.common.nmethods = 1;
  m.common.method[0].ordering = CHOLMOD_NATURAL;
  m.common.postorder = 0;
  m.common.lnz = from.common.lnz;
  m.common.fl = from.common.fl;
  m.factor = cholmod_copy_factor(from.factor, &m.common);
  m.check("copy of a symbolic analysis");
  m.pattern = from.pattern;
  m.lower_value.clear();
}

void SparseCholesky::factorize(const Eigen::SparseMatrix<double>& upper) {
  if (!analyzed()) analyze(upper);
  Impl& m = *impl_;
  const std::vector<int>& value_map = m.pattern->value_map;
  if (static_cast<std::size_t>(upper.nonZeros()) != value_map.size())
    throw NumericalError("SparseCholesky: the sparsity pattern changed since analyze()");
  m.lower_value.resize(value_map.size());
  const double* values = upper.valuePtr();
  for (std::size_t k = 0; k < value_map.size(); ++k) m.lower_value[value_map[k]] = values[k];
  cholmod_sparse B = m.lower_view();
  cholmod_factorize(&B, m.factor, &m.common);
  if (m.common.status == CHOLMOD_NOT_POSDEF)
    throw NumericalError("matrix is not positive definite (CHOLMOD stopped at column " +
                         std::to_string(m.factor->minor) + ")");
  m.check("numeric factorization");
}

void SparseCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd* x) {
  if (!analyzed()) throw NumericalError("SparseCholesky::solve called before factorize");
  Impl& m = *impl_;
  const auto n = static_cast<size_t>(b.size());
  const std::vector<int>& permutation = m.pattern->permutation;
  if (n != permutation.size()) throw NumericalError("SparseCholesky::solve: right-hand side has the wrong size");
  m.permuted_rhs.resize(n);
  for (size_t a = 0; a < n; ++a) m.permuted_rhs[a] = b[permutation[a]];  // c = P b
  if (m.factor->is_super) {
    m.supernodal_solve().solve(static_cast<const double*>(m.factor->x), m.permuted_rhs.data());
  } else {
    if (!m.rhs) m.rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &m.common);
    std::copy(m.permuted_rhs.begin(), m.permuted_rhs.end(), static_cast<double*>(m.rhs->x));
    if (!cholmod_solve2(CHOLMOD_A, m.factor, m.rhs, nullptr, &m.solution, nullptr, &m.workspace_y, &m.workspace_e,
                        &m.common))
      m.check("solve");
    const double* z = static_cast<const double*>(m.solution->x);
    std::copy(z, z + n, m.permuted_rhs.begin());
  }
  x->resize(b.size());
  for (size_t a = 0; a < n; ++a) (*x)[permutation[a]] = m.permuted_rhs[a];  // x = P^T z
}

}  // namespace akvf
