#include "framework/mesh/uv_overlap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace akvf {

namespace {
double signed_area(const Eigen::RowVector2d& a, const Eigen::RowVector2d& b, const Eigen::RowVector2d& c) {
  return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
}

// Which side of the edge a -> b the point p lies on (> 0: left), computed
// from the edge's lexicographically smaller end whichever way it is walked,
// so that the two triangles sharing an edge get exactly opposite signs: a
// sample on the edge is strictly inside neither, not inside both by rounding.
double edge_side(const Eigen::RowVector2d& a, const Eigen::RowVector2d& b, const Eigen::RowVector2d& p) {
  const bool a_first = a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  return a_first ? signed_area(a, b, p) : -signed_area(b, a, p);
}
}  // namespace

UvOverlap measure_uv_overlap(const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F, const std::vector<int>& face_chart,
                             long long samples) {
  const int num_charts = face_chart.empty() ? 1 : 1 + *std::max_element(face_chart.begin(), face_chart.end());
  std::vector<std::vector<int>> chart_faces(num_charts);
  std::vector<double> chart_area(num_charts, 0.0);
  double total_area = 0;
  for (int f = 0; f < F.rows(); ++f) {
    const int chart = face_chart.empty() ? 0 : face_chart[f];
    const double area = std::abs(signed_area(UV.row(F(f, 0)), UV.row(F(f, 1)), UV.row(F(f, 2))));
    if (!std::isfinite(area)) continue;
    chart_faces[chart].push_back(f);
    chart_area[chart] += area;
    total_area += area;
  }
  UvOverlap overlap;
  std::vector<std::uint8_t> count;
  for (int chart = 0; chart < num_charts; ++chart) {
    if (chart_faces[chart].empty() || !(chart_area[chart] > 0)) continue;
    Eigen::RowVector2d low = UV.row(F(chart_faces[chart][0], 0)), high = low;
    for (int f : chart_faces[chart])
      for (int k = 0; k < 3; ++k) {
        low = low.cwiseMin(UV.row(F(f, k)));
        high = high.cwiseMax(UV.row(F(f, k)));
      }
    const double box_area = std::max((high.x() - low.x()) * (high.y() - low.y()), 1e-300);
    const double share = std::max(1024.0, static_cast<double>(samples) * chart_area[chart] / total_area);
    // Square cells, as many as the share asks over the chart's box, and no
    // more than 4 sqrt(share) along its longer side (a long thin chart).
    const double cell = std::max(std::sqrt(box_area / share),
                                 std::max(high.x() - low.x(), high.y() - low.y()) / (4 * std::sqrt(share)));
    const long long nx = std::max(1LL, static_cast<long long>(std::ceil((high.x() - low.x()) / cell)));
    const long long ny = std::max(1LL, static_cast<long long>(std::ceil((high.y() - low.y()) / cell)));
    count.assign(static_cast<size_t>(nx * ny), 0);
    for (int f : chart_faces[chart]) {
      Eigen::RowVector2d a = UV.row(F(f, 0)), b = UV.row(F(f, 1)), c = UV.row(F(f, 2));
      if (signed_area(a, b, c) < 0) std::swap(b, c);
      const Eigen::RowVector2d lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
      // Sample (i, j) sits at the centre of its cell.
      const long long i0 = std::max(0LL, static_cast<long long>(std::ceil((lo.x() - low.x()) / cell - 0.5)));
      const long long i1 = std::min(nx - 1, static_cast<long long>(std::floor((hi.x() - low.x()) / cell - 0.5)));
      const long long j0 = std::max(0LL, static_cast<long long>(std::ceil((lo.y() - low.y()) / cell - 0.5)));
      const long long j1 = std::min(ny - 1, static_cast<long long>(std::floor((hi.y() - low.y()) / cell - 0.5)));
      for (long long j = j0; j <= j1; ++j)
        for (long long i = i0; i <= i1; ++i) {
          const Eigen::RowVector2d p(low.x() + (i + 0.5) * cell, low.y() + (j + 0.5) * cell);
          if (edge_side(a, b, p) > 0 && edge_side(b, c, p) > 0 && edge_side(c, a, p) > 0) {
            std::uint8_t& n = count[static_cast<size_t>(j * nx + i)];
            if (n < 2) ++n;
          }
        }
    }
    for (std::uint8_t n : count) {
      overlap.covered_samples += n >= 1;
      overlap.overlapped_samples += n >= 2;
    }
  }
  return overlap;
}

}  // namespace akvf
