#pragma once
// The convex hull of points of the plane.
#include <Eigen/Core>
#include <vector>

namespace akvf {

// The hull's corners, counterclockwise, without collinear ones (Andrew's
// monotone chain); empty if every point is the same.
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points);

// The area of a counterclockwise polygon (the shoelace formula).
double polygon_area(const std::vector<Eigen::Vector2d>& polygon);

}  // namespace akvf
