#include "solvers/sparse_cholesky.h"

#include <cholmod.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "framework/error.h"

namespace akvf {

// How the matrix reaches CHOLMOD. Given the upper triangle of A and a
// fill-reducing permutation P (found once by cholmod_analyze), we keep the
// lower triangle of P A P^T ourselves, in the compressed form CHOLMOD's
// supernodal factorization reads directly when the ordering is natural
// (stype < 0). cholmod_factorize on A with a permutation would instead build a
// permuted transpose, with its allocations, at every call; here each
// factorization only scatters the values through a fixed index map.
struct SparseCholesky::Impl {
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  cholmod_dense* rhs = nullptr;
  cholmod_dense* solution = nullptr;
  cholmod_dense* workspace_y = nullptr;
  cholmod_dense* workspace_e = nullptr;

  std::vector<int> permutation;  // row a of P A P^T is row permutation[a] of A
  std::vector<int> lower_column_start, lower_row;
  std::vector<double> lower_value;
  std::vector<int> value_map;  // nonzero k of the upper input -> its slot in lower_value
  std::vector<double> permuted_rhs;

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

  cholmod_sparse lower_view() {
    return view(static_cast<int>(permutation.size()), lower_column_start.data(), lower_row.data(), lower_value.data(),
                -1);
  }

  void check(const char* what) {
    if (common.status < CHOLMOD_OK)
      throw NumericalError(std::string("CHOLMOD ") + what + " failed (status " + std::to_string(common.status) + ")");
  }

  // Builds the lower triangle of P A P^T from the pattern of `upper`.
  void build_permuted_lower(const Eigen::SparseMatrix<double>& upper) {
    const int n = static_cast<int>(upper.rows());
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
    std::sort(entries.begin(), entries.end(),
              [](const Entry& x, const Entry& y) { return std::tie(x.column, x.row) < std::tie(y.column, y.row); });
    lower_column_start.assign(n + 1, 0);
    lower_row.resize(entries.size());
    lower_value.assign(entries.size(), 0.0);
    value_map.resize(entries.size());
    for (std::size_t e = 0; e < entries.size(); ++e) {
      ++lower_column_start[entries[e].column + 1];
      lower_row[e] = entries[e].row;
      value_map[entries[e].source] = static_cast<int>(e);
    }
    for (int j = 0; j < n; ++j) lower_column_start[j + 1] += lower_column_start[j];
  }
};

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::analyzed() const { return impl_->factor != nullptr; }

double SparseCholesky::factor_nonzeros() const { return impl_->common.lnz; }

double SparseCholesky::factor_flops() const { return impl_->common.fl; }

void SparseCholesky::analyze(const Eigen::SparseMatrix<double>& upper) {
  if (!upper.isCompressed() || upper.rows() != upper.cols())
    throw NumericalError("SparseCholesky: matrix must be square and compressed");
  Impl& m = *impl_;
  cholmod_free_factor(&m.factor, &m.common);
  const int n = static_cast<int>(upper.rows());

  // 1. CHOLMOD's own choice of fill-reducing ordering (AMD, or METIS when
  //    AMD fills in badly), postordered.
  m.common.nmethods = 0;
  m.common.postorder = 1;
  cholmod_sparse A = Impl::view(n, const_cast<int*>(upper.outerIndexPtr()), const_cast<int*>(upper.innerIndexPtr()),
                                const_cast<double*>(upper.valuePtr()), 1);
  cholmod_factor* ordering = cholmod_analyze(&A, &m.common);
  m.check("symbolic analysis");
  const int* perm = static_cast<const int*>(ordering->Perm);
  m.permutation.assign(perm, perm + n);
  cholmod_free_factor(&ordering, &m.common);

  // 2. The permuted matrix, analyzed again in its natural order (the
  //    postorder is already part of the permutation).
  m.build_permuted_lower(upper);
  m.common.nmethods = 1;
  m.common.method[0].ordering = CHOLMOD_NATURAL;
  m.common.postorder = 0;
  cholmod_sparse B = m.lower_view();
  m.factor = cholmod_analyze(&B, &m.common);
  m.check("symbolic analysis of the permuted matrix");
  m.permuted_rhs.resize(n);
}

void SparseCholesky::factorize(const Eigen::SparseMatrix<double>& upper) {
  if (!analyzed()) analyze(upper);
  Impl& m = *impl_;
  if (static_cast<std::size_t>(upper.nonZeros()) != m.value_map.size())
    throw NumericalError("SparseCholesky: the sparsity pattern changed since analyze()");
  const double* values = upper.valuePtr();
  for (std::size_t k = 0; k < m.value_map.size(); ++k) m.lower_value[m.value_map[k]] = values[k];
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
  if (n != m.permutation.size()) throw NumericalError("SparseCholesky::solve: right-hand side has the wrong size");
  if (!m.rhs) m.rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &m.common);
  double* c = static_cast<double*>(m.rhs->x);
  for (size_t a = 0; a < n; ++a) c[a] = b[m.permutation[a]];  // c = P b
  if (!cholmod_solve2(CHOLMOD_A, m.factor, m.rhs, nullptr, &m.solution, nullptr, &m.workspace_y, &m.workspace_e,
                      &m.common))
    m.check("solve");
  x->resize(b.size());
  const double* z = static_cast<const double*>(m.solution->x);
  for (size_t a = 0; a < n; ++a) (*x)[m.permutation[a]] = z[a];  // x = P^T z
}

}  // namespace akvf
