#pragma once
// The volumetric Killing operator K(x) of Eq. (9)-(10) (Proposition 3):
// 3x3 blocks per vertex pair. For a tet with vertices (x_p, x_q, x_r, x_s),
//   a = x_q - x_s,  b = x_s - x_r,  c = x_r - x_p,  n1 = b x a,  n2 = b x c,
//   K_edge(p, q) = [ n2 n1^T + (n1 . n2) I ] / (36 Vol)              (Eq. 9)
// summed over the tets of edge (p, q), and K_pp = -sum_q K_pq (Eq. 10).
// n1 and n2 are the (doubled-area) normals of the faces opposite p and q;
// the formula does not depend on the order of r and s, so each of a tet's
// six edges uses it with the tet's other two vertices. Vol is the current
// (deformed) volume.
#include <Eigen/Core>

#include "framework/optimization/element_matrix.h"

namespace akvf {

// K's quadratic form integrates (1/2)|G + G^T|^2 = 2|sym_0 G|^2 +
// (2/3)(tr G)^2 over the current tets; the divergence weight beta gives
// K_beta with beta (2/3)(tr G)^2 instead, as in 2D (killing_operator_2d.h).

// The 12x12 local matrix of one tet with current corners p[0..3]
// (positively oriented) and divergence weight beta (1: Eq. 9-10).
void killing_local_matrix_3d(const Eigen::Vector3d p[4], double divergence_weight, ElementMatrix3D::Local* local);

// Fills matrix with K_beta(x) for the tets T (#T by 4) at the interleaved
// positions x (x_0, y_0, z_0, x_1, ...).
void assemble_killing_operator_3d(const Eigen::MatrixXi& T, const Eigen::VectorXd& x, ElementMatrix3D* matrix,
                                  double divergence_weight = 1);

}  // namespace akvf
