#include "framework/mesh/overlap_free_pieces.h"

#include <array>
#include <cmath>
#include <deque>

#include "framework/mesh/box_pairs.h"
#include "framework/mesh/mesh_topology.h"

namespace akvf {

namespace {

using Vec2 = Eigen::Vector2d;

double orient(const Vec2& p, const Vec2& q, const Vec2& r) {
  return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
}

// Whether an edge of triangle a separates it from triangle b: every corner
// of b on the far side of the edge's line, or on it to rounding (so that
// triangles sharing an edge or a corner do not overlap).
bool separated_by_an_edge_of(const std::array<Vec2, 3>& a, const std::array<Vec2, 3>& b) {
  const double side = orient(a[0], a[1], a[2]) > 0 ? 1 : -1;
  for (int k = 0; k < 3; ++k) {
    const Vec2& p = a[k];
    const Vec2& q = a[(k + 1) % 3];
    const double length = (q - p).norm();
    bool all_outside = true;
    for (int j = 0; j < 3 && all_outside; ++j)
      all_outside = side * orient(p, q, b[j]) <= 1e-10 * length * (b[j] - p).norm();
    if (all_outside) return true;
  }
  return false;
}

// Whether the interiors of the two triangles meet (the separating axis test).
bool interiors_meet(const std::array<Vec2, 3>& a, const std::array<Vec2, 3>& b) {
  return !separated_by_an_edge_of(a, b) && !separated_by_an_edge_of(b, a);
}

}  // namespace

int overlap_free_pieces(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, const std::vector<int>& face_chart,
                        int num_charts, std::vector<int>* pieces) {
  const int nf = static_cast<int>(F.rows());
  const int nv = static_cast<int>(UV.rows());
  auto corners = [&](int f) {
    return std::array<Vec2, 3>{UV.row(F(f, 0)).transpose(), UV.row(F(f, 1)).transpose(), UV.row(F(f, 2)).transpose()};
  };
  std::vector<Box2> boxes(nf);
  for (int f = 0; f < nf; ++f) {
    const auto p = corners(f);
    boxes[f] = {std::min({p[0].x(), p[1].x(), p[2].x()}), std::min({p[0].y(), p[1].y(), p[2].y()}),
                std::max({p[0].x(), p[1].x(), p[2].x()}), std::max({p[0].y(), p[1].y(), p[2].y()})};
  }
  std::vector<std::vector<int>> overlapping(nf);
  std::vector<char> chart_overlaps(num_charts, 0);
  for_each_overlapping_pair(boxes, boxes, [&](int f, int g) {
    if (g <= f || face_chart[f] != face_chart[g] || !interiors_meet(corners(f), corners(g))) return;
    overlapping[f].push_back(g);
    overlapping[g].push_back(f);
    chart_overlaps[face_chart[f]] = 1;
  });
  *pieces = face_chart;
  int count = num_charts;
  const std::vector<std::array<int, 3>> across = faces_across_edges(F, nv);
  std::vector<int> piece(nf, -1);             // the piece being grown of each placed face
  std::vector<int> vertex_piece(nv, -1);      // the last piece a vertex joined
  std::vector<char> numbered(num_charts, 0);  // the chart's first piece keeps its number
  int grown = 0;
  for (int seed = 0; seed < nf; ++seed) {
    const int chart = face_chart[seed];
    if (!chart_overlaps[chart] || piece[seed] >= 0) continue;
    const int id = grown++;
    const int number = numbered[chart] ? count++ : chart;
    numbered[chart] = 1;
    std::deque<int> queue{seed};
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop_front();
      if (piece[f] >= 0) continue;
      int shared = 0, opposite = -1;  // with one shared edge, the corner off it
      for (int k = 0; k < 3; ++k)
        if (across[f][k] >= 0 && piece[across[f][k]] == id) {
          ++shared;
          opposite = F(f, (k + 2) % 3);
        }
      const bool disk = f == seed || shared == 2 || (shared == 1 && vertex_piece[opposite] != id);
      if (!disk) continue;
      bool free = true;
      for (int g : overlapping[f]) free = free && piece[g] != id;
      if (!free) continue;
      piece[f] = id;
      (*pieces)[f] = number;
      for (int k = 0; k < 3; ++k) vertex_piece[F(f, k)] = id;
      for (int k = 0; k < 3; ++k) {
        const int g = across[f][k];
        if (g >= 0 && piece[g] < 0 && face_chart[g] == chart) queue.push_back(g);
      }
    }
  }
  return count;
}

}  // namespace akvf
