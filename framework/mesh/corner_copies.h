#pragma once
// A mesh opened along some of its edges: the corners around a vertex stay one
// vertex across every edge whose two faces are joined, and become separate
// copies across the others (a cut, or a seam).
#include <Eigen/Core>
#include <vector>

namespace akvf {

// Faces face0 and face1 share the edge (a, b) and stay joined across it.
struct FaceJoin {
  int face0, face1, a, b;
};

struct CornerCopies {
  std::vector<int> copy_of_corner;  // 3 F: the new vertex of face f's corner k at 3 f + k
  std::vector<int> source_vertex;   // the vertex of F each new vertex copies, ascending
};

// The copies of F's vertices (nv of them) when only `joins` hold corners
// together: numbered by source vertex, then by the first face around it.
CornerCopies split_corners(const Eigen::MatrixXi& F, int nv, const std::vector<FaceJoin>& joins);

}  // namespace akvf
