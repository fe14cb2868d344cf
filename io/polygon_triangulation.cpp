#include "io/polygon_triangulation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "framework/mesh/mesh_topology.h"

namespace akvf {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Whether p lies in the closed triangle a b c (counter-clockwise).
bool inside(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return cross(b - a, p - a) >= 0 && cross(c - b, p - b) >= 0 && cross(a - c, p - c) >= 0;
}

// Polygons with more corners take the first valid ear rather than the best
// one, and those with more than kEarCorners are cut as a fan: ear clipping
// is cubic in the corners at worst.
constexpr int kBestEarCorners = 32;
constexpr int kEarCorners = 256;

}  // namespace

std::vector<std::array<int, 3>> triangulate_polygon(const Eigen::MatrixXd& V, const std::vector<int>& ring,
                                                    const std::function<bool(int, int)>& is_edge) {
  const int n = static_cast<int>(ring.size());
  std::vector<std::array<int, 3>> triangles;
  if (n < 3) return triangles;
  if (n == 3) return {{0, 1, 2}};
  // Newell's normal (twice the vector area), and a basis of its plane.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p = V.row(ring[i]), q = V.row(ring[(i + 1) % n]);
    normal += p.cross(q);
  }
  std::vector<Eigen::Vector2d> point(n);
  if (n > kEarCorners) normal.setZero();  // a fan below
  if (normal.norm() > 0) {
    normal.normalize();
    const Eigen::Vector3d helper = std::abs(normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d u = normal.cross(helper).normalized(), v = normal.cross(u);
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d p = V.row(ring[i]);
      point[i] = {p.dot(u), p.dot(v)};
    }
  }
  std::vector<int> left(n);
  for (int i = 0; i < n; ++i) left[i] = i;
  while (left.size() > 3) {
    const int m = static_cast<int>(left.size());
    // The valid ear with the shortest diagonal; one whose diagonal is
    // already an edge of the mesh (a side of another face) only if no
    // other is valid: that diagonal would give the edge a third face.
    int best = -1, best_on_edge = -1;
    double best_length = std::numeric_limits<double>::infinity();
    double best_on_edge_length = best_length;
    for (int k = 0; k < m && normal.norm() > 0; ++k) {
      const int a = left[(k + m - 1) % m], b = left[k], c = left[(k + 1) % m];
      if (!(cross(point[b] - point[a], point[c] - point[b]) > 0)) continue;  // reflex or flat
      bool empty = true;
      for (int j = 0; j < m && empty; ++j) {
        const int p = left[j];
        if (p != a && p != b && p != c && inside(point[p], point[a], point[b], point[c])) empty = false;
      }
      if (!empty) continue;
      const double length = (V.row(ring[a]) - V.row(ring[c])).squaredNorm();
      if (is_edge && is_edge(ring[a], ring[c])) {
        if (length < best_on_edge_length) {
          best_on_edge = k;
          best_on_edge_length = length;
        }
        continue;
      }
      if (length < best_length) {
        best = k;
        best_length = length;
      }
      if (n > kBestEarCorners) break;
    }
    if (best < 0) best = best_on_edge;
    if (best < 0) break;  // no valid ear: a fan finishes it
    triangles.push_back({left[(best + m - 1) % m], left[best], left[(best + 1) % m]});
    left.erase(left.begin() + best);
  }
  for (std::size_t k = 1; k + 1 < left.size(); ++k) triangles.push_back({left[0], left[k], left[k + 1]});
  return triangles;
}

TriangulatedPolygons triangulate_faces(const Eigen::MatrixXd& V, const std::vector<int>& corners,
                                       const std::vector<int>& sizes) {
  TriangulatedPolygons out;
  out.triangles.reserve(corners.size());
  // The faces' sides, as sorted edge keys.
  const int nv = static_cast<int>(V.rows());
  std::vector<std::int64_t> sides;
  long long first = 0;
  for (const int n : sizes) {
    for (int k = 0; k < n; ++k)
      sides.push_back(undirected_edge_key(corners[first + k], corners[first + (k + 1) % n], nv));
    first += n;
  }
  std::sort(sides.begin(), sides.end());
  const auto is_side = [&](int u, int v) {
    return std::binary_search(sides.begin(), sides.end(), undirected_edge_key(u, v, nv));
  };
  first = 0;
  std::vector<int> ring;
  for (int f = 0; f < static_cast<int>(sizes.size()); ++f) {
    const int n = sizes[f];
    ring.assign(corners.begin() + first, corners.begin() + first + n);
    if (n > 3) {
      ++out.polygons;
      out.largest = std::max(out.largest, n);
    }
    for (const auto& triangle : triangulate_polygon(V, ring, is_side))
      for (const int k : triangle) {
        out.triangles.push_back(ring[k]);
        out.source_corner.push_back(first + k);
      }
    out.source_face.resize(out.triangles.size() / 3, f);
    first += n;
  }
  return out;
}

std::optional<TriangulatedPolygons> triangulate_polygons(const Eigen::MatrixXd& V, std::vector<int>* corners,
                                                         const std::vector<int>& sizes, const std::string& file_name,
                                                         std::vector<std::string>* warnings) {
  if (std::none_of(sizes.begin(), sizes.end(), [](int n) { return n > 3; })) return std::nullopt;
  TriangulatedPolygons t = triangulate_faces(V, *corners, sizes);
  if (warnings)
    warnings->push_back(file_name + ": triangulated " + std::to_string(t.polygons) +
                        (t.polygons == 1 ? " face" : " faces") + " with more than three corners (up to " +
                        std::to_string(t.largest) + ") into triangles; " + std::to_string(t.triangles.size() / 3) +
                        " triangles in all, numbered in messages as triangles");
  t.file_corners = std::move(*corners);
  *corners = std::move(t.triangles);
  return t;
}

}  // namespace akvf
