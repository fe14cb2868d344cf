#include "preconditioners/killing_operator_3d.h"

#include <Eigen/Geometry>
#include <Eigen/QR>

#include "framework/optimization/element_derivatives.h"

namespace akvf {

void killing_local_matrix_3d(const Eigen::Vector3d p[4], double divergence_weight, ElementMatrix3D::Local* local) {
  const double volume = (p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])) / 6;
  local->setZero();
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      // The other two corners, in either order (Eq. 9 does not depend on it).
      int others[2], k = 0;
      for (int m = 0; m < 4; ++m)
        if (m != i && m != j) others[k++] = m;
      const Eigen::Vector3d a = p[j] - p[others[1]], b = p[others[1]] - p[others[0]], c = p[others[0]] - p[i];
      const Eigen::Vector3d n1 = b.cross(a), n2 = b.cross(c);
      const Eigen::Matrix3d block = (n2 * n1.transpose() + n1.dot(n2) * Eigen::Matrix3d::Identity()) / (36 * volume);
      local->block<3, 3>(3 * i, 3 * j) = block;
      local->block<3, 3>(3 * j, 3 * i) = block.transpose();
      local->block<3, 3>(3 * i, 3 * i) -= block;              // Eq. (10): K_pp = -sum_q K_pq
      local->block<3, 3>(3 * j, 3 * j) -= block.transpose();  // K_qq gets K_qp = K_pq^T
    }
  if (divergence_weight != 1) {  // (beta - 1) (2/3) (div v)^2 over the tet
    Eigen::Matrix3d Ds;
    for (int k = 0; k < 3; ++k) Ds.col(k) = p[k + 1] - p[0];
    const Eigen::Matrix<double, 12, 1> b = divergence_row<3>(Ds.inverse());
    *local += ((divergence_weight - 1) * 2.0 / 3.0 * volume) * b * b.transpose();
  }
}

void assemble_killing_operator_3d(const Eigen::MatrixXi& T, const Eigen::VectorXd& x, ElementMatrix3D* matrix,
                                  double divergence_weight) {
  matrix->assemble([&](int t, ElementMatrix3D::Local* local) {
    Eigen::Vector3d p[4];
    for (int k = 0; k < 4; ++k) p[k] = x.segment<3>(3 * T(t, k));
    killing_local_matrix_3d(p, divergence_weight, local);
  });
}

}  // namespace akvf
