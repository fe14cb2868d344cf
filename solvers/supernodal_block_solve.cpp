#include "solvers/supernodal_block_solve.h"

#include <algorithm>
#include <cstddef>

#include "solvers/vector_lanes.h"

namespace akvf {

namespace {

template <class Value>
const Value* column_of(const Value* L, int rows, int j) {
  return L + static_cast<std::size_t>(j) * rows;
}

// An entry of L as a double.
[[gnu::always_inline]] inline double widen(double x) { return x; }
[[gnu::always_inline]] inline double widen(SingleEntry x) { return x.value; }
// sum += (p[0..3]) x, in lanes (no vector by value: vector_lanes.h).
[[gnu::always_inline]] inline void multiply_add(const double* p, const Lanes& x, Lanes& sum) {
  sum += lanes_at(p).value * x;
}
[[gnu::always_inline]] inline void multiply_add(const SingleEntry* p, const Lanes& x, Lanes& sum) {
  sum += __builtin_convertvector(floats_at(&p->value).value, Lanes) * x;
}

template <class Value>
[[gnu::always_inline]] inline void forward_panels(int rows, int columns, const Value* __restrict L,
                                                  double* __restrict w) {
  for (int j0 = 0; j0 < columns; j0 += 4) {
    const int width = std::min(4, columns - j0), below = j0 + width;
    for (int j = j0; j < below; ++j) {  // the panel's triangle
      const Value* column = column_of(L, rows, j);
      w[j] /= widen(column[j]);
      for (int i = j + 1; i < below; ++i) w[i] -= w[j] * widen(column[i]);
    }
    if (width == 4) {  // the rows below, less the panel's four columns at once
      const Value *l0 = column_of(L, rows, j0), *l1 = column_of(L, rows, j0 + 1), *l2 = column_of(L, rows, j0 + 2),
                  *l3 = column_of(L, rows, j0 + 3);
      const double a0 = w[j0], a1 = w[j0 + 1], a2 = w[j0 + 2], a3 = w[j0 + 3];
      for (int i = below; i < rows; ++i)
        w[i] -= (widen(l0[i]) * a0 + widen(l1[i]) * a1) + (widen(l2[i]) * a2 + widen(l3[i]) * a3);
    } else {
      for (int j = j0; j < below; ++j) {
        const Value* column = column_of(L, rows, j);
        const double a = w[j];
        for (int i = below; i < rows; ++i) w[i] -= widen(column[i]) * a;
      }
    }
  }
}

template <class Value>
[[gnu::always_inline]] inline void backward_panels(int rows, int columns, const Value* __restrict L,
                                                   double* __restrict w) {
  for (int j0 = (columns - 1) / 4 * 4; j0 >= 0; j0 -= 4) {
    const int width = std::min(4, columns - j0), below = j0 + width;
    // The panel's columns dotted with the known entries below it, four
    // sums in vector lanes each, then the rest one by one.
    Lanes sums[4] = {};
    int i = below;
    if (width == 4) {
      const Value *l0 = column_of(L, rows, j0), *l1 = column_of(L, rows, j0 + 1), *l2 = column_of(L, rows, j0 + 2),
                  *l3 = column_of(L, rows, j0 + 3);
      Lanes s0 = {}, s1 = {}, s2 = {}, s3 = {};
      for (; i + 4 <= rows; i += 4) {
        const Lanes x = lanes_at(w + i).value;
        multiply_add(l0 + i, x, s0);
        multiply_add(l1 + i, x, s1);
        multiply_add(l2 + i, x, s2);
        multiply_add(l3 + i, x, s3);
      }
      sums[0] = s0, sums[1] = s1, sums[2] = s2, sums[3] = s3;
    } else {
      for (; i + 4 <= rows; i += 4) {
        const Lanes x = lanes_at(w + i).value;
        for (int q = 0; q < width; ++q) multiply_add(column_of(L, rows, j0 + q) + i, x, sums[q]);
      }
    }
    double dot[4];
    for (int q = 0; q < width; ++q) {
      dot[q] = lane_sum(sums[q]);
      const Value* column = column_of(L, rows, j0 + q);
      for (int r = i; r < rows; ++r) dot[q] += widen(column[r]) * w[r];
    }
    for (int j = below - 1; j >= j0; --j) {  // the panel's triangle
      const Value* column = column_of(L, rows, j);
      double x = w[j] - dot[j - j0];
      for (int r = j + 1; r < below; ++r) x -= widen(column[r]) * w[r];
      w[j] = x / widen(column[j]);
    }
  }
}

}  // namespace

AKVF_FOR_EACH_X86_LEVEL void forward_block(int rows, int columns, const double* L, double* w) {
  forward_panels(rows, columns, L, w);
}
AKVF_FOR_EACH_X86_LEVEL void forward_block(int rows, int columns, const SingleEntry* L, double* w) {
  forward_panels(rows, columns, L, w);
}
AKVF_FOR_EACH_X86_LEVEL void backward_block(int rows, int columns, const double* L, double* w) {
  backward_panels(rows, columns, L, w);
}
AKVF_FOR_EACH_X86_LEVEL void backward_block(int rows, int columns, const SingleEntry* L, double* w) {
  backward_panels(rows, columns, L, w);
}

}  // namespace akvf
