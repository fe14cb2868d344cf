#pragma once
// Unfolding a planar map by moving single vertices: a vertex placed in the
// kernel of its star (the points from which every edge of its link is seen
// counterclockwise) makes all of its triangles positive and changes no other.
#include <Eigen/Core>
#include <vector>

namespace akvf {

// Moves vertices of the triangles that UV (#V by 2) inverts, one at a time,
// each to the centroid of its star's kernel (clipped, for a boundary vertex,
// to the bounding box of its star), where that kernel has an interior: a
// triangle's vertex in the most inverted triangles first. Stops when no
// triangle is inverted or a pass over them moves nothing. Deterministic: the
// vertices are taken in an order set by F and UV alone.
//   returns  the vertices moved, in increasing order; count_inverted_triangles
//            tells whether the map was unfolded
std::vector<int> unfold_by_star_kernels(const Eigen::MatrixXi& F, Eigen::MatrixXd* UV);

}  // namespace akvf
