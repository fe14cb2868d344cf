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
                               const std::function<void(int i, int j)>& visit) {
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
  // (cell, box of b) for every cell each box of b covers, sorted by cell.
  std::vector<std::pair<long long, int>> entries;
  entries.reserve(2 * b.size());
  for (int j = 0; j < static_cast<int>(b.size()); ++j) {
    if (!finite(b[j])) continue;
    for (long long y = row(b[j].min_y); y <= row(b[j].max_y); ++y)
      for (long long x = column(b[j].min_x); x <= column(b[j].max_x); ++x) entries.push_back({y * nx + x, j});
  }
  std::sort(entries.begin(), entries.end());
  std::vector<int> candidates, seen(b.size(), -1);
  for (int i = 0; i < static_cast<int>(a.size()); ++i) {
    const Box2& box = a[i];
    if (!finite(box) || box.max_x < all.min_x || box.min_x > all.max_x || box.max_y < all.min_y ||
        box.min_y > all.max_y)
      continue;
    candidates.clear();
    for (long long y = row(box.min_y); y <= row(box.max_y); ++y) {
      const long long first = y * nx + column(box.min_x), last = y * nx + column(box.max_x);
      auto it = std::lower_bound(entries.begin(), entries.end(), std::pair<long long, int>{first, -1});
      for (; it != entries.end() && it->first <= last; ++it) {
        const int j = it->second;
        if (seen[j] == i) continue;
        seen[j] = i;
        if (box.overlaps(b[j])) candidates.push_back(j);
      }
    }
    std::sort(candidates.begin(), candidates.end());
    for (int j : candidates) visit(i, j);
  }
}

}  // namespace akvf
