#pragma once
// The least-squares conformal map (Levy, Petitjean, Ray and Maillot 2002) of
// a disk: a start that is an isometry wherever the surface is developable
// (akvf/parameterization.cpp takes it where it is flip-free and lower in
// energy than the Tutte map).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <vector>

#include "akvf/mesh.h"
#include "akvf/rest_geometry.h"

namespace akvf {

// Solves A x = b for a symmetric positive definite A given by its upper
// triangle in the 2 x 2-block pattern of ElementMatrix2D on the mesh's
// triangles (block_upper_pattern<2>, so that a solver may take that
// pattern's symbolic analysis); false when A is not positive definite.
using BlockSpdSolver =
    std::function<bool(const Eigen::SparseMatrix<double>& upper, const Eigen::VectorXd& b, Eigen::VectorXd* x)>;

// The map (u, v) minimizing the conformal energy
//   sum_f A_f / 2 |grad v - R grad u|^2 = Dirichlet energy - signed area
// (R the quarter turn; zero exactly on the orientation-preserving conformal
// maps), with two boundary vertices pinned at their rest distance apart:
// the vertex of boundary_loop farthest at rest from the loop's centroid,
// and the vertex farthest from that. The map depends on that choice (the
// energy scales with the map's square), which depends on the geometry
// alone, not on the numbering. Unlike Tutte's, the map may fold.
//   rest    of mesh's triangles (its areas and Dm^-1)
//   solver  empty: Eigen's simplicial L D L^T
//   returns UV (#V by 2), or an empty matrix when the solver failed
Eigen::MatrixXd conformal_map(const TriMesh& mesh, const RestTriangles& rest, const std::vector<int>& boundary_loop,
                              const BlockSpdSolver& solver = {});

}  // namespace akvf
