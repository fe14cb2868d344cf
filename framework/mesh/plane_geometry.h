#pragma once
// Geometry of the plane: convex hulls and areas.
#include <Eigen/Core>
#include <vector>

namespace akvf {

// The hull's corners, counterclockwise, without collinear ones (Andrew's
// monotone chain); empty if every point is the same.
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points);

// The area of a counterclockwise polygon (the shoelace formula).
double polygon_area(const std::vector<Eigen::Vector2d>& polygon);

// The unsigned area of triangle f of F in UV (one row per vertex).
double triangle_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, int f);

// The area of the triangles F in UV.
double map_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV);

}  // namespace akvf
