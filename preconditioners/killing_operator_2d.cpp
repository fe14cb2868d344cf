#include "preconditioners/killing_operator_2d.h"

#include <Eigen/LU>

#include "framework/optimization/element_derivatives.h"

namespace akvf {

void killing_local_matrix_2d(const Eigen::Vector2d p[3], double scale, double divergence_weight,
                             ElementMatrix2D::Local* local) {
  const Eigen::Vector2d e1 = p[1] - p[0], e2 = p[2] - p[0];
  const double area = 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
  // Eq. (5)'s block B_k = K_ab of corner k (a = k, b = k + 1, r = k + 2,
  // mod 3), entry by entry: s (e'_i e_j / (4 A) - cot(theta) [i = j]), with
  // cot(theta) = e . e' / (2 A) = 2 e . e' / (4 A): s / (4 A) times
  // e'_i e_j - 2 e . e' [i = j].
  const double s_over_4a = scale / (4 * area);
  double B[3][2][2];
  for (int k = 0; k < 3; ++k) {
    const int a = k, b = (k + 1) % 3, r = (k + 2) % 3;
    const double ex = p[a].x() - p[r].x(), ey = p[a].y() - p[r].y();
    const double fx = p[b].x() - p[r].x(), fy = p[b].y() - p[r].y();  // e'
    const double two_dot = 2 * (ex * fx + ey * fy);
    B[k][0][0] = s_over_4a * (fx * ex - two_dot);
    B[k][0][1] = s_over_4a * (fx * ey);
    B[k][1][0] = s_over_4a * (fy * ex);
    B[k][1][1] = s_over_4a * (fy * ey - two_dot);
  }
  // The upper triangle (all ElementMatrix reads): K_01 = B_0, K_12 = B_1,
  // K_02 = B_2^T, and K_pp = -sum_r K_pr in the order of the corners' loop:
  // K_00 = -B_0 - B_2^T, K_11 = -B_0^T - B_1, K_22 = -B_1^T - B_2.
  ElementMatrix2D::Local& K = *local;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      K(i, 2 + j) = B[0][i][j];
      K(2 + i, 4 + j) = B[1][i][j];
      K(i, 4 + j) = B[2][j][i];
    }
  for (int i = 0; i < 2; ++i)
    for (int j = i; j < 2; ++j) {
      K(i, j) = (0 - B[0][i][j]) - B[2][j][i];
      K(2 + i, 2 + j) = (0 - B[0][j][i]) - B[1][i][j];
      K(4 + i, 4 + j) = (0 - B[1][j][i]) - B[2][i][j];
    }
  if (divergence_weight != 1) {  // (beta - 1) (div v)^2 over the face
    Eigen::Matrix2d Ds;
    Ds << e1, e2;
    const Eigen::Matrix<double, 6, 1> d = divergence_row<2>(Ds.inverse());
    const Eigen::Matrix<double, 6, 1> b = ((divergence_weight - 1) * scale * area) * d;
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i <= j; ++i) K(i, j) += d[j] * b[i];  // (b d^T)(i, j), as Eigen's outer product rounds it
  }
}

void assemble_killing_operator_2d(const Eigen::MatrixXi& F, const Eigen::VectorXd& x, const Eigen::VectorXd& rest_area,
                                  bool area_scaling, ElementMatrix2D* matrix, double divergence_weight,
                                  double energy_scale, const ElementMatrix2D::LocalFunction& add_to_face) {
  matrix->assemble([&](int f, ElementMatrix2D::Local* local) {
    Eigen::Vector2d p[3];
    for (int k = 0; k < 3; ++k) p[k] = x.segment<2>(2 * F(f, k));
    double scale = energy_scale;
    if (area_scaling) {
      const Eigen::Vector2d e1 = p[1] - p[0], e2 = p[2] - p[0];
      scale *= rest_area[f] / (0.5 * (e1.x() * e2.y() - e1.y() * e2.x()));
    }
    killing_local_matrix_2d(p, scale, divergence_weight, local);
    if (add_to_face) add_to_face(f, local);
  });
}

}  // namespace akvf
