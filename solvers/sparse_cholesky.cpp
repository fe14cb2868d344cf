#include "solvers/sparse_cholesky.h"

#include <cholmod.h>

#include <cstring>

#include "framework/error.h"

namespace akvf {

struct SparseCholesky::Impl {
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  cholmod_dense* rhs = nullptr;
  cholmod_dense* solution = nullptr;
  cholmod_dense* workspace_y = nullptr;
  cholmod_dense* workspace_e = nullptr;

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

  // A read-only CHOLMOD view of Eigen's arrays (no copy).
  static cholmod_sparse view(const Eigen::SparseMatrix<double>& upper) {
    cholmod_sparse A{};
    A.nrow = static_cast<size_t>(upper.rows());
    A.ncol = static_cast<size_t>(upper.cols());
    A.nzmax = static_cast<size_t>(upper.nonZeros());
    A.p = const_cast<int*>(upper.outerIndexPtr());
    A.i = const_cast<int*>(upper.innerIndexPtr());
    A.x = const_cast<double*>(upper.valuePtr());
    A.stype = 1;  // symmetric, upper triangle stored
    A.itype = CHOLMOD_INT;
    A.xtype = CHOLMOD_REAL;
    A.dtype = CHOLMOD_DOUBLE;
    A.sorted = 1;
    A.packed = 1;
    return A;
  }
};

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::analyzed() const { return impl_->factor != nullptr; }

double SparseCholesky::factor_nonzeros() const { return impl_->common.lnz; }

double SparseCholesky::factor_flops() const { return impl_->common.fl; }

void SparseCholesky::analyze(const Eigen::SparseMatrix<double>& upper) {
  if (!upper.isCompressed()) throw NumericalError("SparseCholesky: matrix must be compressed");
  cholmod_free_factor(&impl_->factor, &impl_->common);
  cholmod_sparse A = Impl::view(upper);
  impl_->factor = cholmod_analyze(&A, &impl_->common);
  if (!impl_->factor || impl_->common.status < CHOLMOD_OK)
    throw NumericalError("CHOLMOD symbolic analysis failed (status " + std::to_string(impl_->common.status) + ")");
}

void SparseCholesky::factorize(const Eigen::SparseMatrix<double>& upper) {
  if (!analyzed()) analyze(upper);
  cholmod_sparse A = Impl::view(upper);
  cholmod_factorize(&A, impl_->factor, &impl_->common);
  if (impl_->common.status == CHOLMOD_NOT_POSDEF)
    throw NumericalError("matrix is not positive definite (CHOLMOD stopped at column " +
                         std::to_string(impl_->factor->minor) + ")");
  if (impl_->common.status < CHOLMOD_OK)
    throw NumericalError("CHOLMOD numeric factorization failed (status " + std::to_string(impl_->common.status) + ")");
}

void SparseCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd* x) {
  if (!analyzed()) throw NumericalError("SparseCholesky::solve called before factorize");
  const auto n = static_cast<size_t>(b.size());
  if (!impl_->rhs || impl_->rhs->nrow != n) {
    cholmod_free_dense(&impl_->rhs, &impl_->common);
    impl_->rhs = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, &impl_->common);
  }
  std::memcpy(impl_->rhs->x, b.data(), n * sizeof(double));
  if (!cholmod_solve2(CHOLMOD_A, impl_->factor, impl_->rhs, nullptr, &impl_->solution, nullptr,
                      &impl_->workspace_y, &impl_->workspace_e, &impl_->common))
    throw NumericalError("CHOLMOD solve failed (status " + std::to_string(impl_->common.status) + ")");
  x->resize(b.size());
  std::memcpy(x->data(), impl_->solution->x, n * sizeof(double));
}

}  // namespace akvf
