#include "preconditioners/killing_operator_2d.h"

#include <Eigen/LU>

#include "preconditioners/element_derivatives.h"

namespace akvf {

void killing_local_matrix_2d(const Eigen::Vector2d p[3], double scale, double divergence_weight,
                             ElementMatrix2D::Local* local) {
  const Eigen::Vector2d e1 = p[1] - p[0], e2 = p[2] - p[0];
  const double area = 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
  local->setZero();
  for (int k = 0; k < 3; ++k) {
    const int a = k, b = (k + 1) % 3, r = (k + 2) % 3;
    const Eigen::Vector2d e = p[a] - p[r], e_prime = p[b] - p[r];
    const double cot_theta = e.dot(e_prime) / (2 * area);
    // Eq. (5): the block K_pq for p = corner a, q = corner b.
    const Eigen::Matrix2d block =
        scale * (e_prime * e.transpose() / (4 * area) - cot_theta * Eigen::Matrix2d::Identity());
    local->block<2, 2>(2 * a, 2 * b) = block;
    local->block<2, 2>(2 * b, 2 * a) = block.transpose();
    local->block<2, 2>(2 * a, 2 * a) -= block;              // K_pp = -sum_r K_pr
    local->block<2, 2>(2 * b, 2 * b) -= block.transpose();  // K_qq gets K_qp = K_pq^T
  }
  if (divergence_weight != 1) {  // (beta - 1) (div v)^2 over the face
    Eigen::Matrix2d Ds;
    Ds << e1, e2;
    const Eigen::Matrix<double, 6, 1> b = divergence_row<2>(Ds.inverse());
    *local += ((divergence_weight - 1) * scale * area) * b * b.transpose();
  }
}

void assemble_killing_operator_2d(const Eigen::MatrixXi& F, const Eigen::VectorXd& x, const Eigen::VectorXd& rest_area,
                                  bool area_scaling, ElementMatrix2D* matrix, double divergence_weight) {
  matrix->assemble([&](int f, ElementMatrix2D::Local* local) {
    Eigen::Vector2d p[3];
    for (int k = 0; k < 3; ++k) p[k] = x.segment<2>(2 * F(f, k));
    double scale = 1;
    if (area_scaling) {
      const Eigen::Vector2d e1 = p[1] - p[0], e2 = p[2] - p[0];
      scale = rest_area[f] / (0.5 * (e1.x() * e2.y() - e1.y() * e2.x()));
    }
    killing_local_matrix_2d(p, scale, divergence_weight, local);
  });
}

}  // namespace akvf
