#pragma once
// The dense part of the triangular solves (supernodal_solve.h) on one
// supernode's block: column-major, rows x columns, its diagonal triangle
// L11 on top of the rows below, L21. Both go by panels of four columns, so
// that the rows below a panel are read once per panel, not once per column.

namespace akvf {

// w = [y; 0] (rows entries) becomes [L11^-1 y; -L21 L11^-1 y].
void forward_block(int rows, int columns, const double* L, double* w);

// w = [x; the solution's entries of the rows below] has its first `columns`
// entries replaced by L11^-T (x - L21^T w(columns..rows)).
void backward_block(int rows, int columns, const double* L, double* w);

}  // namespace akvf
