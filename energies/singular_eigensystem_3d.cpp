#include "energies/singular_eigensystem_3d.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>

namespace akvf {

SingularEigensystem3D::SingularEigensystem3D(const Eigen::Matrix3d& J) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  U = svd.matrixU();
  V = svd.matrixV();
  // diag(U^T J V) rather than svd.singularValues(): the same numbers to
  // rounding, without GCC 12's false may-be-uninitialized warning on Eigen's
  // fixed-size singular-value array.
  sigma = (U.transpose() * J * V).diagonal();
  twist.setZero();
  flip.setZero();
  scaling.setZero();
}

void SingularEigensystem3D::decompose(Eigen::Matrix<double, 9, 9>* Q, Eigen::Matrix<double, 9, 1>* lambda) const {
  const double r = 1 / std::sqrt(2.0);
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const Eigen::Matrix3d a = U.col(i) * V.col(j).transpose(), b = U.col(j) * V.col(i).transpose();
    Q->col(2 * k) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(Eigen::Matrix3d(r * (a - b)).data());
    Q->col(2 * k + 1) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(Eigen::Matrix3d(r * (a + b)).data());
    (*lambda)[2 * k] = twist[k];
    (*lambda)[2 * k + 1] = flip[k];
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scaling);
  for (int m = 0; m < 3; ++m) {
    const Eigen::Matrix3d mode = U * eig.eigenvectors().col(m).asDiagonal() * V.transpose();
    Q->col(6 + m) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(mode.data());
    (*lambda)[6 + m] = eig.eigenvalues()[m];
  }
}

Eigen::Matrix<double, 9, 9> SingularEigensystem3D::filtered_hessian(bool absolute) const {
  // P = Q diag(filtered lambda) Q^T.
  Eigen::Matrix<double, 9, 9> Q;
  Eigen::Matrix<double, 9, 1> lambda;
  decompose(&Q, &lambda);
  const auto filter = [absolute](double value) { return absolute ? std::abs(value) : std::max(value, 0.0); };
  return Q * lambda.unaryExpr(filter).asDiagonal() * Q.transpose();
}

HessianEigensystem<3>::Eigenpairs SingularEigensystem3D::eigenpairs() const {
  Eigen::Matrix<double, 9, 9> Q;
  HessianEigensystem<3>::Eigenpairs pairs;
  decompose(&Q, &pairs.values);
  for (int m = 0; m < 9; ++m) pairs.modes[m] = Eigen::Map<const Eigen::Matrix3d>(Q.col(m).data());
  return pairs;
}

}  // namespace akvf
