#include "framework/mesh/raster_packing.h"

#include "framework/mesh/plane_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

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

// One chart in one orientation on the grid: its cells (one row of runs
// [begin, end) per grid row), and where its points' lowest corner lies.
struct Mask {
  int width = 0, height = 0;
  std::vector<std::vector<std::array<int, 2>>> runs;
  std::vector<int> longest;   // per row, its longest run
  Eigen::RowVector2d origin;  // the turned chart's point at the mask's cell (0, 0) corner
  long cells = 0;
};

// Whether the closed triangle t and the cell [x0, x0 + h] x [y0, y0 + h]
// overlap: separated along no edge normal (the axes are the bounding box's).
bool touches(const std::array<Eigen::RowVector2d, 3>& t, double x0, double y0, double h) {
  for (int k = 0; k < 3; ++k) {
    const Eigen::RowVector2d e = t[(k + 1) % 3] - t[k];
    const Eigen::RowVector2d n(-e.y(), e.x());
    const double third = n.dot(t[(k + 2) % 3] - t[k]);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Eigen::RowVector2d& corner : {Eigen::RowVector2d(x0, y0), Eigen::RowVector2d(x0 + h, y0),
                                             Eigen::RowVector2d(x0, y0 + h), Eigen::RowVector2d(x0 + h, y0 + h)}) {
      const double d = n.dot(corner - t[k]);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    if (std::min(0.0, third) > hi || std::max(0.0, third) < lo) return false;
  }
  return true;
}

Mask rasterize(const Eigen::MatrixXi& F, const std::vector<int>& faces, const Eigen::MatrixXd& UV, double angle,
               double h, int ring) {
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
  for (int f : faces) {
    std::array<Eigen::RowVector2d, 3> t;
    for (int k = 0; k < 3; ++k) t[k] = (turned(UV.row(F(f, k))) - mask.origin) / h;
    const Eigen::RowVector2d tlo = t[0].cwiseMin(t[1]).cwiseMin(t[2]), thi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
    for (int y = std::max(0, static_cast<int>(tlo.y())); y <= std::min(mask.height - 1, static_cast<int>(thi.y())); ++y)
      for (int x = std::max(0, static_cast<int>(tlo.x())); x <= std::min(mask.width - 1, static_cast<int>(thi.x()));
           ++x)
        if (!cell[static_cast<std::size_t>(y) * mask.width + x] && touches(t, x, y, 1.0))
          cell[static_cast<std::size_t>(y) * mask.width + x] = 1;
  }
  // The gap: every cell within `ring` cells of a marked one.
  std::vector<char> grown = cell;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x)
      if (cell[static_cast<std::size_t>(y) * mask.width + x])
        for (int dy = -ring; dy <= ring; ++dy)
          for (int dx = -ring; dx <= ring; ++dx) {
            const int yy = y + dy, xx = x + dx;
            if (yy >= 0 && yy < mask.height && xx >= 0 && xx < mask.width)
              grown[static_cast<std::size_t>(yy) * mask.width + xx] = 1;
          }
  mask.runs.resize(mask.height);
  mask.longest.assign(mask.height, 0);
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width;) {
      if (!grown[static_cast<std::size_t>(y) * mask.width + x]) {
        ++x;
        continue;
      }
      const int begin = x;
      while (x < mask.width && grown[static_cast<std::size_t>(y) * mask.width + x]) ++x;
      mask.runs[y].push_back({begin, x});
      mask.cells += x - begin;
      mask.longest[y] = std::max(mask.longest[y], x - begin);
    }
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
  int height() const { return static_cast<int>(free_.size()); }

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
      std::vector<int> row(width_);
      for (int i = 0; i < width_; ++i) row[i] = width_ - i;
      free_.push_back(std::move(row));
      longest_free_.push_back(width_);
    }
    for (int j = 0; j < m.height; ++j) {
      std::vector<int>& free = free_[y + j];
      for (const auto& [begin, end] : m.runs[j])
        for (int i = begin; i < end; ++i) free[x + i] = 0;
      for (int i = width_ - 1; i >= 0; --i) {
        const int next = i + 1 < width_ ? free[i + 1] : 0;
        if (free[i] > 0)
          free[i] = next > 0 ? next + 1 : 1;
        else
          free[i] = next < 0 ? next - 1 : -1;
      }
      longest_free_[y + j] = std::max(0, *std::max_element(free.begin(), free.end()));
    }
    while (first_open_ < height() && longest_free_[first_open_] == 0) ++first_open_;
  }

  int first_open() const { return first_open_; }

 private:
  // 0 if m fits with its corner at (x, y); otherwise how far right the next
  // place that may fit is: past the taken run that a run of m meets (every
  // place before fails on that run).
  int misses(const Mask& m, int x, int y) const {
    for (int j = 0; j < m.height && y + j < height(); ++j) {
      const std::vector<int>& free = free_[y + j];
      for (const auto& [begin, end] : m.runs[j]) {
        const int at = x + begin, here = free[at];
        if (here >= end - begin) continue;
        if (here <= 0) return -here;             // a taken run starts here
        if (at + here >= width_) return width_;  // free to the row's end, too short
        return here - free[at + here];           // the free run, then the taken one
      }
    }
    return 0;
  }

  int width_;
  std::vector<std::vector<int>> free_;
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
                   std::vector<ChartPlacement>* placement, double* gap) {
  const int n = static_cast<int>(chart_faces.size());
  std::vector<double> area(n, 0.0);
  for (int c = 0; c < n; ++c)
    for (int f : chart_faces[c]) area[c] += triangle_area(F, UV, f);
  const double total = std::accumulate(area.begin(), area.end(), 0.0);
  // About 256 cells per chart (16 across, so that the ring of cells around
  // each, the gap, costs it about a quarter of its area), at least 2^16 and
  // at most 2^20 in all: fine enough for the charts' shapes, coarse enough
  // for the brute-force search.
  const double target = std::clamp(256.0 * n, 65536.0, 1048576.0);
  const double h = std::sqrt(total / target);
  if (!(h > 0)) return std::numeric_limits<double>::infinity();
  // Two grown masks never share a cell, so charts lie at least 2 ring h apart.
  const int ring = std::max(1, static_cast<int>(std::ceil(least_gap / (2 * h))));
  if (gap) *gap = 2 * ring * h;
  std::vector<std::vector<Mask>> masks(n);
  long cells = 0;
  int widest = 0;
  for (int c = 0; c < n; ++c) {
    int narrowest = std::numeric_limits<int>::max();
    for (double angle : angles[c]) {
      masks[c].push_back(rasterize(F, chart_faces[c], UV, angle, h, ring));
      narrowest = std::min(narrowest, masks[c].back().width);
    }
    cells += masks[c][0].cells;
    widest = std::max(widest, narrowest);
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return area[a] > area[b]; });

  // The charts go in, largest first, into an atlas of a fixed width (the
  // rows of a square filled to 90 % ... 50 %) or, last (fill 0), into the
  // square that grows least, as wide as the smallest square yet (a chart
  // reaching past it cannot give a smaller one); each turned as keeps the
  // square smallest, then ends lowest. The smallest square wins.
  int best_cells = std::numeric_limits<int>::max();
  for (const double fill : {0.9, 0.8, 0.7, 0.6, 0.5, 0.0}) {
    const int width = fill > 0 ? std::max(widest, static_cast<int>(std::ceil(std::sqrt(cells / fill)))) : 0;
    Atlas atlas(width > 0 ? width : best_cells);
    std::vector<ChartPlacement> trial(n);
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
      trial[c].angle = angles[c][best_q];
      trial[c].offset = Eigen::RowVector2d(best.x, best.y) * h - m.origin;
      side = best.side;
      if (side >= best_cells) break;  // it cannot give a smaller square
    }
    if (side < best_cells) {
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
