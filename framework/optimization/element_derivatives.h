#pragma once
// Derivatives of an element's Jacobian J = Ds Dm^-1 (§3) with respect to its
// corner positions, shared by the preconditioners that assemble
// G^T (something) G per element (projected Newton, SLIM, Laplacian) and by
// the local Newton sweeps (local_newton_sweep.h).
#include <Eigen/Core>
#include <array>

namespace akvf {

// G (D^2 by D (D + 1)): dvec(J) / d(x_0, ..., x_D) for J = [x_1 - x_0, ..., x_D - x_0] Dm^-1,
// vec column-major, corner positions interleaved (corner k's coordinate r is column D k + r).
template <int D>
Eigen::Matrix<double, D * D, D*(D + 1)> jacobian_map(const Eigen::Matrix<double, D, D>& Dm_inv) {
  // J(r, c) = sum_k (x_{k+1} - x_0)[r] Dm_inv(k, c).
  Eigen::Matrix<double, D * D, D*(D + 1)> G = Eigen::Matrix<double, D * D, D*(D + 1)>::Zero();
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) {
      G(r + D * c, r) = -Dm_inv.col(c).sum();
      for (int k = 0; k < D; ++k) G(r + D * c, D * (k + 1) + r) = Dm_inv(k, c);
    }
  return G;
}

// Rest gradients of the D + 1 hat functions: rows of Dm^-1 for corners
// 1..D, and corner 0 minus their sum.
template <int D>
std::array<Eigen::Matrix<double, D, 1>, D + 1> hat_gradients(const Eigen::Matrix<double, D, D>& Dm_inv) {
  std::array<Eigen::Matrix<double, D, 1>, D + 1> grad;
  grad[0] = -Dm_inv.colwise().sum().transpose();
  for (int k = 0; k < D; ++k) grad[k + 1] = Dm_inv.row(k).transpose();
  return grad;
}

// The divergence of a velocity v (corner velocities interleaved) over an
// element whose current edge matrix Ds has inverse Ds_inv: b . v, b holding
// each corner's hat-function gradient (tr(Dv Ds^-1) = sum_k grad phi_k . v_k).
template <int D>
Eigen::Matrix<double, D*(D + 1), 1> divergence_row(const Eigen::Matrix<double, D, D>& Ds_inv) {
  const auto grad = hat_gradients<D>(Ds_inv);
  Eigen::Matrix<double, D*(D + 1), 1> b;
  for (int k = 0; k <= D; ++k) b.template segment<D>(D * k) = grad[k];
  return b;
}

}  // namespace akvf
