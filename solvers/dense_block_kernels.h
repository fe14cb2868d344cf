#pragma once
// The two dense operations of a supernodal Cholesky factorization
// (supernodal_factorization.h) on one supernode's block, by BLAS/LAPACK for
// large blocks and by plain loops for small ones.
//
// Why the loops: each call of OpenBLAS's dsyrk, dtrsm or dpotrf takes its
// work buffer from one pool guarded by a process-wide mutex
// (blas_memory_alloc). With both cores factoring at once and most
// supernodes of a mesh's K a few columns wide, the two cores meet at that
// mutex all the time: `perf record` on hilbert_b's factorization put about
// 30 % of its samples in the mutex and the futex calls behind it. The loops
// take no lock and pack nothing: both operations are one kernel, the lower
// part of L L^T by tiles of eight rows by four columns whose sums stay in
// vector registers over L's columns (the Cholesky factorization
// left-looking by panels of four columns), compiled for any x86-64 and for
// x86-64-v3 (AVX2, FMA), the processor's choice taken at load time. Without
// cache blocking they fall behind BLAS on large blocks. Each operation runs
// as loops below the size where the BLAS calls become faster with both
// cores calling them at once (the factorization's case), measured by the
// `DenseBlock` benchmarks (blocks of 2c rows by c columns): between c = 48
// and 64 for an update (330 000 and 790 000 flops), between 96 and 128 for
// a block's Cholesky factorization (1.2 and 2.8 million flops).
namespace akvf {

constexpr double kLoopUpdateFlops = 5e5;
constexpr double kLoopCholeskyFlops = 2e6;

// C(i, j) = sum_p L(i, p) L(j, p) for 0 <= j < columns, j <= i < rows: the
// lower part of an earlier supernode's update of the supernode being built
// (L: its rows reaching that supernode, column-major, leading dimension ld,
// k columns; the first `columns` rows are inside the supernode). C is
// column-major with leading dimension rows. BLAS: dsyrk on the first
// `columns` rows, dgemm below them (CHOLMOD's calls).
void block_update(int rows, int columns, int k, const double* L, int ld, double* C);

// Factors a supernode's block in place: its diagonal block A11 (columns x
// columns) into L11 L11^T, the rows below into L21 = A21 L11^-T. The block is
// column-major, rows x columns, leading dimension rows. Returns -1, or the
// first column (0-based) whose pivot is not positive. BLAS: dpotrf, then
// dtrsm.
int block_cholesky(int rows, int columns, double* block);

// Flops of the two operations (what block_update and block_cholesky compare
// with the limits above).
inline double update_flops(int rows, int columns, int k) {
  return static_cast<double>(k) * columns * (2.0 * rows - columns);
}
inline double cholesky_flops(int rows, int columns) {
  const double c = columns, b = rows - columns;
  return c * c * c / 3 + b * c * c;
}

// Each way alone (tests and benchmarks).
void loop_update(int rows, int columns, int k, const double* L, int ld, double* C);
void blas_update(int rows, int columns, int k, const double* L, int ld, double* C);
int loop_cholesky(int rows, int columns, double* block);
int blas_cholesky(int rows, int columns, double* block);

}  // namespace akvf
