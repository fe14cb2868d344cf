#include "framework/mesh/manifold_repair.h"

#include <algorithm>
#include <numeric>

#include "framework/mesh/mesh_topology.h"

namespace akvf {

namespace {

constexpr std::size_t kListed = 5;

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

ManifoldRepair repair_manifold(TriMesh* mesh, std::vector<int>* input_vertex,
                               const std::vector<std::pair<int, int>>& open) {
  ManifoldRepair repair;
  const int nf = mesh->num_faces();
  const Eigen::MatrixXi& F = mesh->F;
  // Each undirected edge's sides, by (smaller end, larger end), in file order.
  const std::vector<HalfEdge> sides = sorted_half_edges(F, mesh->num_vertices());
  // Corners 3 f + k joined across edges of exactly two faces.
  std::vector<int> parent(3 * static_cast<std::size_t>(nf));
  std::iota(parent.begin(), parent.end(), 0);
  auto corner_of = [&](int f, int v) {
    for (int k = 0; k < 3; ++k)
      if (F(f, k) == v) return 3 * f + k;
    return -1;
  };
  auto join = [&](int f, int g, const std::pair<int, int>& edge) {
    for (const int v : {edge.first, edge.second}) {
      const int a = corner_of(f, v), b = corner_of(g, v);
      if (a >= 0 && b >= 0) parent[find(parent, a)] = find(parent, b);
    }
  };
  // Each run of sides with the same ends is one edge's corners.
  for (std::size_t i = 0; i < sides.size();) {
    const std::pair<int, int> edge{sides[i].lo, sides[i].hi};
    std::size_t end = i + 1;
    while (end < sides.size() && sides[end].lo == edge.first && sides[end].hi == edge.second) ++end;
    const HalfEdge* faces = sides.data() + i;
    const std::size_t count = end - i;
    i = end;
    if (count == 2) {
      if (faces[0].face != faces[1].face && !std::binary_search(open.begin(), open.end(), edge))
        join(faces[0].face, faces[1].face, edge);
      continue;
    }
    if (count < 2) continue;
    // Three or more faces: the first two (in file order) that run along the
    // edge in opposite directions stay joined, the others come off.
    ++repair.opened_edges;
    if (repair.first_opened.size() < kListed)
      repair.first_opened.push_back({(*input_vertex)[edge.first], (*input_vertex)[edge.second]});
    auto forward = [&](const HalfEdge& side) { return F(side.face, side.corner) == edge.first; };
    bool joined = false;
    for (std::size_t a = 0; a < count && !joined; ++a)
      for (std::size_t b = a + 1; b < count && !joined; ++b)
        if (forward(faces[a]) != forward(faces[b]) && faces[a].face != faces[b].face) {
          join(faces[a].face, faces[b].face, edge);
          joined = true;
        }
  }
  // Per vertex, its fans (classes of corners): the first keeps the vertex.
  std::vector<int> fan_of_root(parent.size(), -1);  // root corner -> vertex it became
  std::vector<int> fans(mesh->num_vertices(), 0);
  std::vector<Eigen::RowVector3d> copies;
  Eigen::MatrixXi G = F;
  for (int c = 0; c < 3 * nf; ++c) {
    const int root = find(parent, c), v = F(c / 3, c % 3);
    if (fan_of_root[root] < 0) {
      if (fans[v]++ == 0) {
        fan_of_root[root] = v;
      } else {
        fan_of_root[root] = mesh->num_vertices() + static_cast<int>(copies.size());
        copies.push_back(mesh->V.row(v));
        input_vertex->push_back((*input_vertex)[v]);
        ++repair.added_copies;
        if (fans[v] == 2) {
          ++repair.split_vertices;
          if (repair.first_split.size() < kListed) repair.first_split.push_back((*input_vertex)[v]);
        }
      }
    }
    G(c / 3, c % 3) = fan_of_root[root];
  }
  if (!copies.empty()) {
    const Eigen::Index n = mesh->V.rows();
    mesh->V.conservativeResize(n + static_cast<Eigen::Index>(copies.size()), 3);
    for (std::size_t i = 0; i < copies.size(); ++i) mesh->V.row(n + static_cast<Eigen::Index>(i)) = copies[i];
  }
  mesh->F = std::move(G);
  return repair;
}

std::string repair_description(const ManifoldRepair& repair, const std::string& name, int index_base) {
  if (!repair.any()) return "";
  auto list = [&](const std::vector<int>& first, int count) {
    std::string text;
    for (const int v : first) text += (text.empty() ? "" : ", ") + file_number(v, index_base);
    return text + (count > static_cast<int>(first.size()) ? ", ..." : "");
  };
  auto count = [](int n, const std::string& one, const std::string& many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  std::vector<std::string> parts;
  if (repair.opened_edges > 0) {
    std::string edges;
    for (const auto& [a, b] : repair.first_opened)
      edges += (edges.empty() ? "(" : ", (") + file_number(a, index_base) + ", " + file_number(b, index_base) + ")";
    parts.push_back("opened " + count(repair.opened_edges, "edge", "edges") + " shared by three or more faces (" +
                    edges + (repair.opened_edges > static_cast<int>(repair.first_opened.size()) ? ", ...)" : ")"));
  }
  if (repair.split_vertices > 0)
    parts.push_back("split " + count(repair.split_vertices, "non-manifold vertex", "non-manifold vertices") + " (" +
                    list(repair.first_split, repair.split_vertices) + ") into one copy per fan of faces, " +
                    count(repair.added_copies, "copy", "copies") + " added");
  std::string text = name + ": repaired: ";
  for (std::size_t i = 0; i < parts.size(); ++i) text += (i > 0 ? "; " : "") + parts[i];
  return text + numbering_note(index_base) + "; the UV is per corner there (--repair none refuses such input)";
}

}  // namespace akvf
