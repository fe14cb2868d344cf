#pragma once
// The planar Killing operator K(x) of Eq. (5) (Proposition 1): 2x2 blocks per
// vertex pair,
//   K_pq = sum_{f ~ (p,q)} s_f [ e' e^T / (4 A_f) - cot(theta) I ]   (p ~ q)
//   K_pp = -sum_{r ~ p} K_pr
// where, in face f, r is the vertex opposite edge (p,q), e = x_p - x_r,
// e' = x_q - x_r, theta is the angle between them at r, A_f the UV area and
// cot(theta) = e . e' / (2 A_f). With area scaling (§4.2.1) s_f = A_hat_f / A_f
// integrates the Killing energy over the 3D surface; otherwise s_f = 1.
#include <Eigen/Core>

#include "framework/optimization/element_matrix.h"

namespace akvf {

// K's quadratic form integrates (1/2)|G + G^T|^2 = 2|sym_0 G|^2 + (tr G)^2
// for the velocity gradient G (sym_0: the trace-free symmetric part). The
// divergence weight beta gives K_beta, whose form has beta (tr G)^2 instead:
// K_beta = K - (1 - beta) sum_f s_f A_f b_f b_f^T, b_f . v the divergence of
// v on face f. beta = 1 is Eq. (5); beta = 0 (K_0) measures only the
// departure from a conformal motion, and its null space is the similarities
// (energy_scale.h, rest_divergence_weight, says which energy wants which).

// The upper triangle (what ElementMatrix reads) of the 6x6 local matrix of
// Eq. (5) for one face with UV corners p[0..2] (counter-clockwise), face
// scale s_f and divergence weight beta.
void killing_local_matrix_2d(const Eigen::Vector2d p[3], double scale, double divergence_weight,
                             ElementMatrix2D::Local* local);

// Fills matrix with c K_beta(x) (beta = divergence_weight; 1: K(x) of Eq. 5;
// c = energy_scale) for the faces F (#F by 3) at the interleaved UV
// positions x; rest_area (#F, A_hat_f) is used when area_scaling.
// add_to_face, if given, then adds to each face's local matrix (its upper
// triangle).
void assemble_killing_operator_2d(const Eigen::MatrixXi& F, const Eigen::VectorXd& x, const Eigen::VectorXd& rest_area,
                                  bool area_scaling, ElementMatrix2D* matrix, double divergence_weight = 1,
                                  double energy_scale = 1, const ElementMatrix2D::LocalFunction& add_to_face = nullptr);

}  // namespace akvf
