#pragma once
// Assembly of the planar Killing operator K(x) of Eq. (5) (Proposition 1):
// 2x2 blocks per vertex pair,
//   K_pq = sum_{f ~ (p,q)} s_f [ e' e^T / (4 A_f) - cot(theta) I ]   (p ~ q)
//   K_pp = -sum_{r ~ p} K_pr
// where, in face f, r is the vertex opposite edge (p,q), e = x_p - x_r,
// e' = x_q - x_r, theta is the angle between them at r, A_f the UV area and
// cot(theta) = e . e' / (2 A_f). With area scaling (§4.2.1) s_f = A_hat_f / A_f
// integrates the Killing energy over the 3D surface; otherwise s_f = 1.
//
// The sparsity pattern depends only on the faces, so it is built once; each
// assemble() fills the values in parallel with a deterministic gather.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace akvf {

class KillingOperator2D {
 public:
  //   F  #F by 3 faces;  dofs interleaved (u_0, v_0, u_1, v_1, ...)
  KillingOperator2D(const Eigen::MatrixXi& F, int num_vertices);

  // Fills the upper triangle of K(x) into upper().
  //   rest_area  #F A_hat_f (used when area_scaling)
  void assemble(const Eigen::VectorXd& x, const Eigen::VectorXd& rest_area, bool area_scaling);
  // upper() += shift I (Tikhonov regularization).
  void add_to_diagonal(double shift);

  // Upper triangle, column-major compressed, 2|V| by 2|V|.
  const Eigen::SparseMatrix<double>& upper() const { return upper_; }
  // Mean of the diagonal of the last assembled K (before any shift).
  double mean_diagonal() const { return mean_diagonal_; }

  // The full symmetric matrix (for tests and small problems).
  Eigen::SparseMatrix<double> full() const;

 private:
  static constexpr int kSlotsPerFace = 21;  // 3 edge blocks x 4 + 3 diagonal blocks x 3 (upper)
  void face_values(const Eigen::VectorXd& x, int f, double scale, double* out) const;

  Eigen::MatrixXi F_;
  Eigen::SparseMatrix<double> upper_;
  std::vector<double> face_buffer_;       // #F x 21 local values
  std::vector<int> gather_offsets_;       // per nonzero: its contributions in gather_sources_
  std::vector<int> gather_sources_;       // indices into face_buffer_
  std::vector<int> diagonal_entries_;     // nonzero index of each (i, i)
  double mean_diagonal_ = 0;
};

}  // namespace akvf
