#pragma once
// Broad phase for 2D proximity queries: the pairs of axis-aligned boxes, one
// from each of two sets, that overlap. A uniform grid over the second set
// (cells about as large as its typical box, at most about 4 cells per box)
// makes the work O(boxes + pairs) for boxes of similar size.
#include <functional>
#include <vector>

namespace akvf {

struct Box2 {
  double min_x, min_y, max_x, max_y;
  bool overlaps(const Box2& o) const {
    return min_x <= o.max_x && o.min_x <= max_x && min_y <= o.max_y && o.min_y <= max_y;
  }
};

// The order of the pairs for each i of `a`: increasing j, or the grid's
// own order (the same on every run, but not sorted; for a caller that only
// takes a minimum or a maximum, which then skips a sort per box).
enum class PairOrder { kIncreasing, kGrid };

// Calls visit(i, j) once for every i of `a` and j of `b` whose boxes overlap
// (closed boxes), in increasing i and, for each i, in `order`: the order,
// and so any sum the caller forms, is the same on every run. Boxes with a
// non-finite coordinate overlap nothing.
void for_each_overlapping_pair(const std::vector<Box2>& a, const std::vector<Box2>& b,
                               const std::function<void(int i, int j)>& visit,
                               PairOrder order = PairOrder::kIncreasing);

}  // namespace akvf
