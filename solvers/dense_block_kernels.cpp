#include "solvers/dense_block_kernels.h"

#include <cmath>
#include <cstddef>
#include <string>

#include "akvf/error.h"

// BLAS and LAPACK (Fortran interface, 32-bit integers: Debian's OpenBLAS and
// reference BLAS, the ones CHOLMOD calls).
extern "C" {
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc);
void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
            const int* ldc);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
}

namespace akvf {

void loop_update(int rows, int columns, int k, const double* L, int ld, double* C) {
  // Column j of C is a sum of k columns of L scaled by row j's entries,
  // four at a time (contiguous inner loops; C's column read and written
  // once per four).
  const auto column = [&](int p) { return L + static_cast<std::size_t>(p) * ld; };
  for (int j = 0; j < columns; ++j) {
    double* c = C + static_cast<std::size_t>(j) * rows;
    for (int i = j; i < rows; ++i) c[i] = 0;
    int p = 0;
    for (; p + 4 <= k; p += 4) {
      const double *l0 = column(p), *l1 = column(p + 1), *l2 = column(p + 2), *l3 = column(p + 3);
      const double a0 = l0[j], a1 = l1[j], a2 = l2[j], a3 = l3[j];
      for (int i = j; i < rows; ++i) c[i] += l0[i] * a0 + l1[i] * a1 + l2[i] * a2 + l3[i] * a3;
    }
    for (; p < k; ++p) {
      const double* l = column(p);
      const double a = l[j];
      for (int i = j; i < rows; ++i) c[i] += l[i] * a;
    }
  }
}

void blas_update(int rows, int columns, int k, const double* L, int ld, double* C) {
  const double one = 1, zero = 0;
  const int below = rows - columns;
  dsyrk_("L", "N", &columns, &k, &one, L, &ld, &zero, C, &rows);
  if (below > 0) dgemm_("N", "T", &below, &columns, &k, &one, L + columns, &ld, L, &ld, &zero, C + columns, &rows);
}

int loop_cholesky(int rows, int columns, double* block) {
  // Left-looking, by columns: column j less the earlier columns' parts,
  // then divided by its pivot's square root; the rows below the diagonal
  // block go along (they are L21's rows).
  for (int j = 0; j < columns; ++j) {
    double* c = block + static_cast<std::size_t>(j) * rows;
    for (int p = 0; p < j; ++p) {
      const double* l = block + static_cast<std::size_t>(p) * rows;
      const double a = l[j];
      for (int i = j; i < rows; ++i) c[i] -= l[i] * a;
    }
    if (!(c[j] > 0)) return j;
    const double pivot = std::sqrt(c[j]);
    c[j] = pivot;
    for (int i = j + 1; i < rows; ++i) c[i] /= pivot;
  }
  return -1;
}

int blas_cholesky(int rows, int columns, double* block) {
  int info = 0;
  dpotrf_("L", &columns, block, &rows, &info);
  if (info < 0) throw NumericalError("dpotrf rejected argument " + std::to_string(-info));
  if (info > 0) return info - 1;
  const int below = rows - columns;
  if (below <= 0) return -1;
  const double one = 1;
  dtrsm_("R", "L", "T", "N", &below, &columns, &one, block, &rows, block + columns, &rows);
  return -1;
}

void block_update(int rows, int columns, int k, const double* L, int ld, double* C) {
  if (update_flops(rows, columns, k) < kLoopUpdateFlops)
    loop_update(rows, columns, k, L, ld, C);
  else
    blas_update(rows, columns, k, L, ld, C);
}

int block_cholesky(int rows, int columns, double* block) {
  return cholesky_flops(rows, columns) < kLoopCholeskyFlops ? loop_cholesky(rows, columns, block)
                                                    : blas_cholesky(rows, columns, block);
}

}  // namespace akvf
