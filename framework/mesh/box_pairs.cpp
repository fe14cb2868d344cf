#include "framework/mesh/box_pairs.h"

#include <algorithm>
#include <cmath>

namespace akvf {

namespace {
bool finite(const Box2& box) {
  return std::isfinite(box.min_x) && std::isfinite(box.min_y) && std::isfinite(box.max_x) && std::isfinite(box.max_y);
}
}  // namespace

void for_each_overlapping_pair(const std::vector<Box2>& a, const std::vector<Box2>& b,
                               const std::function<void(int i, int j)>& visit, PairOrder order) {
  Box2 all{INFINITY, INFINITY, -INFINITY, -INFINITY};
  double extent_sum = 0;
  int count = 0;
  for (const Box2& box : b) {
    if (!finite(box)) continue;
    all = {std::min(all.min_x, box.min_x), std::min(all.min_y, box.min_y), std::max(all.max_x, box.max_x),
           std::max(all.max_y, box.max_y)};
    extent_sum += std::max(box.max_x - box.min_x, box.max_y - box.min_y);
    ++count;
  }
  if (count == 0 || a.empty()) return;
  // Cells as large as the mean box, but no more than about 4 per box of b.
  const double width = all.max_x - all.min_x, height = all.max_y - all.min_y;
  const double floor_size = std::sqrt(std::max(width * height, 1e-300) / (4.0 * count));
  double cell = std::max({extent_sum / count, floor_size, std::max(width, height) / (4.0 * count), 1e-300});
  const long long nx = std::min<long long>(static_cast<long long>(width / cell) + 1, 4LL * count + 1);
  const long long ny = std::min<long long>(static_cast<long long>(height / cell) + 1, 4LL * count + 1);
  const double cell_x = width / nx > cell ? width / nx : cell, cell_y = height / ny > cell ? height / ny : cell;
  // Clamped as doubles first: a box far outside b's (a long sweep) must not
  // overflow the conversion.
  auto column = [&](double x) {
    return static_cast<long long>(std::clamp(std::floor((x - all.min_x) / cell_x), 0.0, double(nx - 1)));
  };
  auto row = [&](double y) {
    return static_cast<long long>(std::clamp(std::floor((y - all.min_y) / cell_y), 0.0, double(ny - 1)));
  };
  // The boxes of b in each cell, in increasing order, as compressed rows:
  // cell c holds items[first[c] .. first[c + 1]). There are at most about
  // 12 count cells (the cell is at least floor_size and max(width,
  // height) / (4 count)).
  const long long cells = nx * ny;
  std::vector<int> first(static_cast<std::size_t>(cells) + 1, 0);
  auto for_each_cell = [&](const Box2& box, auto&& visit_cell) {
    for (long long y = row(box.min_y); y <= row(box.max_y); ++y)
      for (long long x = column(box.min_x); x <= column(box.max_x); ++x) visit_cell(y * nx + x);
  };
  for (const Box2& box : b)
    if (finite(box)) for_each_cell(box, [&](long long c) { ++first[c + 1]; });
  for (long long c = 0; c < cells; ++c) first[c + 1] += first[c];
  std::vector<int> items(static_cast<std::size_t>(first[cells]));
  std::vector<int> next(first.begin(), first.end() - 1);
  for (int j = 0; j < static_cast<int>(b.size()); ++j)
    if (finite(b[j])) for_each_cell(b[j], [&](long long c) { items[next[c]++] = j; });
  std::vector<int> candidates, seen(b.size(), -1);
  for (int i = 0; i < static_cast<int>(a.size()); ++i) {
    const Box2& box = a[i];
    if (!finite(box) || box.max_x < all.min_x || box.min_x > all.max_x || box.max_y < all.min_y ||
        box.min_y > all.max_y)
      continue;
    candidates.clear();
    for_each_cell(box, [&](long long c) {
      for (int k = first[c]; k < first[c + 1]; ++k) {
        const int j = items[k];
        if (seen[j] == i) continue;
        seen[j] = i;
        if (!box.overlaps(b[j])) continue;
        if (order == PairOrder::kGrid)
          visit(i, j);
        else
          candidates.push_back(j);
      }
    });
    std::sort(candidates.begin(), candidates.end());
    for (int j : candidates) visit(i, j);
  }
}

}  // namespace akvf
