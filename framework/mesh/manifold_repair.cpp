#include "framework/mesh/manifold_repair.h"

#include <algorithm>
#include <numeric>

namespace akvf {

namespace {

constexpr std::size_t kListed = 5;

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

ManifoldRepair repair_manifold(TriMesh* mesh, std::vector<int>* input_vertex) {
  ManifoldRepair repair;
  const int nf = mesh->num_faces();
  const Eigen::MatrixXi& F = mesh->F;
  // Each undirected edge's face corners (face, position of its first end),
  // edges by (smaller end, larger end), an edge's corners in file order:
  // the face sides counted by their smaller end, then each vertex's few
  // sorted by their larger end, stably (file order kept within an edge).
  const int nv = mesh->num_vertices();
  std::vector<int> side_start(nv + 1, 0);
  const auto low_end = [&](int f, int k) { return std::min(F(f, k), F(f, (k + 1) % 3)); };
  const auto high_end = [&](int f, int k) { return std::max(F(f, k), F(f, (k + 1) % 3)); };
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) ++side_start[low_end(f, k) + 1];
  for (int v = 0; v < nv; ++v) side_start[v + 1] += side_start[v];
  std::vector<std::pair<int, int>> sides(3 * static_cast<std::size_t>(nf));
  {
    std::vector<int> next(side_start.begin(), side_start.end() - 1);
    for (int f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) sides[next[low_end(f, k)]++] = {f, k};
  }
  const auto by_high_end = [&](const std::pair<int, int>& x, const std::pair<int, int>& y) {
    return high_end(x.first, x.second) < high_end(y.first, y.second);
  };
  for (int v = 0; v < nv; ++v) {
    const auto first = sides.begin() + side_start[v], last = sides.begin() + side_start[v + 1];
    if (last - first > 32) {  // a vertex of many faces (a fan's centre)
      std::stable_sort(first, last, by_high_end);
      continue;
    }
    for (auto i = first + 1; i < last; ++i) {  // by insertion: no buffer to allocate for a vertex's few sides
      const std::pair<int, int> side = *i;
      auto j = i;
      for (; j > first && by_high_end(side, *(j - 1)); --j) *j = *(j - 1);
      *j = side;
    }
  }
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
  const auto ends_of = [&](const std::pair<int, int>& side) {
    return std::pair<int, int>{low_end(side.first, side.second), high_end(side.first, side.second)};
  };
  for (std::size_t i = 0; i < sides.size();) {
    const std::pair<int, int> edge = ends_of(sides[i]);
    std::size_t end = i + 1;
    while (end < sides.size() && ends_of(sides[end]) == edge) ++end;
    const std::pair<int, int>* faces = sides.data() + i;
    const std::size_t count = end - i;
    i = end;
    if (count == 2) {
      if (faces[0].first != faces[1].first) join(faces[0].first, faces[1].first, edge);
      continue;
    }
    if (count < 2) continue;
    // Three or more faces: the first two (in file order) that run along the
    // edge in opposite directions stay joined, the others come off.
    ++repair.opened_edges;
    if (repair.first_opened.size() < kListed)
      repair.first_opened.push_back({(*input_vertex)[edge.first], (*input_vertex)[edge.second]});
    auto forward = [&](const std::pair<int, int>& corner) { return F(corner.first, corner.second) == edge.first; };
    bool joined = false;
    for (std::size_t a = 0; a < count && !joined; ++a)
      for (std::size_t b = a + 1; b < count && !joined; ++b)
        if (forward(faces[a]) != forward(faces[b]) && faces[a].first != faces[b].first) {
          join(faces[a].first, faces[b].first, edge);
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
