#pragma once
// The dense part of the triangular solves (supernodal_solve.h) on one
// supernode's block: column-major, rows x columns, its diagonal triangle
// L11 on top of the rows below, L21. Both go by panels of four columns, so
// that the rows below a panel are read once per panel, not once per column.

namespace akvf {

// An entry of L rounded to single precision, stored over the factor's
// doubles (SparseCholesky::round_factor_to_single): it may alias them.
struct [[gnu::may_alias]] SingleEntry {
  float value;
};

// w = [y; 0] (rows entries) becomes [L11^-1 y; -L21 L11^-1 y]. L's entries
// in double or single precision (widened to double as they are read; w and
// the sums in double).
void forward_block(int rows, int columns, const double* L, double* w);
void forward_block(int rows, int columns, const SingleEntry* L, double* w);

// w = [x; the solution's entries of the rows below] has its first `columns`
// entries replaced by L11^-T (x - L21^T w(columns..rows)).
void backward_block(int rows, int columns, const double* L, double* w);
void backward_block(int rows, int columns, const SingleEntry* L, double* w);

}  // namespace akvf
