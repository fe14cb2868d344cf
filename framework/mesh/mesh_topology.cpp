#include "framework/mesh/mesh_topology.h"

#include <algorithm>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "akvf/error.h"

namespace akvf {

std::vector<HalfEdge> sorted_half_edges(const Eigen::MatrixXi& F, int num_vertices) {
  std::vector<int> bucket_start(num_vertices + 1, 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++bucket_start[std::min(F(f, k), F(f, (k + 1) % 3)) + 1];
  std::partial_sum(bucket_start.begin(), bucket_start.end(), bucket_start.begin());
  std::vector<HalfEdge> half_edges(3 * static_cast<std::size_t>(F.rows()));
  {
    std::vector<int> next(bucket_start.begin(), bucket_start.end() - 1);
    for (int f = 0; f < F.rows(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = F(f, k), b = F(f, (k + 1) % 3);
        half_edges[next[std::min(a, b)]++] = {std::min(a, b), std::max(a, b), f, k};
      }
  }
  for (int v = 0; v < num_vertices; ++v)
    std::sort(half_edges.begin() + bucket_start[v], half_edges.begin() + bucket_start[v + 1],
              [](const HalfEdge& x, const HalfEdge& y) {
                return std::tie(x.hi, x.face, x.corner) < std::tie(y.hi, y.face, y.corner);
              });
  return half_edges;
}

EdgeTopology edge_topology(const Eigen::MatrixXi& F) {
  if (F.size() > 0 && F.minCoeff() < 0) throw ValidationError("edge_topology: a face has a negative vertex index");
  const std::vector<HalfEdge> half_edges = sorted_half_edges(F, F.size() > 0 ? F.maxCoeff() + 1 : 0);
  const auto from = [&](const HalfEdge& h) { return F(h.face, h.corner); };
  EdgeTopology topology;
  for (std::size_t i = 0; i < half_edges.size();) {
    std::size_t j = i;
    while (j < half_edges.size() && half_edges[j].lo == half_edges[i].lo && half_edges[j].hi == half_edges[i].hi) ++j;
    const HalfEdge& h = half_edges[i];
    const std::size_t count = j - i;
    ++topology.num_edges;
    if (count == 1) {
      topology.boundary_half_edges.emplace_back(from(h), from(h) == h.lo ? h.hi : h.lo);
    } else if (count == 2) {
      if (from(half_edges[i]) == from(half_edges[i + 1]) && topology.misoriented_edge.empty())
        topology.misoriented_edge = {h.lo, h.hi, half_edges[i].face, half_edges[i + 1].face};
    } else if (topology.overused_edge.empty()) {
      topology.overused_edge = {h.lo, h.hi, static_cast<int>(count)};
    }
    i = j;
  }
  return topology;
}

DisjointSets::DisjointSets(int size) : parent_(size) { std::iota(parent_.begin(), parent_.end(), 0); }

int DisjointSets::find(int i) {
  while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
  return i;
}

bool DisjointSets::unite(int a, int b) {
  a = find(a);
  b = find(b);
  if (a == b) return false;
  parent_[std::max(a, b)] = std::min(a, b);
  return true;
}

std::vector<int> vertex_components(const Eigen::MatrixXi& elements, int num_vertices, int* count) {
  DisjointSets sets(num_vertices);
  for (int e = 0; e < elements.rows(); ++e)
    for (int k = 1; k < elements.cols(); ++k) sets.unite(elements(e, 0), elements(e, k));
  std::vector<int> component(num_vertices, -1), of_root(num_vertices, -1);
  int components = 0;
  for (int e = 0; e < elements.rows(); ++e)
    for (int k = 0; k < elements.cols(); ++k) {
      const int v = elements(e, k), root = sets.find(v);
      if (of_root[root] < 0) of_root[root] = components++;
      component[v] = of_root[root];
    }
  if (count) *count = components;
  return component;
}

int count_components(const Eigen::MatrixXi& F, int num_vertices) {
  int components = 0;
  vertex_components(F, num_vertices, &components);
  return components;
}

std::vector<std::vector<int>> boundary_loops(const EdgeTopology& topology, int num_vertices) {
  std::vector<int> next(num_vertices, -1);
  for (const auto& [a, b] : topology.boundary_half_edges) {
    if (next[a] != -1)
      throw ValidationError("vertex " + std::to_string(a) + " is non-manifold: two separate boundary fans meet there");
    next[a] = b;
  }
  std::vector<std::vector<int>> loops;
  std::vector<char> visited(num_vertices, 0);
  for (const auto& [start, unused] : topology.boundary_half_edges) {
    if (visited[start]) continue;
    std::vector<int> loop;
    for (int v = start; !visited[v]; v = next[v]) {
      if (next[v] == -1)
        throw ValidationError("boundary is not closed at vertex " + std::to_string(v) + " (non-manifold mesh)");
      visited[v] = 1;
      loop.push_back(v);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

VertexFaces vertex_faces(const Eigen::MatrixXi& F, int num_vertices) {
  VertexFaces result;
  result.offsets.assign(num_vertices + 1, 0);
  const int corners = static_cast<int>(F.cols());
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < corners; ++k) ++result.offsets[F(f, k) + 1];
  std::partial_sum(result.offsets.begin(), result.offsets.end(), result.offsets.begin());
  result.face_corner.resize(result.offsets.back());
  std::vector<int> fill(result.offsets.begin(), result.offsets.end() - 1);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < corners; ++k) result.face_corner[fill[F(f, k)]++] = corners * f + k;
  return result;
}

std::vector<std::array<int, 3>> faces_across_edges(const Eigen::MatrixXi& F, int num_vertices) {
  const int nf = static_cast<int>(F.rows());
  std::vector<std::array<int, 3>> across(nf, {-1, -1, -1});
  std::unordered_map<std::int64_t, int> first_side;  // edge -> 3 f + k of its first face
  first_side.reserve(3 * static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const auto [it, inserted] =
          first_side.emplace(undirected_edge_key(F(f, k), F(f, (k + 1) % 3), num_vertices), 3 * f + k);
      if (!inserted) {
        across[f][k] = it->second / 3;
        across[it->second / 3][it->second % 3] = f;
      }
    }
  return across;
}

}  // namespace akvf
