#include "framework/mesh/chart_splitting.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "framework/mesh/convex_hull.h"
#include "framework/mesh/mesh_topology.h"

namespace akvf {

namespace {

constexpr int kDirections = 16, kOffsets = 16;

double uv_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, int f) {
  const Eigen::RowVector2d a = UV.row(F(f, 1)) - UV.row(F(f, 0)), b = UV.row(F(f, 2)) - UV.row(F(f, 0));
  return 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
}

// The hull area less the area of each set of faces.
std::vector<double> waste_of(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV,
                             const std::vector<std::vector<int>>& sets) {
  std::vector<double> waste(sets.size(), 0);
  for (std::size_t s = 0; s < sets.size(); ++s) {
    std::vector<Eigen::Vector2d> points;
    double area = 0;
    for (int f : sets[s]) {
      area += uv_area(F, UV, f);
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

// Whether the faces form a disk: V - E + F = 1 (they are connected, and
// part of a disk, so of genus 0 with one boundary loop).
bool is_disk(const Eigen::MatrixXi& F, const std::vector<int>& faces, int num_vertices) {
  std::unordered_set<int> vertices;
  std::unordered_set<std::int64_t> edges;
  for (int f : faces)
    for (int k = 0; k < 3; ++k) {
      vertices.insert(F(f, k));
      edges.insert(undirected_edge_key(F(f, k), F(f, (k + 1) % 3), num_vertices));
    }
  return static_cast<long>(vertices.size()) - static_cast<long>(edges.size()) + static_cast<long>(faces.size()) == 1;
}

}  // namespace

double map_area(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV) {
  double area = 0;
  for (int f = 0; f < F.rows(); ++f) area += uv_area(F, UV, f);
  return area;
}

std::vector<double> chart_waste(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, const std::vector<int>& face_chart,
                                int num_charts) {
  std::vector<std::vector<int>> faces(num_charts);
  for (int f = 0; f < F.rows(); ++f) faces[face_chart[f]].push_back(f);
  return waste_of(F, UV, faces);
}

std::vector<ChartSplit> straight_splits(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV,
                                        const std::vector<int>& face_chart, int num_charts, int chart, int count,
                                        const std::function<bool(const ChartSplit&)>& accept) {
  std::vector<int> faces;
  for (int f = 0; f < F.rows(); ++f)
    if (face_chart[f] == chart) faces.push_back(f);
  std::vector<ChartSplit> best;  // at most `count`, least waste first
  if (faces.size() < 2) return best;
  const int n = static_cast<int>(faces.size());
  const int num_vertices = static_cast<int>(UV.rows());
  // The chart's interior edges, as pairs of its faces (local numbers).
  std::vector<std::array<int, 2>> joins;
  {
    std::unordered_map<std::int64_t, int> first;
    first.reserve(3 * faces.size());
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        const int f = faces[i];
        const auto [it, inserted] = first.emplace(undirected_edge_key(F(f, k), F(f, (k + 1) % 3), num_vertices), i);
        if (!inserted) joins.push_back({it->second, i});
      }
  }
  std::vector<Eigen::Vector2d> centroid(n);
  for (int i = 0; i < n; ++i)
    centroid[i] = (UV.row(F(faces[i], 0)) + UV.row(F(faces[i], 1)) + UV.row(F(faces[i], 2))).transpose() / 3;

  std::vector<int> parent(n), side(n);
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
      for (const auto& [a, b] : joins)
        if (side[a] == side[b]) parent[find(parent, a)] = find(parent, b);
      std::vector<int> piece_of_root(n, -1);
      std::vector<std::vector<int>> pieces;
      for (int i = 0; i < n; ++i) {
        int& piece = piece_of_root[find(parent, i)];
        if (piece < 0) {
          piece = static_cast<int>(pieces.size());
          pieces.emplace_back();
        }
        pieces[piece].push_back(faces[i]);
      }
      if (pieces.size() < 2) continue;
      const std::vector<double> waste = waste_of(F, UV, pieces);
      const double total = std::accumulate(waste.begin(), waste.end(), 0.0);
      if (static_cast<int>(best.size()) == count && total >= best.back().waste) continue;
      if (!std::all_of(pieces.begin(), pieces.end(),
                       [&](const std::vector<int>& p) { return is_disk(F, p, num_vertices); }))
        continue;
      ChartSplit split;
      split.face_chart = face_chart;
      split.num_charts = num_charts;
      for (std::size_t p = 1; p < pieces.size(); ++p) {
        for (int f : pieces[p]) split.face_chart[f] = split.num_charts;
        ++split.num_charts;
      }
      split.waste = total;
      if (!accept(split)) continue;
      const auto at = std::upper_bound(best.begin(), best.end(), total,
                                       [](double waste, const ChartSplit& other) { return waste < other.waste; });
      best.insert(at, std::move(split));
      if (static_cast<int>(best.size()) > count) best.pop_back();
    }
  }
  return best;
}

}  // namespace akvf
