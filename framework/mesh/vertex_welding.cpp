#include "framework/mesh/vertex_welding.h"

#include <algorithm>
#include <numeric>

#include "framework/mesh/mesh_topology.h"

namespace akvf {

namespace {

constexpr std::size_t kFirstFew = 5;

}  // namespace

VertexWelding weld_exact_duplicates(const TriMesh& mesh, TriMesh* welded) {
  const int nv = mesh.num_vertices(), nf = mesh.num_faces();
  std::vector<int> first_face(nv, -1);
  for (int f = nf - 1; f >= 0; --f)
    for (int k = 0; k < 3; ++k) first_face[mesh.F(f, k)] = f;
  // The used vertices by position (then index): equal positions are adjacent.
  std::vector<int> order;
  for (int v = 0; v < nv; ++v)
    if (first_face[v] >= 0) order.push_back(v);
  const auto position_less = [&](int a, int b) {
    for (int c = 0; c < 3; ++c)
      if (mesh.V(a, c) != mesh.V(b, c)) return mesh.V(a, c) < mesh.V(b, c);
    return a < b;
  };
  std::sort(order.begin(), order.end(), position_less);
  const auto same_position = [&](std::size_t i) { return mesh.V.row(order[i]) == mesh.V.row(order[i - 1]); };
  VertexWelding welding;
  bool twins = false;
  for (std::size_t i = 1; i < order.size() && !twins; ++i) twins = same_position(i);
  if (!twins) return welding;
  // Pieces: faces joined across shared edges; a vertex's is its first face's.
  DisjointSets pieces(nf);
  const std::vector<std::array<int, 3>> across = faces_across_edges(mesh.F, nv);
  for (int f = 0; f < nf; ++f)
    for (const int g : across[f])
      if (g >= 0) pieces.unite(f, g);
  const auto piece = [&](int v) { return pieces.find(first_face[v]); };
  std::vector<int> target(nv);
  std::iota(target.begin(), target.end(), 0);
  int first = -1;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const int v = order[i];
    if (i == 0 || !same_position(i)) {
      first = v;
      continue;
    }
    // A twin in the same piece is the file's own seam (the sides of a cut
    // disk): kept apart.
    if (piece(v) == piece(first)) continue;
    target[v] = first;
    ++welding.welded;
  }
  if (welding.welded == 0) return welding;
  for (int v = 0; v < nv && welding.first_welded.size() < kFirstFew; ++v)
    if (target[v] != v) welding.first_welded.push_back(v);
  *welded = mesh;
  welded->F = mesh.F.unaryExpr([&](int v) { return target[v]; });
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
