#pragma once
// The eigensystem of a rotation-invariant 3D density's Hessian d2D/dvec(J)^2
// in closed form [Smith, de Goes and Kim 2019, "Analytic Eigensystems for
// Isotropic Distortion Energies"]. With J = U diag(sigma) V^T (det J > 0, so
// sigma >= 0 and det U = det V) and D = Psi(sigma), the nine eigenvectors are
//   twists  (u_i v_j^T - u_j v_i^T) / sqrt(2), eigenvalue (Psi_i + Psi_j) / (sigma_i + sigma_j),
//   flips   (u_i v_j^T + u_j v_i^T) / sqrt(2), eigenvalue (Psi_i - Psi_j) / (sigma_i - sigma_j),
// one of each per pair i < j, and three scalings U diag(e) V^T with (e,
// lambda) the eigenpairs of the 3x3 matrix d2 Psi / dsigma^2. The density
// supplies the eigenvalues (in closed form, so equal singular values need no
// limit); this file turns them into the filtered Hessian projected Newton
// uses, with no 9x9 eigensolver.
#include <Eigen/Core>

#include "akvf/distortion_density.h"

namespace akvf {

struct SingularEigensystem3D {
  Eigen::Matrix3d U, V;
  Eigen::Vector3d sigma;
  // Indexed by the pair's complement k: entry k belongs to the pair
  // (k + 1, k + 2) mod 3.
  Eigen::Vector3d twist, flip;
  Eigen::Matrix3d scaling;  // d2 Psi / dsigma^2

  // U, V and sigma of J by a Jacobi SVD; the eigenvalues are left for the
  // density to fill in.
  explicit SingularEigensystem3D(const Eigen::Matrix3d& J);

  // sum over the nine eigenpairs of max(lambda, 0) v v^T (clamped), or of
  // |lambda| v v^T (absolute).
  Eigen::Matrix<double, 9, 9> filtered_hessian(bool absolute) const;
  // The nine eigenpairs, unfiltered.
  HessianEigensystem<3>::Eigenpairs eigenpairs() const;

 private:
  // The eigenvectors as the columns of Q (vec, column-major) and their
  // eigenvalues.
  void decompose(Eigen::Matrix<double, 9, 9>* Q, Eigen::Matrix<double, 9, 1>* lambda) const;
};

}  // namespace akvf
