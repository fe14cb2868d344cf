#include "framework/mesh/seam_opening.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>
#include <unordered_map>
#include <unordered_set>

#include <Eigen/Geometry>

#include "framework/mesh/corner_copies.h"
#include "framework/mesh/mesh_topology.h"

namespace akvf {

namespace {

// A crease: faces whose normals differ by more than this (the angle at which
// Blender's auto smooth starts to show an edge as sharp); a walk along
// creases also turns by less at each vertex.
constexpr double kCreaseAngle = M_PI / 6;

// Whether an edge lies on a feature line: the normals of its two faces more
// than kCreaseAngle apart, and neither face as sharp across its other edges
// (a feature line parts two smooth sides; a crease among creases is the
// surface's noise). The faces across each edge are found at the first
// question.
class Creases {
 public:
  explicit Creases(const TriMesh& mesh) : mesh_(mesh) {}

  // Edge k of face f (from corner k to k + 1).
  bool operator()(int f, int k) {
    if (across_.empty()) across_ = faces_across_edges(mesh_.F, mesh_.num_vertices());
    const int g = across_[f][k];
    if (!sharp(f, k)) return false;
    for (int face : {f, g})
      for (int j = 0; j < 3; ++j)
        if (across_[face][j] != (face == f ? g : f) && sharp(face, j)) return false;
    return true;
  }

 private:
  bool sharp(int f, int k) const {
    const int g = across_[f][k];
    return g >= 0 && normal(f).dot(normal(g)) < std::cos(kCreaseAngle);
  }

  Eigen::Vector3d normal(int f) const {
    const Eigen::Vector3d p = mesh_.V.row(mesh_.F(f, 0)), q = mesh_.V.row(mesh_.F(f, 1)),
                          r = mesh_.V.row(mesh_.F(f, 2));
    return (q - p).cross(r - p).normalized();
  }

  const TriMesh& mesh_;
  std::vector<std::array<int, 3>> across_;
};

// Each vertex's neighbours, with the edge between them as 3 f + k (edge k
// of face f; an interior edge is listed twice).
using EdgeNeighbours = std::vector<std::vector<std::pair<int, int>>>;

// Goes on from the last vertex of *path (a seam's start and first edge) to
// the neighbour of highest energy above `above` across a crease edge, not
// an end, turning by less than kCreaseAngle; each vertex taken becomes an
// end (seam_paths' comment).
void walk_along_creases(const TriMesh& mesh, const EdgeNeighbours& neighbours, const std::vector<double>& energy,
                        double above, Creases* crease, std::vector<char>* end, std::vector<int>* path) {
  for (int w = path->back(), before = -1; energy[w] > above;) {
    const auto straight_on = [&](int u) {
      if (before < 0) return true;
      const Eigen::Vector3d along = (mesh.V.row(w) - mesh.V.row(before)).normalized();
      return along.dot((mesh.V.row(u) - mesh.V.row(w)).normalized()) > std::cos(kCreaseAngle);
    };
    int next = -1;
    for (const auto& [u, edge] : neighbours[w])
      if (!(*end)[u] && energy[u] > above && (next < 0 || energy[u] > energy[next]) && (*crease)(edge / 3, edge % 3) &&
          straight_on(u))
        next = u;
    if (next < 0) return;
    (*end)[next] = 1;
    path->push_back(next);
    before = w;
    w = next;
  }
}

std::vector<char> boundary_vertices(const Eigen::MatrixXi& F, int nv) {
  std::vector<char> on_boundary(nv, 0);
  for (const auto& [from, to] : edge_topology(F).boundary_half_edges) on_boundary[from] = on_boundary[to] = 1;
  return on_boundary;
}

}  // namespace

std::vector<std::vector<int>> seam_paths(const TriMesh& mesh, const std::vector<int>& starts,
                                         const std::vector<double>& energy, double crease_walk_above) {
  const int nv = mesh.num_vertices();
  const std::vector<char> on_boundary = boundary_vertices(mesh.F, nv);
  std::vector<char> end = on_boundary;
  EdgeNeighbours neighbours(nv);
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      neighbours[a].push_back({b, 3 * f + k});
      neighbours[b].push_back({a, 3 * f + k});
    }
  Creases crease(mesh);
  std::vector<double> distance(nv, std::numeric_limits<double>::infinity());
  std::vector<int> parent(nv, -1), reached;
  std::vector<std::vector<int>> paths;
  using Item = std::pair<double, int>;
  for (int start : starts) {
    if (on_boundary[start]) {
      int inward = -1;
      for (const auto& [w, edge] : neighbours[start])
        if (!end[w] && (inward < 0 || energy[w] > energy[inward])) inward = w;
      if (inward >= 0) {
        end[inward] = 1;
        std::vector<int> path{start, inward};
        walk_along_creases(mesh, neighbours, energy, crease_walk_above, &crease, &end, &path);
        std::reverse(path.begin(), path.end());
        paths.push_back(std::move(path));
      }
      continue;
    }
    if (end[start]) continue;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    distance[start] = 0;
    reached.push_back(start);
    queue.push({0.0, start});
    int found = -1;
    while (!queue.empty() && found < 0) {
      const auto [d, v] = queue.top();
      queue.pop();
      if (d > distance[v]) continue;
      if (end[v]) {
        found = v;
        break;
      }
      for (const auto& [w, edge] : neighbours[v]) {
        const double dw = d + (mesh.V.row(v) - mesh.V.row(w)).norm();
        if (dw < distance[w]) {
          if (distance[w] == std::numeric_limits<double>::infinity()) reached.push_back(w);
          distance[w] = dw;
          parent[w] = v;
          queue.push({dw, w});
        }
      }
    }
    if (found >= 0) {
      std::vector<int> path;
      for (int w = found; w >= 0; w = parent[w]) path.push_back(w);
      std::reverse(path.begin(), path.end());
      for (int w : path) end[w] = 1;
      paths.push_back(std::move(path));
    }
    for (int w : reached) {
      distance[w] = std::numeric_limits<double>::infinity();
      parent[w] = -1;
    }
    reached.clear();
  }
  return paths;
}

namespace {

// Opens `disk` along the edges whose keys (undirected_edge_key) are in
// `seam`, of total 3D length `length`, its faces then in the charts
// `face_chart` (num_charts of them, each a disk). Returns, for every new
// vertex, the vertex of the old mesh it copies.
std::vector<int> open_edges(DiskMesh* disk, const std::unordered_set<std::int64_t>& seam, double length,
                            std::vector<int> face_chart, int num_charts) {
  TriMesh& mesh = disk->mesh;
  const int nv = mesh.num_vertices(), nf = mesh.num_faces();
  // Every interior edge joins its two faces, except the seam's.
  std::unordered_map<std::int64_t, int> first_face;
  first_face.reserve(3 * static_cast<std::size_t>(nf));
  std::vector<FaceJoin> joins;
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      const std::int64_t key = undirected_edge_key(a, b, nv);
      const auto [it, inserted] = first_face.emplace(key, f);
      if (!inserted && !seam.count(key)) joins.push_back({it->second, f, a, b});
    }
  const CornerCopies copies = split_corners(mesh.F, nv, joins);
  TriMesh opened;
  opened.index_base = mesh.index_base;
  opened.V.resize(static_cast<Eigen::Index>(copies.source_vertex.size()), 3);
  std::vector<int> input_vertex(copies.source_vertex.size());
  std::vector<int> first_copy(nv, -1);
  for (std::size_t v = 0; v < copies.source_vertex.size(); ++v) {
    const int source = copies.source_vertex[v];
    opened.V.row(v) = mesh.V.row(source);
    input_vertex[v] = disk->input_vertex[source];
    if (first_copy[source] < 0) first_copy[source] = static_cast<int>(v);
  }
  opened.F.resize(nf, 3);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) opened.F(f, k) = copies.copy_of_corner[3 * f + k];

  // One loop per chart, in chart order (each chart is a disk).
  std::vector<int> chart_of_vertex(opened.num_vertices(), 0);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) chart_of_vertex[opened.F(f, k)] = face_chart[f];
  std::vector<std::vector<int>> loops(num_charts);
  for (auto& loop : boundary_loops(edge_topology(opened.F), opened.num_vertices()))
    loops[chart_of_vertex[loop.front()]] = std::move(loop);

  for (auto& corners : disk->removed_corners)
    for (CornerSource& source : corners) {
      if (source.a >= 0) source.a = first_copy[source.a];
      if (source.b >= 0) source.b = first_copy[source.b];
    }
  mesh = std::move(opened);
  disk->input_vertex = std::move(input_vertex);
  disk->boundary_loops = std::move(loops);
  disk->face_chart = std::move(face_chart);
  disk->cut_edges += static_cast<int>(seam.size());
  disk->cut_length += length;
  disk->cut = true;
  return copies.source_vertex;
}

}  // namespace

std::vector<int> open_seams(DiskMesh* disk, const std::vector<std::vector<int>>& paths) {
  const TriMesh& mesh = disk->mesh;
  const int nv = mesh.num_vertices();
  std::unordered_set<std::int64_t> seam;
  double length = 0;
  for (const std::vector<int>& path : paths)
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      seam.insert(undirected_edge_key(path[i], path[i + 1], nv));
      length += (mesh.V.row(path[i]) - mesh.V.row(path[i + 1])).norm();
    }
  return open_edges(disk, seam, length, disk->face_chart, disk->num_charts());
}

std::vector<int> split_charts(DiskMesh* disk, const std::vector<int>& face_chart, int num_charts) {
  const TriMesh& mesh = disk->mesh;
  const int nv = mesh.num_vertices();
  std::unordered_map<std::int64_t, int> first_face;
  std::unordered_set<std::int64_t> seam;
  double length = 0;
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      const std::int64_t key = undirected_edge_key(a, b, nv);
      const auto [it, inserted] = first_face.emplace(key, f);
      if (!inserted && face_chart[it->second] != face_chart[f] && seam.insert(key).second)
        length += (mesh.V.row(a) - mesh.V.row(b)).norm();
    }
  // Each piece keeps what its chart was before the cut.
  std::vector<int> genus(num_charts, 0), input_loops(num_charts, 0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int old_chart = disk->face_chart[f];
    if (old_chart < static_cast<int>(disk->chart_genus.size())) genus[face_chart[f]] = disk->chart_genus[old_chart];
    if (old_chart < static_cast<int>(disk->chart_input_loops.size()))
      input_loops[face_chart[f]] = disk->chart_input_loops[old_chart];
  }
  if (!disk->chart_genus.empty()) disk->chart_genus = std::move(genus);
  if (!disk->chart_input_loops.empty()) disk->chart_input_loops = std::move(input_loops);
  return open_edges(disk, seam, length, face_chart, num_charts);
}

namespace {

// The 3D-shortest path from `from` along edges that are not boundary edges
// to a boundary vertex other than `from`, through interior vertices not
// `blocked`: from, ..., that vertex; empty if there is none.
std::vector<int> path_to_boundary(const TriMesh& mesh, const std::vector<std::vector<int>>& neighbours,
                                  const std::vector<char>& on_boundary,
                                  const std::unordered_set<std::int64_t>& boundary_edges, int from,
                                  const std::vector<char>& blocked) {
  const int nv = mesh.num_vertices();
  std::unordered_map<int, double> distance{{from, 0.0}};
  std::unordered_map<int, int> parent;
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  queue.push({0.0, from});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v]) continue;
    if (v != from && on_boundary[v]) {
      std::vector<int> path;
      for (int w = v; w != from; w = parent[w]) path.push_back(w);
      path.push_back(from);
      std::reverse(path.begin(), path.end());
      return path;
    }
    for (int w : neighbours[v]) {
      if (blocked[w] || w == from || boundary_edges.count(undirected_edge_key(v, w, nv))) continue;
      const double dw = d + (mesh.V.row(v) - mesh.V.row(w)).norm();
      const auto it = distance.find(w);
      if (it == distance.end() || dw < it->second) {
        distance[w] = dw;
        parent[w] = v;
        queue.push({dw, w});
      }
    }
  }
  return {};
}

}  // namespace

std::vector<int> split_through(DiskMesh* disk, const std::vector<int>& through, int* parted) {
  const TriMesh& mesh = disk->mesh;
  const int nv = mesh.num_vertices(), nf = mesh.num_faces();
  const std::vector<std::array<int, 3>> across = faces_across_edges(mesh.F, nv);
  std::vector<std::vector<int>> neighbours(nv);
  std::unordered_set<std::int64_t> boundary_edges;
  std::vector<char> on_boundary(nv, 0);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      neighbours[a].push_back(b);
      if (across[f][k] >= 0) continue;
      neighbours[b].push_back(a);  // listed once from each side of an interior edge
      boundary_edges.insert(undirected_edge_key(a, b, nv));
      on_boundary[a] = on_boundary[b] = 1;
    }
  std::unordered_set<std::int64_t> cut;
  std::vector<char> blocked(nv, 0);
  for (std::size_t c = 0; c < through.size(); ++c) {
    if (through[c] < 0) continue;
    // From the vertex, or else (a corner of a single triangle on the
    // boundary has no path) from a neighbour.
    std::vector<int> candidates{through[c]};
    candidates.insert(candidates.end(), neighbours[through[c]].begin(), neighbours[through[c]].end());
    for (int v : candidates) {
      std::vector<int> chord = path_to_boundary(mesh, neighbours, on_boundary, boundary_edges, v, blocked);
      if (!chord.empty() && !on_boundary[v]) {
        for (int w : chord) blocked[w] = w != v;
        const std::vector<int> other = path_to_boundary(mesh, neighbours, on_boundary, boundary_edges, v, blocked);
        for (int w : chord) blocked[w] = 0;
        std::reverse(chord.begin(), chord.end());
        chord.insert(chord.end(), other.begin() + (other.empty() ? 0 : 1), other.end());
        if (other.empty()) chord.clear();
      }
      if (chord.empty()) continue;
      for (std::size_t i = 0; i + 1 < chord.size(); ++i) cut.insert(undirected_edge_key(chord[i], chord[i + 1], nv));
      break;
    }
  }
  // The faces of each parted chart reached from its first face without
  // crossing the cut keep its number; the others get a new one.
  std::vector<int> face_chart = disk->face_chart;
  std::vector<char> reached(nf, 0), parted_chart(disk->num_charts(), 0);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3 && !cut.empty(); ++k)
      if (cut.count(undirected_edge_key(mesh.F(f, k), mesh.F(f, (k + 1) % 3), nv))) parted_chart[face_chart[f]] = 1;
  std::vector<char> started(disk->num_charts(), 0);
  for (int seed = 0; seed < nf; ++seed) {
    const int chart = disk->face_chart[seed];
    if (!parted_chart[chart] || started[chart]) continue;
    started[chart] = 1;
    std::vector<int> stack{seed};
    reached[seed] = 1;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int g = across[f][k];
        if (g < 0 || reached[g] || cut.count(undirected_edge_key(mesh.F(f, k), mesh.F(f, (k + 1) % 3), nv))) continue;
        reached[g] = 1;
        stack.push_back(g);
      }
    }
  }
  int count = disk->num_charts();
  std::vector<int> second(disk->num_charts(), -1);
  for (int f = 0; f < nf; ++f) {
    const int chart = disk->face_chart[f];
    if (!parted_chart[chart] || reached[f]) continue;
    if (second[chart] < 0) second[chart] = count++;
    face_chart[f] = second[chart];
  }
  if (parted) *parted = count - disk->num_charts();
  return split_charts(disk, face_chart, count);
}

void part_seam_sides(const DiskMesh& disk, double fraction, Eigen::VectorXd* x) {
  const TriMesh& mesh = disk.mesh;
  const std::vector<int>& input_vertex = disk.input_vertex;
  const int nv = static_cast<int>(input_vertex.size());
  std::vector<Eigen::Vector2d> direction(nv, Eigen::Vector2d::Zero());
  std::vector<double> height(nv, std::numeric_limits<double>::infinity());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    Eigen::Vector2d p[3];
    for (int k = 0; k < 3; ++k) p[k] = x->segment<2>(2 * mesh.F(f, k));
    const double twice_area = (p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x();
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.F(f, k);
      height[v] = std::min(height[v], twice_area / (p[(k + 1) % 3] - p[(k + 2) % 3]).norm());
    }
  }
  // The loops keep the chart to their left: the inner angle at a vertex
  // turns counter-clockwise from the edge to the next vertex to the edge to
  // the previous one.
  for (const std::vector<int>& loop : disk.boundary_loops) {
    const int n = static_cast<int>(loop.size());
    for (int i = 0; i < n && n > 2; ++i) {
      const Eigen::Vector2d c = x->segment<2>(2 * loop[i]);
      const Eigen::Vector2d to_next = x->segment<2>(2 * loop[(i + 1) % n]) - c;
      const Eigen::Vector2d to_previous = x->segment<2>(2 * loop[(i + n - 1) % n]) - c;
      double angle =
          std::atan2(to_next.x() * to_previous.y() - to_next.y() * to_previous.x(), to_next.dot(to_previous));
      if (angle <= 0) angle += 2 * M_PI;
      const double half = 0.5 * angle, length = to_next.norm();
      if (length > 0)
        direction[loop[i]] = Eigen::Vector2d(std::cos(half) * to_next.x() - std::sin(half) * to_next.y(),
                                             std::sin(half) * to_next.x() + std::cos(half) * to_next.y()) /
                             length;
    }
  }
  // The copies of one input vertex, consecutive in `order`.
  std::vector<int> order(nv);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return input_vertex[a] < input_vertex[b]; });
  std::vector<Eigen::Vector2d> move(nv, Eigen::Vector2d::Zero());
  for (int i = 0, j = 0; i < nv; i = j) {
    for (j = i + 1; j < nv && input_vertex[order[j]] == input_vertex[order[i]];) ++j;
    for (int a = i; a < j; ++a)
      for (int b = i; b < j; ++b) {
        const int v = order[a], w = order[b];
        const double step = fraction * height[v];
        if (v != w && (x->segment<2>(2 * v) - x->segment<2>(2 * w)).norm() < step) move[v] = step * direction[v];
      }
  }
  for (int v = 0; v < nv; ++v) x->segment<2>(2 * v) += move[v];
}

}  // namespace akvf
