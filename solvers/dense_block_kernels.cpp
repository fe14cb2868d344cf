#include "solvers/dense_block_kernels.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "akvf/error.h"
#include "solvers/vector_lanes.h"

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

namespace {

// One tile of lower_product: rows i0 .. i0 + 4 V - 1 (a = L + i0) by the
// columns j0 .. j0 + NC - 1 (b = L + j0), c = C + j0 ldc + i0; `offset` =
// i0 - j0, so row r of column q is in the lower part when r + offset >= q.
// The 4 V x NC sums stay in registers over the k columns of L.
template <int V, int NC, bool kSubtract>
[[gnu::always_inline]] inline void product_tile(int k, const double* a, const double* b, int ld, double* c, int ldc,
                                                int offset) {
  Lanes sum[NC][V];
#pragma GCC unroll 4
  for (int q = 0; q < NC; ++q)
#pragma GCC unroll 2
    for (int v = 0; v < V; ++v) sum[q][v] = Lanes{0, 0, 0, 0};
  for (int p = 0; p < k; ++p) {
    const double* ap = a + static_cast<std::size_t>(p) * ld;
    const double* bp = b + static_cast<std::size_t>(p) * ld;
    Lanes x[V];
#pragma GCC unroll 2
    for (int v = 0; v < V; ++v) x[v] = lanes_at(ap + 4 * v).value;
#pragma GCC unroll 4
    for (int q = 0; q < NC; ++q) {
      const double scale = bp[q];
#pragma GCC unroll 2
      for (int v = 0; v < V; ++v) sum[q][v] += x[v] * scale;
    }
  }
  if (offset >= NC - 1) {  // every row of the tile is in the lower part
#pragma GCC unroll 4
    for (int q = 0; q < NC; ++q)
#pragma GCC unroll 2
      for (int v = 0; v < V; ++v) {
        double* target = c + static_cast<std::size_t>(q) * ldc + 4 * v;
        if constexpr (kSubtract)
          lanes_at(target).value -= sum[q][v];
        else
          lanes_at(target).value = sum[q][v];
      }
    return;
  }
#pragma GCC unroll 4
  for (int q = 0; q < NC; ++q)
#pragma GCC unroll 2
    for (int v = 0; v < V; ++v)
#pragma GCC unroll 4
      for (int l = 0; l < 4; ++l) {
        if (4 * v + l + offset < q) continue;
        double& target = c[static_cast<std::size_t>(q) * ldc + 4 * v + l];
        target = kSubtract ? target - sum[q][v][l] : sum[q][v][l];
      }
}

// Rows i0 .. rows - 1 (fewer than four) of a column block, one sum at a time.
template <bool kSubtract>
[[gnu::always_inline]] inline void product_rows(int i0, int rows, int j0, int nc, int k, const double* L, int ld,
                                                double* C, int ldc) {
  for (int q = 0; q < nc; ++q)
    for (int i = std::max(i0, j0 + q); i < rows; ++i) {
      double sum = 0;
      for (int p = 0; p < k; ++p)
        sum += L[static_cast<std::size_t>(p) * ld + i] * L[static_cast<std::size_t>(p) * ld + j0 + q];
      double& target = C[static_cast<std::size_t>(j0 + q) * ldc + i];
      target = kSubtract ? target - sum : sum;
    }
}

template <int NC, bool kSubtract>
[[gnu::always_inline]] inline void product_column_block(int rows, int j0, int k, const double* L, int ld, double* C,
                                                        int ldc) {
  double* c = C + static_cast<std::size_t>(j0) * ldc;
  int i0 = j0;
  for (; i0 + 8 <= rows; i0 += 8) product_tile<2, NC, kSubtract>(k, L + i0, L + j0, ld, c + i0, ldc, i0 - j0);
  if (i0 + 4 <= rows) {
    product_tile<1, NC, kSubtract>(k, L + i0, L + j0, ld, c + i0, ldc, i0 - j0);
    i0 += 4;
  }
  if (i0 < rows) product_rows<kSubtract>(i0, rows, j0, NC, k, L, ld, C, ldc);
}

// C(i, j) = sum_p L(i, p) L(j, p) (kSubtract: C(i, j) -= it) for
// 0 <= j < columns, j <= i < rows, p < k; L column-major with leading
// dimension ld, C with ldc. Column blocks of four, row tiles of eight.
template <bool kSubtract>
[[gnu::always_inline]] inline void lower_product(int rows, int columns, int k, const double* L, int ld, double* C,
                                                 int ldc) {
  int j0 = 0;
  for (; j0 + 4 <= columns; j0 += 4) product_column_block<4, kSubtract>(rows, j0, k, L, ld, C, ldc);
  switch (columns - j0) {
    case 3:
      product_column_block<3, kSubtract>(rows, j0, k, L, ld, C, ldc);
      break;
    case 2:
      product_column_block<2, kSubtract>(rows, j0, k, L, ld, C, ldc);
      break;
    case 1:
      product_column_block<1, kSubtract>(rows, j0, k, L, ld, C, ldc);
      break;
    default:
      break;
  }
}

}  // namespace

AKVF_FOR_EACH_X86_LEVEL void loop_update(int rows, int columns, int k, const double* L, int ld, double* C) {
  lower_product<false>(rows, columns, k, L, ld, C, rows);
}

void blas_update(int rows, int columns, int k, const double* L, int ld, double* C) {
  const double one = 1, zero = 0;
  const int below = rows - columns;
  dsyrk_("L", "N", &columns, &k, &one, L, &ld, &zero, C, &rows);
  if (below > 0) dgemm_("N", "T", &below, &columns, &k, &one, L + columns, &ld, L, &ld, &zero, C + columns, &rows);
}

AKVF_FOR_EACH_X86_LEVEL int loop_cholesky(int rows, int columns, double* block) {
  // Left-looking, by panels of four columns: a panel less the earlier
  // columns' parts (one lower_product), then its own columns one by one,
  // each less the panel's earlier ones and scaled by the inverse of its
  // pivot's square root. The rows below the diagonal block go along (they
  // are L21's rows).
  for (int j0 = 0; j0 < columns; j0 += 4) {
    const int width = std::min(4, columns - j0);
    lower_product<true>(rows - j0, width, j0, block + j0, rows, block + static_cast<std::size_t>(j0) * rows + j0, rows);
    for (int j = j0; j < j0 + width; ++j) {
      double* c = block + static_cast<std::size_t>(j) * rows;
      for (int p = j0; p < j; ++p) {
        const double* l = block + static_cast<std::size_t>(p) * rows;
        const double a = l[j];
        for (int i = j; i < rows; ++i) c[i] -= l[i] * a;
      }
      if (!(c[j] > 0)) return j;
      const double pivot = std::sqrt(c[j]), inverse = 1 / pivot;
      c[j] = pivot;
      for (int i = j + 1; i < rows; ++i) c[i] *= inverse;
    }
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
