#include "framework/mesh/fold_repair.h"

#include <algorithm>
#include <array>
#include <vector>

#include "framework/mesh/mesh_topology.h"
#include "framework/mesh/plane_geometry.h"

namespace akvf {

namespace {

bool is_inverted(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, int f) {
  return !(twice_signed_area(F, UV, f) > 0);
}

// The part of the convex polygon (counterclockwise) to the left of the
// directed line a -> b (Sutherland and Hodgman's clipping by one line).
std::vector<Eigen::Vector2d> clip_left_of(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& a,
                                          const Eigen::Vector2d& b) {
  std::vector<Eigen::Vector2d> kept;
  const Eigen::Vector2d direction = b - a;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& p = polygon[i];
    const Eigen::Vector2d& q = polygon[(i + 1) % polygon.size()];
    const double side_p = cross(direction, p - a), side_q = cross(direction, q - a);
    if (side_p >= 0) kept.push_back(p);
    if ((side_p >= 0) != (side_q >= 0)) kept.push_back(p + side_p / (side_p - side_q) * (q - p));
  }
  return kept;
}

// The area centroid of a convex polygon of positive area.
Eigen::Vector2d polygon_centroid(const std::vector<Eigen::Vector2d>& polygon) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double twice_area = 0;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const double a = cross(polygon[i] - polygon[0], polygon[i + 1] - polygon[0]);
    sum += a * (polygon[0] + polygon[i] + polygon[i + 1]) / 3;
    twice_area += a;
  }
  return sum / twice_area;
}

// Where vertex v makes all of its triangles positive: the centroid of its
// star's kernel within the star's bounding box; false when the kernel has
// no interior (to rounding: area below 1e-12 of the box's).
bool kernel_centroid(const Eigen::MatrixXi& F, const VertexFaces& incidence, const Eigen::MatrixXd& UV, int v,
                     Eigen::Vector2d* centroid) {
  Eigen::Vector2d low = UV.row(v).transpose(), high = low;
  for (int i = incidence.offsets[v]; i < incidence.offsets[v + 1]; ++i)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d p = UV.row(F(incidence.face_corner[i] / 3, k)).transpose();
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
  std::vector<Eigen::Vector2d> kernel = {low, {high.x(), low.y()}, high, {low.x(), high.y()}};
  const double box_area = polygon_area(kernel);
  for (int i = incidence.offsets[v]; i < incidence.offsets[v + 1] && kernel.size() >= 3; ++i) {
    const int f = incidence.face_corner[i] / 3, corner = incidence.face_corner[i] % 3;
    kernel =
        clip_left_of(kernel, UV.row(F(f, (corner + 1) % 3)).transpose(), UV.row(F(f, (corner + 2) % 3)).transpose());
  }
  if (kernel.size() < 3 || !(polygon_area(kernel) > 1e-12 * box_area)) return false;
  *centroid = polygon_centroid(kernel);
  return true;
}

}  // namespace

std::vector<int> unfold_by_star_kernels(const Eigen::MatrixXi& F, Eigen::MatrixXd* UV) {
  const VertexFaces incidence = vertex_faces(F, static_cast<int>(UV->rows()));
  std::vector<int> moved;
  const auto sorted = [&moved] {
    std::sort(moved.begin(), moved.end());
    moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
    return moved;
  };
  std::size_t previously_inverted = F.rows() + 1;
  for (;;) {
    std::vector<int> inverted_around(UV->rows(), 0);
    std::vector<int> inverted;
    for (int f = 0; f < F.rows(); ++f)
      if (is_inverted(F, *UV, f)) {
        inverted.push_back(f);
        for (int k = 0; k < 3; ++k) ++inverted_around[F(f, k)];
      }
    // Each move makes every triangle of its vertex positive and changes no
    // other, so the count falls pass by pass (unless rounding holds it).
    if (inverted.empty() || inverted.size() >= previously_inverted) return sorted();
    previously_inverted = inverted.size();
    const std::size_t moved_before = moved.size();
    for (int f : inverted) {
      if (!is_inverted(F, *UV, f)) continue;  // a vertex moved earlier in the pass unfolded it
      std::array<int, 3> corners = {F(f, 0), F(f, 1), F(f, 2)};
      std::sort(corners.begin(), corners.end(), [&](int a, int b) {
        return inverted_around[a] != inverted_around[b] ? inverted_around[a] > inverted_around[b] : a < b;
      });
      for (int v : corners) {
        Eigen::Vector2d centroid;
        if (!kernel_centroid(F, incidence, *UV, v, &centroid)) continue;
        UV->row(v) = centroid.transpose();
        moved.push_back(v);
        break;
      }
    }
    if (moved.size() == moved_before) return sorted();
  }
}

}  // namespace akvf
