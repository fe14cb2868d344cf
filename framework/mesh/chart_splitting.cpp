#include "framework/mesh/chart_splitting.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "framework/mesh/mesh_topology.h"
#include "framework/mesh/plane_geometry.h"

namespace akvf {

namespace {

constexpr int kDirections = 16, kOffsets = 16;

// The hull area less the area of each set of faces.
std::vector<double> waste_of(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV,
                             const std::vector<std::vector<int>>& sets) {
  std::vector<double> waste(sets.size(), 0);
  for (std::size_t s = 0; s < sets.size(); ++s) {
    std::vector<Eigen::Vector2d> points;
    double area = 0;
    for (int f : sets[s]) {
      area += triangle_area(F, UV, f);
      for (int k = 0; k < 3; ++k) points.push_back(UV.row(F(f, k)).transpose());
    }
    waste[s] = std::max(0.0, polygon_area(convex_hull(std::move(points))) - area);
  }
  return waste;
}

int find(std::vector<int>& parent, int a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

}  // namespace

std::vector<double> chart_waste(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, const std::vector<int>& face_chart,
                                int num_charts) {
  std::vector<std::vector<int>> faces(num_charts);
  for (int f = 0; f < F.rows(); ++f) faces[face_chart[f]].push_back(f);
  return waste_of(F, UV, faces);
}

std::vector<double> chart_areas(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, const std::vector<int>& face_chart,
                                int num_charts) {
  std::vector<double> area(num_charts, 0);
  for (int f = 0; f < F.rows(); ++f) area[face_chart[f]] += triangle_area(F, UV, f);
  return area;
}

std::vector<ChartSplit> straight_splits(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV,
                                        const std::vector<int>& face_chart, int num_charts, int chart, int count,
                                        const std::function<bool(const ChartSplit&)>& accept, SplitRank rank) {
  std::vector<int> faces;
  for (int f = 0; f < F.rows(); ++f)
    if (face_chart[f] == chart) faces.push_back(f);
  std::vector<ChartSplit> best;  // at most `count`, least waste first
  if (faces.size() < 2) return best;
  const int n = static_cast<int>(faces.size());
  const int num_vertices = static_cast<int>(UV.rows());
  // The chart's edges: interior ones join two of its faces (local numbers),
  // boundary ones belong to one. A piece's hull is its boundary's, which
  // runs along the chart's boundary and the cut.
  struct Edge {
    int face, other, a, b;  // other = -1 on the boundary
  };
  std::vector<Edge> edges;
  {
    std::unordered_map<std::int64_t, int> first;
    first.reserve(3 * faces.size());
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        const int f = faces[i], a = F(f, k), b = F(f, (k + 1) % 3);
        const auto [it, inserted] = first.emplace(undirected_edge_key(a, b, num_vertices), edges.size());
        if (inserted)
          edges.push_back({i, -1, a, b});
        else
          edges[it->second].other = i;
      }
  }
  std::vector<Eigen::Vector2d> centroid(n);
  std::vector<double> face_area(n);
  for (int i = 0; i < n; ++i) {
    centroid[i] = (UV.row(F(faces[i], 0)) + UV.row(F(faces[i], 1)) + UV.row(F(faces[i], 2))).transpose() / 3;
    face_area[i] = triangle_area(F, UV, faces[i]);
  }

  std::vector<int> parent(n), side(n), piece_of(n), stamp(num_vertices, -1);
  int stamps = 0;
  for (int direction = 0; direction < kDirections; ++direction) {
    const double angle = direction * M_PI / kDirections;
    const Eigen::Vector2d normal(std::cos(angle), std::sin(angle));
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Eigen::Vector2d& c : centroid) {
      lo = std::min(lo, normal.dot(c));
      hi = std::max(hi, normal.dot(c));
    }
    for (int step = 1; step < kOffsets; ++step) {
      const double offset = lo + (hi - lo) * step / kOffsets;
      for (int i = 0; i < n; ++i) side[i] = normal.dot(centroid[i]) > offset;
      std::iota(parent.begin(), parent.end(), 0);
      for (const Edge& e : edges)
        if (e.other >= 0 && side[e.face] == side[e.other]) parent[find(parent, e.face)] = find(parent, e.other);
      std::vector<int> piece_of_root(n, -1);
      std::vector<std::vector<int>> pieces;  // local face numbers
      for (int i = 0; i < n; ++i) {
        int& piece = piece_of_root[find(parent, i)];
        if (piece < 0) {
          piece = static_cast<int>(pieces.size());
          pieces.emplace_back();
        }
        piece_of[i] = piece;
        pieces[piece].push_back(i);
      }
      if (pieces.size() < 2) continue;
      // Each piece's boundary: its points (for the hull) and edge count.
      std::vector<std::vector<Eigen::Vector2d>> outline(pieces.size());
      std::vector<long> boundary_edges(pieces.size(), 0);
      for (const Edge& e : edges) {
        if (e.other >= 0 && piece_of[e.face] == piece_of[e.other]) continue;
        for (int i : {e.face, e.other}) {
          if (i < 0) continue;
          outline[piece_of[i]].push_back(UV.row(e.a).transpose());
          outline[piece_of[i]].push_back(UV.row(e.b).transpose());
          ++boundary_edges[piece_of[i]];
        }
      }
      double total = 0;
      double largest = 0, smallest = std::numeric_limits<double>::infinity();
      for (std::size_t p = 0; p < pieces.size(); ++p) {
        double area = 0;
        for (int i : pieces[p]) area += face_area[i];
        total += std::max(0.0, polygon_area(convex_hull(std::move(outline[p]))) - area);
        largest = std::max(largest, area);
        smallest = std::min(smallest, area);
      }
      const double key = rank == SplitRank::kEvenPieces ? total + (largest - smallest) : total;
      if (static_cast<int>(best.size()) == count && key >= best.back().rank) continue;
      // A disk: V - E + F = 1 (connected and part of a disk, so genus 0;
      // then one boundary loop), with E = (3 F + boundary edges) / 2.
      bool disks = true;
      for (std::size_t p = 0; p < pieces.size() && disks; ++p) {
        long vertices = 0;
        for (int i : pieces[p])
          for (int k = 0; k < 3; ++k)
            if (int& mark = stamp[F(faces[i], k)]; mark != stamps) {
              mark = stamps;
              ++vertices;
            }
        ++stamps;
        const long face_count = static_cast<long>(pieces[p].size());
        disks = vertices - (3 * face_count + boundary_edges[p]) / 2 + face_count == 1;
      }
      if (!disks) continue;
      ChartSplit split;
      split.face_chart = face_chart;
      split.num_charts = num_charts;
      for (std::size_t p = 1; p < pieces.size(); ++p) {
        for (int i : pieces[p]) split.face_chart[faces[i]] = split.num_charts;
        ++split.num_charts;
      }
      split.waste = total;
      split.rank = key;
      if (!accept(split)) continue;
      const auto at = std::upper_bound(best.begin(), best.end(), key,
                                       [](double k, const ChartSplit& other) { return k < other.rank; });
      best.insert(at, std::move(split));
      if (static_cast<int>(best.size()) > count) best.pop_back();
    }
  }
  return best;
}

}  // namespace akvf
