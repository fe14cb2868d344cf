#pragma once
// The vertex graph of a mesh (vertices joined when they share an element),
// the sparsity pattern of every matrix assembled per element on it (the
// Killing operator, the Newton Hessian, the SLIM proxy, the Laplacian) in
// blocks of D x D, and the graph a fill-reducing ordering of those matrices
// is computed on (solvers/fill_reducing_ordering.h).
#include <Eigen/Core>
#include <vector>

namespace akvf {

// The graph's upper triangle in compressed columns: column v lists the
// vertices u <= v that share an element with v, v itself last, in
// increasing order (a vertex in no element has an empty column).
struct UpperVertexGraph {
  std::vector<int> column_start;  // num_vertices + 1
  std::vector<int> row;
  int num_vertices() const { return static_cast<int>(column_start.size()) - 1; }
};

// From the elements (#E by N vertex indices, any N), by counting: no
// triplet per pair (those took 3.4 GB at 10 M triangles).
UpperVertexGraph upper_vertex_graph(const Eigen::MatrixXi& elements, int num_vertices);

}  // namespace akvf
