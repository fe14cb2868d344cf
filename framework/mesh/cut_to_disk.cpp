#include "framework/mesh/cut_to_disk.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <queue>
#include <unordered_map>

#include "akvf/error.h"
#include "framework/mesh/corner_copies.h"
#include "framework/mesh/mesh_topology.h"

namespace akvf {

namespace {

// An edge of the closed-up surface: a real edge of the mesh or a cone edge
// (hole vertex to a boundary vertex), with the two faces beside it (real
// faces first, then one cone face per boundary edge).
struct Edge {
  int a, b;
  int face[2];
  double length;
  bool real;
};

// The mesh with a cone on every boundary loop: vertices [0, nv) real and
// nv + h the cone vertex of loop h.
struct ClosedSurface {
  int num_vertices = 0, num_faces = 0;
  std::vector<Edge> edges;
  std::vector<int> adjacency_offsets, adjacency;  // edges at each vertex (CSR)
  std::vector<std::vector<int>> loops;
};

ClosedSurface close_surface(const TriMesh& mesh) {
  const int nv = mesh.num_vertices(), nf = mesh.num_faces();
  const Eigen::MatrixXi& F = mesh.F;
  ClosedSurface s;
  std::unordered_map<std::int64_t, int> edge_of;
  edge_of.reserve(3 * static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      const auto [it, inserted] = edge_of.emplace(undirected_edge_key(a, b, nv), static_cast<int>(s.edges.size()));
      if (inserted) {
        s.edges.push_back({std::min(a, b), std::max(a, b), {f, -1}, (mesh.V.row(a) - mesh.V.row(b)).norm(), true});
      } else {
        s.edges[it->second].face[1] = f;
      }
    }
  s.loops = boundary_loops(edge_topology(F), nv);
  int cone_face = nf;
  for (std::size_t h = 0; h < s.loops.size(); ++h) {
    const std::vector<int>& loop = s.loops[h];
    const int n = static_cast<int>(loop.size()), first_face = cone_face;
    const int cone = nv + static_cast<int>(h);
    for (int i = 0; i < n; ++i)  // the cone face over boundary edge (loop[i], loop[i + 1])
      s.edges[edge_of.at(undirected_edge_key(loop[i], loop[(i + 1) % n], nv))].face[1] = cone_face++;
    for (int i = 0; i < n; ++i)
      s.edges.push_back({cone, loop[i], {first_face + (i + n - 1) % n, first_face + i}, 0.0, false});
  }
  s.num_vertices = nv + static_cast<int>(s.loops.size());
  s.num_faces = cone_face;
  s.adjacency_offsets.assign(s.num_vertices + 1, 0);
  for (const Edge& e : s.edges) {
    ++s.adjacency_offsets[e.a + 1];
    ++s.adjacency_offsets[e.b + 1];
  }
  for (int v = 0; v < s.num_vertices; ++v) s.adjacency_offsets[v + 1] += s.adjacency_offsets[v];
  s.adjacency.resize(s.adjacency_offsets.back());
  std::vector<int> fill(s.adjacency_offsets.begin(), s.adjacency_offsets.end() - 1);
  for (int e = 0; e < static_cast<int>(s.edges.size()); ++e) {
    s.adjacency[fill[s.edges[e].a]++] = e;
    s.adjacency[fill[s.edges[e].b]++] = e;
  }
  return s;
}

int other_end(const Edge& e, int v) { return e.a == v ? e.b : e.a; }

// Shortest-path distances from the sources along the edges, and the edge
// by which each vertex was reached (-1 for sources and unreached vertices).
struct PathTree {
  std::vector<double> distance;
  std::vector<int> parent_edge;
};

PathTree shortest_paths(const ClosedSurface& s, const std::vector<int>& sources) {
  PathTree tree;
  tree.distance.assign(s.num_vertices, std::numeric_limits<double>::infinity());
  tree.parent_edge.assign(s.num_vertices, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int v : sources) {
    tree.distance[v] = 0;
    queue.push({0.0, v});
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > tree.distance[v]) continue;
    for (int i = s.adjacency_offsets[v]; i < s.adjacency_offsets[v + 1]; ++i) {
      const Edge& e = s.edges[s.adjacency[i]];
      const int w = other_end(e, v);
      if (d + e.length < tree.distance[w]) {
        tree.distance[w] = d + e.length;
        tree.parent_edge[w] = s.adjacency[i];
        queue.push({tree.distance[w], w});
      }
    }
  }
  return tree;
}

// Per component, the vertex farthest (in tree distance) from its source.
std::vector<int> farthest_per_component(const PathTree& tree, const std::vector<int>& component, int num_components) {
  std::vector<int> farthest(num_components, -1);
  for (std::size_t v = 0; v < component.size(); ++v) {
    const int c = component[v];
    if (c >= 0 && (farthest[c] < 0 || tree.distance[v] > tree.distance[farthest[c]])) farthest[c] = static_cast<int>(v);
  }
  return farthest;
}

// The joins of the real interior edges that are not cut.
std::vector<FaceJoin> uncut_joins(const std::vector<Edge>& edges, int nf, const std::vector<char>& cut) {
  std::vector<FaceJoin> joins;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Edge& edge = edges[e];
    if (!edge.real || edge.face[1] < 0 || edge.face[1] >= nf || cut[e]) continue;  // cone, boundary or cut edges
    joins.push_back({edge.face[0], edge.face[1], edge.a, edge.b});
  }
  return joins;
}

}  // namespace

DiskCut cut_to_disks(const TriMesh& mesh) {
  const int nv = mesh.num_vertices(), nf = mesh.num_faces();
  const Eigen::MatrixXi& F = mesh.F;
  DiskCut out;
  std::vector<int> component = vertex_components(F, nv, &out.num_charts);
  const ClosedSurface s = close_surface(mesh);
  // A vertex whose corners form several fans across the uncut edges is not
  // manifold (the count of a surface's genus and the cut assume it is).
  {
    const CornerCopies uncut = split_corners(F, nv, uncut_joins(s.edges, nf, std::vector<char>(s.edges.size(), 0)));
    for (std::size_t i = 1; i < uncut.source_vertex.size(); ++i)
      if (uncut.source_vertex[i] == uncut.source_vertex[i - 1]) {
        out.nonmanifold_vertex = uncut.source_vertex[i];
        return out;
      }
  }
  for (std::size_t h = 0; h < s.loops.size(); ++h) component.push_back(component[s.loops[h].front()]);

  // Genus per component from its Euler characteristic and boundary loops.
  const int charts = out.num_charts;
  std::vector<long long> euler(charts, 0);
  out.chart_loops.assign(charts, 0);
  for (int v = 0; v < nv; ++v) ++euler[component[v]];
  for (const Edge& e : s.edges)
    if (e.real) --euler[component[e.a]];
  for (int f = 0; f < nf; ++f) ++euler[component[F(f, 0)]];
  for (std::size_t h = 0; h < s.loops.size(); ++h) ++out.chart_loops[component[nv + h]];
  out.chart_genus.resize(charts);
  for (int c = 0; c < charts; ++c) out.chart_genus[c] = static_cast<int>((2 - euler[c] - out.chart_loops[c]) / 2);

  // Roots: a cone vertex where the component has boundary; otherwise the end
  // of a double sweep from its first vertex.
  std::vector<int> root(charts, -1), first_vertex(charts, -1);
  for (int v = s.num_vertices - 1; v >= 0; --v) first_vertex[component[v]] = v;
  for (std::size_t h = s.loops.size(); h-- > 0;) root[component[nv + h]] = nv + static_cast<int>(h);
  std::vector<int> sweep_sources;
  for (int c = 0; c < charts; ++c)
    if (root[c] < 0) sweep_sources.push_back(first_vertex[c]);
  if (!sweep_sources.empty()) {
    const std::vector<int> far = farthest_per_component(shortest_paths(s, sweep_sources), component, charts);
    for (int c = 0; c < charts; ++c)
      if (root[c] < 0) root[c] = far[c];
  }
  const PathTree tree = shortest_paths(s, root);

  // Kept ends of the cut graph: the cone vertices, and both ends of the
  // diameter path of a closed genus-0 component.
  std::vector<char> kept(s.num_vertices, 0);
  for (int v = nv; v < s.num_vertices; ++v) kept[v] = 1;
  const std::vector<int> far = farthest_per_component(tree, component, charts);
  for (int c = 0; c < charts; ++c)
    if (out.chart_loops[c] == 0 && out.chart_genus[c] == 0) kept[root[c]] = kept[far[c]] = 1;

  // The dual spanning tree of the edges outside T, longest loops first.
  const int num_edges = static_cast<int>(s.edges.size());
  std::vector<char> in_tree(num_edges, 0);
  for (int v = 0; v < s.num_vertices; ++v)
    if (tree.parent_edge[v] >= 0) in_tree[tree.parent_edge[v]] = 1;
  std::vector<int> candidates;
  std::vector<double> loop_length(num_edges, 0);
  for (int e = 0; e < num_edges; ++e) {
    if (in_tree[e]) continue;
    candidates.push_back(e);
    loop_length[e] = tree.distance[s.edges[e].a] + s.edges[e].length + tree.distance[s.edges[e].b];
  }
  std::stable_sort(candidates.begin(), candidates.end(), [&](int x, int y) { return loop_length[x] > loop_length[y]; });
  DisjointSets faces(s.num_faces);
  std::vector<char> in_graph(num_edges, 1);  // the cut graph: every edge outside the dual tree
  for (int e : candidates)
    if (faces.unite(s.edges[e].face[0], s.edges[e].face[1])) in_graph[e] = 0;

  // Prune dangling branches down to the kept vertices.
  std::vector<int> degree(s.num_vertices, 0), leaves;
  for (int e = 0; e < num_edges; ++e)
    if (in_graph[e]) ++degree[s.edges[e].a], ++degree[s.edges[e].b];
  for (int v = 0; v < s.num_vertices; ++v)
    if (degree[v] == 1 && !kept[v]) leaves.push_back(v);
  while (!leaves.empty()) {
    const int v = leaves.back();
    leaves.pop_back();
    if (degree[v] != 1) continue;
    for (int i = s.adjacency_offsets[v]; i < s.adjacency_offsets[v + 1]; ++i) {
      const int e = s.adjacency[i];
      if (!in_graph[e]) continue;
      in_graph[e] = 0;
      --degree[v];
      const int w = other_end(s.edges[e], v);
      if (--degree[w] == 1 && !kept[w]) leaves.push_back(w);
      break;
    }
  }

  // A closed genus-0 component whose far end is a neighbour of the root
  // (a tetrahedron, say) would open into a 2-gon, which has no planar map:
  // the path is extended by one more edge at its far end, so the boundary
  // has at least 4 edges (cutting along any simple path of a sphere still
  // leaves a disk).
  for (int c = 0; c < charts; ++c) {
    if (out.chart_loops[c] != 0 || out.chart_genus[c] != 0) continue;
    const int end = far[c], parent = tree.parent_edge[end];
    if (parent < 0 || other_end(s.edges[parent], end) != root[c]) continue;
    for (int i = s.adjacency_offsets[end]; i < s.adjacency_offsets[end + 1]; ++i)
      if (other_end(s.edges[s.adjacency[i]], end) != root[c]) {
        in_graph[s.adjacency[i]] = 1;
        break;
      }
  }
  std::vector<char> cut(num_edges, 0);
  for (int e = 0; e < num_edges; ++e) cut[e] = in_graph[e] && s.edges[e].real && s.edges[e].face[1] < nf;
  out.cut_edges = static_cast<int>(std::count(cut.begin(), cut.end(), 1));
  for (int e = 0; e < num_edges; ++e)
    if (cut[e]) out.cut_length += s.edges[e].length;
  const CornerCopies copies = split_corners(F, nv, uncut_joins(s.edges, nf, cut));
  out.source_vertex = copies.source_vertex;
  out.mesh.V.resize(static_cast<Eigen::Index>(out.source_vertex.size()), 3);
  for (std::size_t i = 0; i < out.source_vertex.size(); ++i) out.mesh.V.row(i) = mesh.V.row(out.source_vertex[i]);
  out.mesh.F.resize(nf, 3);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) out.mesh.F(f, k) = copies.copy_of_corner[3 * f + k];
  out.mesh.index_base = mesh.index_base;
  out.face_chart.resize(nf);
  for (int f = 0; f < nf; ++f) out.face_chart[f] = component[F(f, 0)];
  return out;
}

}  // namespace akvf
