#pragma once
// Geometry of the plane: convex hulls and areas.
#include <Eigen/Core>
#include <vector>

namespace akvf {

// a.x b.y - a.y b.x: positive when b is counterclockwise of a.
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The hull's corners, counterclockwise, without collinear ones (Andrew's
// monotone chain); empty if every point is the same.
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points);

// The area of a counterclockwise polygon (the shoelace formula).
double polygon_area(const std::vector<Eigen::Vector2d>& polygon);

// Twice the signed area of triangle f of F in UV (one row per vertex):
// positive when counterclockwise, not positive when inverted or degenerate.
double twice_signed_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, int f);

// The unsigned area of triangle f of F in UV.
double triangle_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, int f);

// The area of the triangles F in UV.
double map_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV);

}  // namespace akvf
