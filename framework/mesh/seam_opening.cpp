#include "framework/mesh/seam_opening.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <queue>
#include <unordered_map>
#include <unordered_set>

#include "framework/mesh/corner_copies.h"
#include "framework/mesh/mesh_topology.h"

namespace akvf {

namespace {

std::vector<char> boundary_vertices(const Eigen::MatrixXi& F, int nv) {
  std::vector<char> on_boundary(nv, 0);
  for (const auto& [from, to] : edge_topology(F).boundary_half_edges) on_boundary[from] = on_boundary[to] = 1;
  return on_boundary;
}

}  // namespace

std::vector<std::vector<int>> seam_paths(const TriMesh& mesh, const std::vector<int>& starts) {
  const int nv = mesh.num_vertices();
  std::vector<char> end = boundary_vertices(mesh.F, nv);
  // Neighbours from the faces' edges (an interior edge is listed twice).
  std::vector<std::vector<int>> neighbours(nv);
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  std::vector<double> distance(nv, std::numeric_limits<double>::infinity());
  std::vector<int> parent(nv, -1), reached;
  std::vector<std::vector<int>> paths;
  using Item = std::pair<double, int>;
  for (int start : starts) {
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
      for (int w : neighbours[v]) {
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

}  // namespace akvf
