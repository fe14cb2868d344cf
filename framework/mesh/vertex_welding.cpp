#include "framework/mesh/vertex_welding.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace akvf {

namespace {

constexpr std::size_t kFirstFew = 5;

// Union-find, the smaller index the root.
struct Components {
  std::vector<int> parent;
  explicit Components(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  }
  void join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

VertexWelding weld_exact_duplicates(TriMesh* mesh) {
  const int nv = mesh->num_vertices(), nf = mesh->num_faces();
  // Pieces: faces joined across shared edges; a vertex's piece is its first face's.
  Components pieces(nf);
  std::unordered_map<std::int64_t, int> edge_face;
  std::vector<int> piece_face(nv, -1);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh->F(f, k), b = mesh->F(f, (k + 1) % 3);
      if (piece_face[a] < 0) piece_face[a] = f;
      const auto [it, inserted] = edge_face.emplace(static_cast<std::int64_t>(std::min(a, b)) * nv + std::max(a, b), f);
      if (!inserted) pieces.join(it->second, f);
    }
  const auto piece = [&](int v) { return pieces.find(piece_face[v]); };
  // The used vertices by position (then index): equal positions are adjacent.
  std::vector<int> order;
  for (int v = 0; v < nv; ++v)
    if (piece_face[v] >= 0) order.push_back(v);
  const auto position_less = [&](int a, int b) {
    for (int c = 0; c < 3; ++c)
      if (mesh->V(a, c) != mesh->V(b, c)) return mesh->V(a, c) < mesh->V(b, c);
    return a < b;
  };
  std::sort(order.begin(), order.end(), position_less);
  std::vector<int> target(nv);
  std::iota(target.begin(), target.end(), 0);
  VertexWelding welding;
  for (std::size_t begin = 0, end = 0; begin < order.size(); begin = end) {
    const int first = order[begin];
    for (end = begin + 1; end < order.size() && mesh->V.row(order[end]) == mesh->V.row(first); ++end) {
      const int v = order[end];
      // A twin in the same piece is the file's own seam (the sides of a
      // cut disk): kept apart.
      if (piece(v) == piece(first)) continue;
      target[v] = first;
      ++welding.welded;
    }
  }
  if (welding.welded == 0) return welding;
  for (int v = 0; v < nv && welding.first_welded.size() < kFirstFew; ++v)
    if (target[v] != v) welding.first_welded.push_back(v);
  for (int f = 0; f < mesh->num_faces(); ++f)
    for (int k = 0; k < 3; ++k) mesh->F(f, k) = target[mesh->F(f, k)];
  return welding;
}

std::string welding_description(const VertexWelding& welding, const std::string& name, int index_base) {
  std::string first;
  for (const int v : welding.first_welded) first += (first.empty() ? "" : ", ") + file_number(v, index_base);
  if (welding.welded > static_cast<int>(welding.first_welded.size())) first += ", ...";
  return name + ": welded " + std::to_string(welding.welded) + (welding.welded == 1 ? " vertex" : " vertices") +
         " onto an earlier vertex at the same position in another piece (" + first + ")" + numbering_note(index_base) +
         "; their corners take that vertex's UV (--repair none keeps them apart)";
}

}  // namespace akvf
