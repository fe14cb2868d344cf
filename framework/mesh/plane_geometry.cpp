#include "framework/mesh/plane_geometry.h"

#include <algorithm>
#include <cmath>

namespace akvf {

std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::vector<Eigen::Vector2d> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (const Eigen::Vector2d& p : points) {
      while (hull.size() >= base + 2 && cross(hull.back() - hull[hull.size() - 2], p - hull[hull.size() - 2]) <= 0)
        hull.pop_back();
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
    twice += cross(a, b);
  }
  return 0.5 * twice;
}

double twice_signed_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, int f) {
  const Eigen::Vector2d p = UV.row(F(f, 0)).transpose();
  return cross(UV.row(F(f, 1)).transpose() - p, UV.row(F(f, 2)).transpose() - p);
}

double triangle_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, int f) {
  return 0.5 * std::abs(twice_signed_area(F, UV, f));
}

double map_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV) {
  double area = 0;
  for (int f = 0; f < F.rows(); ++f) area += triangle_area(F, UV, f);
  return area;
}

}  // namespace akvf
