#include "solvers/supernodal_block_solve.h"

#include <algorithm>
#include <cstddef>

#include "solvers/vector_lanes.h"

namespace akvf {

namespace {

const double* column_of(const double* L, int rows, int j) { return L + static_cast<std::size_t>(j) * rows; }

}  // namespace

AKVF_FOR_EACH_X86_LEVEL void forward_block(int rows, int columns, const double* __restrict L, double* __restrict w) {
  for (int j0 = 0; j0 < columns; j0 += 4) {
    const int width = std::min(4, columns - j0), below = j0 + width;
    for (int j = j0; j < below; ++j) {  // the panel's triangle
      const double* column = column_of(L, rows, j);
      w[j] /= column[j];
      for (int i = j + 1; i < below; ++i) w[i] -= w[j] * column[i];
    }
    if (width == 4) {  // the rows below, less the panel's four columns at once
      const double *l0 = column_of(L, rows, j0), *l1 = column_of(L, rows, j0 + 1), *l2 = column_of(L, rows, j0 + 2),
                   *l3 = column_of(L, rows, j0 + 3);
      const double a0 = w[j0], a1 = w[j0 + 1], a2 = w[j0 + 2], a3 = w[j0 + 3];
      for (int i = below; i < rows; ++i) w[i] -= (l0[i] * a0 + l1[i] * a1) + (l2[i] * a2 + l3[i] * a3);
    } else {
      for (int j = j0; j < below; ++j) {
        const double* column = column_of(L, rows, j);
        const double a = w[j];
        for (int i = below; i < rows; ++i) w[i] -= column[i] * a;
      }
    }
  }
}

AKVF_FOR_EACH_X86_LEVEL void backward_block(int rows, int columns, const double* __restrict L, double* __restrict w) {
  for (int j0 = (columns - 1) / 4 * 4; j0 >= 0; j0 -= 4) {
    const int width = std::min(4, columns - j0), below = j0 + width;
    // The panel's columns dotted with the known entries below it, four
    // sums in vector lanes each, then the rest one by one.
    Lanes sums[4] = {};
    int i = below;
    if (width == 4) {
      const double *l0 = column_of(L, rows, j0), *l1 = column_of(L, rows, j0 + 1), *l2 = column_of(L, rows, j0 + 2),
                   *l3 = column_of(L, rows, j0 + 3);
      Lanes s0 = {}, s1 = {}, s2 = {}, s3 = {};
      for (; i + 4 <= rows; i += 4) {
        const Lanes x = lanes_at(w + i).value;
        s0 += lanes_at(l0 + i).value * x;
        s1 += lanes_at(l1 + i).value * x;
        s2 += lanes_at(l2 + i).value * x;
        s3 += lanes_at(l3 + i).value * x;
      }
      sums[0] = s0, sums[1] = s1, sums[2] = s2, sums[3] = s3;
    } else {
      for (; i + 4 <= rows; i += 4) {
        const Lanes x = lanes_at(w + i).value;
        for (int q = 0; q < width; ++q) sums[q] += lanes_at(column_of(L, rows, j0 + q) + i).value * x;
      }
    }
    double dot[4];
    for (int q = 0; q < width; ++q) {
      dot[q] = lane_sum(sums[q]);
      const double* column = column_of(L, rows, j0 + q);
      for (int r = i; r < rows; ++r) dot[q] += column[r] * w[r];
    }
    for (int j = below - 1; j >= j0; --j) {  // the panel's triangle
      const double* column = column_of(L, rows, j);
      double x = w[j] - dot[j - j0];
      for (int r = j + 1; r < below; ++r) x -= column[r] * w[r];
      w[j] = x / column[j];
    }
  }
}

}  // namespace akvf
