#pragma once
// Combinatorial queries on triangle meshes: edges, components, boundary loops.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace akvf {

// Undirected edges of F with the faces that use them, plus the problems that
// make a mesh non-manifold. Built once from the 3|F| half-edges, bucketed by
// their smaller vertex.
struct EdgeTopology {
  int num_edges = 0;
  // A directed boundary half-edge (a -> b) per boundary edge, as its face
  // traverses it, sorted by (min, max) vertex.
  std::vector<std::pair<int, int>> boundary_half_edges;
  // First edge used by three or more faces, if any: {a, b, face count}.
  std::vector<int> overused_edge;
  // First interior edge traversed in the same direction by both its faces:
  // {a, b, face1, face2}.
  std::vector<int> misoriented_edge;
};

EdgeTopology edge_topology(const Eigen::MatrixXi& F);

// Face f's side from corner k to corner k + 1, by its ends.
struct HalfEdge {
  int lo, hi, face, corner;  // lo = min of the ends, hi = max
};

// The 3|F| sides sorted by (lo, hi, face, corner): each undirected edge's
// sides are one run, in file order. Counted into one bucket per lo, then
// each bucket (the edges at a vertex, a few) sorted. F's indices in
// [0, num_vertices).
std::vector<HalfEdge> sorted_half_edges(const Eigen::MatrixXi& F, int num_vertices);

// A key of the undirected edge (a, b) among num_vertices vertices, the same
// for (b, a).
inline std::int64_t undirected_edge_key(int a, int b, int num_vertices) {
  return static_cast<std::int64_t>(std::min(a, b)) * num_vertices + std::max(a, b);
}

// Union-find with path halving; the smaller index is the representative.
class DisjointSets {
 public:
  explicit DisjointSets(int size);
  int find(int i);
  // Joins the sets of a and b; false if they were one set already.
  bool unite(int a, int b);

 private:
  std::vector<int> parent_;
};

// The connected component of every vertex of the elements (F or T: any
// number of columns), numbered 0, 1, ... in the order of their first
// element; -1 for vertices in no element. *count (if given) = components.
std::vector<int> vertex_components(const Eigen::MatrixXi& elements, int num_vertices, int* count = nullptr);

// Number of connected components of the elements (vertices joined by edges).
int count_components(const Eigen::MatrixXi& F, int num_vertices);

// Boundary loops as ordered vertex lists following the faces' orientation
// (the mesh lies to the left of each loop). Throws ValidationError naming the
// vertex if a vertex starts two boundary half-edges (a non-manifold vertex).
std::vector<std::vector<int>> boundary_loops(const EdgeTopology& topology, int num_vertices);

// For each vertex, the elements (triangles or tets: F has 3 or 4 columns)
// that use it, as compressed rows: the elements of v are entries
// [offsets[v], offsets[v+1]) of face_corner, each encoded as
// F.cols() * element + corner. Order is increasing element index.
struct VertexFaces {
  std::vector<int> offsets;
  std::vector<int> face_corner;
};
VertexFaces vertex_faces(const Eigen::MatrixXi& F, int num_vertices);

// For each face f and each of its edges k (from corner k to corner k + 1),
// the other face on that edge, -1 on the boundary (an edge of at most two
// faces, as after validation).
std::vector<std::array<int, 3>> faces_across_edges(const Eigen::MatrixXi& F, int num_vertices);

}  // namespace akvf
