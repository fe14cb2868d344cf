#include "framework/mesh/raster_packing.h"

#include "framework/mesh/plane_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include <tbb/parallel_for.h>

namespace akvf {

namespace {

// A turn by an angle, its cosine and sine computed once (the masks and the
// placement turn alike, to the bit).
struct Turn {
  explicit Turn(double angle) : c(std::cos(angle)), s(std::sin(angle)) {}
  Eigen::RowVector2d operator()(const Eigen::RowVector2d& p) const {
    return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
  }
  double c, s;
};

// One chart in one orientation on the grid: the cells it takes (one row of
// runs [begin, end) per grid row), the cells within the gap of those (which
// must be free where it goes), and where its points' lowest corner lies.
struct Mask {
  int width = 0, height = 0;
  std::vector<std::vector<std::array<int, 2>>> own;
  std::vector<int> longest;  // per row, the longest run of the grown cells
  // Every run of the grown cells as (row, begin, end), longest first: a
  // place that fails mostly fails there, so a search tests these first.
  std::vector<std::array<int, 3>> tests;
  Eigen::RowVector2d origin;  // the turned chart's point at the mask's cell (0, 0) corner
  long cells = 0;
};

// The x-extent of the closed triangle t within the slab y0 <= y <= y0 + 1:
// its corners in the slab and its edges' crossings of the slab's two lines
// (lo > hi: they do not meet). A cell of the slab meets t exactly when its
// x-extent meets this one.
std::array<double, 2> slab_extent(const std::array<Eigen::RowVector2d, 3>& t, double y0) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int k = 0; k < 3; ++k) {
    const Eigen::RowVector2d& p = t[k];
    const Eigen::RowVector2d& q = t[(k + 1) % 3];
    if (p.y() >= y0 && p.y() <= y0 + 1) {
      lo = std::min(lo, p.x());
      hi = std::max(hi, p.x());
    }
    for (const double line : {y0, y0 + 1})
      if ((p.y() - line) * (q.y() - line) < 0) {
        const double x = p.x() + (q.x() - p.x()) * (line - p.y()) / (q.y() - p.y());
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
  }
  return {lo, hi};
}

// The runs [begin, end) of set cells in cells[start, start + width).
std::vector<std::array<int, 2>> row_runs(const std::vector<char>& cells, std::size_t start, int width) {
  std::vector<std::array<int, 2>> runs;
  for (int x = 0; x < width;) {
    if (!cells[start + x]) {
      ++x;
      continue;
    }
    const int begin = x;
    while (x < width && cells[start + x]) ++x;
    runs.push_back({begin, x});
  }
  return runs;
}

// The cells a chart's gap covers: those nearer than the gap (q cells) to one
// of its cells, and always the 8 around each (charts never touch). Two
// cells dx, dy rows and columns apart lie sqrt(max(dx - 1, 0)^2 +
// max(dy - 1, 0)^2) cells apart: a disk's reach, not a square's.
struct GapReach {
  std::vector<int> across;  // per dy = 0, 1, ...: the largest dx within the gap
  double cells = 0;         // the least distance, in cells, between a cell and one beyond the reach
};

GapReach gap_reach(double q) {
  const auto apart = [](int dx, int dy) { return std::hypot(std::max(dx - 1, 0), std::max(dy - 1, 0)); };
  GapReach reach;
  reach.cells = std::numeric_limits<double>::infinity();
  for (int dy = 0;; ++dy) {
    if (dy > 1 && apart(0, dy) >= q) {
      reach.cells = std::min(reach.cells, apart(0, dy));
      return reach;
    }
    int dx = dy <= 1 ? 1 : 0;
    while (apart(dx + 1, dy) < q) ++dx;
    reach.across.push_back(dx);
    reach.cells = std::min(reach.cells, apart(dx + 1, dy));
  }
}

Mask rasterize(const Eigen::MatrixXi& F, const std::vector<int>& faces, const Eigen::MatrixXd& UV, double angle,
               double h, const GapReach& reach) {
  const int ring = reach.across[0];  // the reach's extent either way
  const Turn turned(angle);
  Eigen::RowVector2d lo = Eigen::RowVector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int f : faces)
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector2d p = turned(UV.row(F(f, k)));
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  Mask mask;
  mask.origin = lo - Eigen::RowVector2d::Constant(ring * h);  // `ring` cells of gap on every side
  mask.width = static_cast<int>(std::floor((hi.x() - mask.origin.x()) / h)) + 1 + ring;
  mask.height = static_cast<int>(std::floor((hi.y() - mask.origin.y()) / h)) + 1 + ring;
  std::vector<char> cell(static_cast<std::size_t>(mask.width) * mask.height, 0);
  const auto at = [&](int x, int y) { return static_cast<std::size_t>(y) * mask.width + x; };
  for (int f : faces) {
    std::array<Eigen::RowVector2d, 3> t;
    for (int k = 0; k < 3; ++k) t[k] = (turned(UV.row(F(f, k))) - mask.origin) / h;
    const double top = std::max({t[0].y(), t[1].y(), t[2].y()});
    const double bottom = std::min({t[0].y(), t[1].y(), t[2].y()});
    // Closed cells: a corner on a line between two rows marks both.
    for (int y = std::max(0, static_cast<int>(std::ceil(bottom)) - 1);
         y <= std::min(mask.height - 1, static_cast<int>(std::floor(top))); ++y) {
      const auto [lo, hi] = slab_extent(t, y);
      if (!(lo <= hi)) continue;
      const int from = std::max(0, static_cast<int>(std::ceil(lo)) - 1);
      const int to = std::min(mask.width - 1, static_cast<int>(std::floor(hi)));
      if (from <= to) std::fill(cell.begin() + at(from, y), cell.begin() + at(to, y) + 1, 1);
    }
  }
  // The gap: every cell within the reach of a marked one, a run at a time.
  mask.own.resize(mask.height);
  for (int y = 0; y < mask.height; ++y) mask.own[y] = row_runs(cell, at(0, y), mask.width);
  std::vector<char> grown(cell.size(), 0);
  const int rows = static_cast<int>(reach.across.size());
  for (int y = 0; y < mask.height; ++y)
    for (const auto& [begin, end] : mask.own[y])
      for (int dy = 1 - rows; dy < rows; ++dy) {
        const int yy = y + dy, dx = reach.across[std::abs(dy)];
        if (yy >= 0 && yy < mask.height)
          std::fill(grown.begin() + at(std::max(0, begin - dx), yy),
                    grown.begin() + at(std::min(mask.width - 1, end - 1 + dx), yy) + 1, 1);
      }
  mask.longest.assign(mask.height, 0);
  for (int y = 0; y < mask.height; ++y)
    for (const auto& [begin, end] : row_runs(grown, at(0, y), mask.width)) {
      mask.cells += end - begin;
      mask.longest[y] = std::max(mask.longest[y], end - begin);
      mask.tests.push_back({y, begin, end});
    }
  std::stable_sort(mask.tests.begin(), mask.tests.end(),
                   [](const auto& a, const auto& b) { return a[2] - a[1] > b[2] - b[1]; });
  return mask;
}

// The atlas: rows of cells, at most `width` wide, as high as it needs. Each
// row keeps, per cell, how many free cells start there (or, negated, how
// many taken ones), so a run of a mask is tested in one look and a search
// steps over a taken run at once; rows above the highest placed mask are
// free.
class Atlas {
 public:
  explicit Atlas(int width) : width_(width) {}

  int width() const { return width_; }
  int height() const { return static_cast<int>(longest_free_.size()); }

  // The leftmost x at which m fits with its corner in row y and its right
  // side at most `limit`, or -1.
  int leftmost_fit(const Mask& m, int y, int limit) const {
    // A row whose longest free run is shorter than the mask's there: no x fits.
    for (int j = 0; j < m.height && y + j < height(); ++j)
      if (longest_free_[y + j] < m.longest[j]) return -1;
    for (int x = 0; x + m.width <= std::min(limit, width_);) {
      const int skip = misses(m, x, y);
      if (skip == 0) return x;
      x += skip;
    }
    return -1;
  }

  void place(const Mask& m, int x, int y) {
    while (height() < y + m.height) {
      for (int i = 0; i < width_; ++i) free_.push_back(width_ - i);
      longest_free_.push_back(width_);
    }
    for (int j = 0; j < m.height; ++j) {
      if (m.own[j].empty()) continue;
      int* free = row(y + j);
      for (const auto& [begin, end] : m.own[j]) std::fill(free + x + begin, free + x + end, 0);
      // The counts from the last taken cell leftwards, up to the first
      // unchanged one left of the mask (those before it are unchanged too).
      const int first = x + m.own[j].front()[0];
      for (int i = x + m.own[j].back()[1] - 1; i >= 0; --i) {
        const int next = i + 1 < width_ ? free[i + 1] : 0;
        const int count = free[i] > 0 ? (next > 0 ? next + 1 : 1) : (next < 0 ? next - 1 : -1);
        if (i < first && count == free[i]) break;
        free[i] = count;
      }
      longest_free_[y + j] = std::max(0, *std::max_element(free, free + width_));
    }
    while (first_open_ < height() && longest_free_[first_open_] == 0) ++first_open_;
  }

  int first_open() const { return first_open_; }

 private:
  // 0 if m fits with its corner at (x, y); otherwise how far right the next
  // place that may fit is: past the taken run that a run of m meets (every
  // place before fails on that run).
  int misses(const Mask& m, int x, int y) const {
    for (const auto& [j, begin, end] : m.tests) {
      if (y + j >= height()) continue;
      const int* free = row(y + j);
      const int at = x + begin, here = free[at];
      if (here >= end - begin) continue;
      if (here <= 0) return -here;             // a taken run starts here
      if (at + here >= width_) return width_;  // free to the row's end, too short
      return here - free[at + here];           // the free run, then the taken one
    }
    return 0;
  }

  int* row(int y) { return free_.data() + static_cast<std::size_t>(y) * width_; }
  const int* row(int y) const { return free_.data() + static_cast<std::size_t>(y) * width_; }

  int width_;
  std::vector<int> free_;          // the rows' counts, one after another
  std::vector<int> longest_free_;  // per row
  int first_open_ = 0;
};

// Where a mask goes, and the side of the square (in cells) around it and
// the masks placed before.
struct Place {
  int x = 0, y = 0, side = 0;
};

// The lowest row, then leftmost, where m fits within `width` cells.
Place first_fit(const Atlas& atlas, const Mask& m, int width, int side) {
  for (int y = atlas.first_open();; ++y)
    if (const int x = atlas.leftmost_fit(m, y, width); x >= 0)
      return {x, y, std::max(side, std::max(x + m.width, y + m.height))};
}

// Inside the square around the masks placed so far if m fits there (the
// lowest row, then leftmost); otherwise where it grows that square least.
Place least_growth(const Atlas& atlas, const Mask& m, int side) {
  for (int y = atlas.first_open(); y + m.height <= side; ++y)
    if (const int x = atlas.leftmost_fit(m, y, side); x >= 0) return {x, y, side};
  // Every row from the first open one to the first free one above all masks
  // (where x = 0 fits): the leftmost place in each; a row cannot do better
  // once its own top reaches the best side found.
  Place best{0, atlas.height(), std::max(side, std::max(m.width, atlas.height() + m.height))};
  for (int y = atlas.first_open(); y < atlas.height() && y + m.height < best.side; ++y)
    if (const int x = atlas.leftmost_fit(m, y, atlas.width()); x >= 0) {
      const int grown = std::max(side, std::max(x + m.width, y + m.height));
      if (grown < best.side) best = {x, y, grown};
    }
  return best;
}

}  // namespace

double raster_pack(const Eigen::MatrixXi& F, const std::vector<std::vector<int>>& chart_faces,
                   const Eigen::MatrixXd& UV, const std::vector<std::vector<double>>& angles, double least_gap,
                   std::vector<ChartPlacement>* placement, double* gap, PackingGrid grid) {
  const int n = static_cast<int>(chart_faces.size());
  std::vector<double> area(n, 0.0);
  for (int c = 0; c < n; ++c)
    for (int f : chart_faces[c]) area[c] += triangle_area(F, UV, f);
  const double total = std::accumulate(area.begin(), area.end(), 0.0);
  // PackingGrid's cells: fine enough for the charts' shapes, coarse enough
  // for the brute-force search.
  const double coarse = grid == PackingGrid::kCoarse ? 0.25 : 1.0;
  const double target = coarse * std::clamp(1024.0 * n, 262144.0, 524288.0);
  const double h = std::sqrt(total / target);
  if (!(h > 0)) return std::numeric_limits<double>::infinity();
  // A chart's grown cells meet no cell another took, so their cells, and
  // the charts in them, lie at least the reach's distance apart.
  const GapReach reach = gap_reach(least_gap / h);
  if (gap) *gap = reach.cells * h;
  std::vector<std::vector<Mask>> masks(n);
  tbb::parallel_for(0, n, [&](int c) {
    for (double angle : angles[c]) masks[c].push_back(rasterize(F, chart_faces[c], UV, angle, h, reach));
  });
  long cells = 0;
  int widest = 0;
  for (int c = 0; c < n; ++c) {
    int narrowest = std::numeric_limits<int>::max();
    for (const Mask& m : masks[c]) narrowest = std::min(narrowest, m.width);
    cells += masks[c][0].cells;
    widest = std::max(widest, narrowest);
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return area[a] > area[b]; });

  // The charts go in, largest first, into an atlas of a fixed width
  // (width > 0) or into the square that grows least (an atlas `limit`
  // wide); each turned as keeps the square smallest, then ends lowest. A
  // trial stops once its square is as large as `limit`: it cannot give a
  // smaller one. Returns the side of its square (or at least `limit`).
  const auto pack_into = [&](int width, int limit, std::vector<ChartPlacement>* trial) {
    Atlas atlas(width > 0 ? width : limit);
    trial->resize(n);
    int side = 0;
    for (int c : order) {
      int best_q = -1;
      Place best;
      for (int q = 0; q < static_cast<int>(masks[c].size()); ++q) {
        const Mask& m = masks[c][q];
        if (m.width > atlas.width()) continue;
        const Place at = width > 0 ? first_fit(atlas, m, width, side) : least_growth(atlas, m, side);
        if (best_q < 0 ||
            std::make_pair(at.side, at.y + m.height) < std::make_pair(best.side, best.y + masks[c][best_q].height)) {
          best_q = q;
          best = at;
        }
      }
      const Mask& m = masks[c][best_q];
      atlas.place(m, best.x, best.y);
      (*trial)[c].angle = angles[c][best_q];
      (*trial)[c].offset = Eigen::RowVector2d(best.x, best.y) * h - m.origin;
      side = best.side;
      if (side >= limit) break;
    }
    return side;
  };
  // Atlases of the widths of a square filled to 90 % ... 50 % (fill 0:
  // the square that grows least, as wide as the smallest square yet; a
  // chart reaching past it cannot give a smaller one). The smallest square
  // wins, the first of one size.
  int best_cells = std::numeric_limits<int>::max();
  for (const double fill : {0.9, 0.8, 0.7, 0.6, 0.5, 0.0}) {
    const int width = fill > 0 ? std::max(widest, static_cast<int>(std::ceil(std::sqrt(cells / fill)))) : 0;
    std::vector<ChartPlacement> trial;
    if (const int side = pack_into(width, best_cells, &trial); side < best_cells) {
      best_cells = side;
      *placement = std::move(trial);
    }
  }
  return h * best_cells;
}

void apply_placement(const Eigen::MatrixXi& F, const std::vector<std::vector<int>>& chart_faces,
                     const std::vector<ChartPlacement>& placement, Eigen::MatrixXd* UV) {
  std::vector<char> moved(UV->rows(), 0);
  for (std::size_t c = 0; c < chart_faces.size(); ++c) {
    const Turn turned(placement[c].angle);
    for (int f : chart_faces[c])
      for (int k = 0; k < 3; ++k)
        if (const int v = F(f, k); !moved[v]) {
          moved[v] = 1;
          UV->row(v) = turned(UV->row(v)) + placement[c].offset;
        }
  }
}

}  // namespace akvf
