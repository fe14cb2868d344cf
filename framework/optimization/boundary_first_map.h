#pragma once
// The boundary-first map of a disk (Sawhney and Crane 2017, "Boundary First
// Flattening") with the scale factor u = 0 on the boundary: every boundary
// edge keeps its rest length, and the interior's area changes only as much
// as its Gaussian curvature needs. The least-squares conformal map
// (conformal_map.h) pins two vertices instead and lets the scale drift, by
// e^u with u growing with the curvature enclosed, so a long curved strip or
// a limb is shrunk exponentially; here the scale is 1 all along the boundary.
#include <Eigen/Core>
#include <vector>

#include "akvf/mesh.h"
#include "framework/mesh/initialization.h"

namespace akvf {

// The map, by the cotangent Laplacian L (initialization.h: positive
// semi-definite, the integrated -Delta):
//  1. the scale factor u solves the Yamabe equation with target curvature 0,
//     L_II u_I = -K_I (K the angle defects of the interior vertices I),
//     u_B = 0;
//  2. the boundary's turning angles become kappa~ = kappa + (L u)_B
//     (kappa = pi - the angle sum; they add up to 2 pi by Gauss-Bonnet);
//  3. the boundary curve of rest edge lengths and those turns, closed by
//     the least change of lengths in sum (l~ - l)^2 / l (BFF's Sec. 4.1.3);
//  4. the interior, the harmonic extension of the curve: L_II X_I = -L_IB X_B.
// Both systems by one InteriorLaplacian with `solver` (the Tutte
// solve's). The loop may run either way round; the map's orientation
// follows the faces'. Returns UV (#V by 2), or an empty matrix when a
// system is singular or its solution not finite, or the closed curve
// would need an edge of length <= 0. The cotangent weights may be
// negative, so the map may fold (the caller checks).
Eigen::MatrixXd boundary_first_map(const TriMesh& mesh, const std::vector<int>& boundary_loop,
                                   const SpdSolver& solver = {});

}  // namespace akvf
