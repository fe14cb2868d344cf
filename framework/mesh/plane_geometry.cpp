#include "framework/mesh/plane_geometry.h"

#include <algorithm>
#include <cmath>

namespace akvf {

std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  const auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector2d> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (const Eigen::Vector2d& p : points) {
      while (hull.size() >= base + 2 && cross(hull[hull.size() - 2], hull.back(), p) <= 0) hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();
    std::reverse(points.begin(), points.end());
  }
  return hull;
}

double polygon_area(const std::vector<Eigen::Vector2d>& polygon) {
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

double triangle_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, int f) {
  const Eigen::RowVector2d a = UV.row(F(f, 1)) - UV.row(F(f, 0)), b = UV.row(F(f, 2)) - UV.row(F(f, 0));
  return 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
}

double map_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV) {
  double area = 0;
  for (int f = 0; f < F.rows(); ++f) area += triangle_area(F, UV, f);
  return area;
}

}  // namespace akvf
