#pragma once
// Symmetric sparse matrices on the interleaved dofs (u_0, v_0, u_1, v_1, ...)
// of a triangle mesh, assembled from one symmetric 6x6 local matrix per
// triangle (dof order: corner 0 u, v, corner 1 u, v, corner 2 u, v). The
// Killing operator, the projected Newton Hessian and the Laplacian all have
// this form.
//
// The sparsity pattern (2x2 blocks for each vertex and edge, upper triangle)
// is built once from the faces. assemble() computes the local matrices in
// parallel and gathers each nonzero from its contributions in a fixed order,
// so the result is bitwise identical for any thread count.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <vector>

namespace akvf {

class ElementMatrix2D {
 public:
  using Local = Eigen::Matrix<double, 6, 6>;
  // Fills the 6x6 local matrix of face f (only its upper triangle is read).
  using LocalFunction = std::function<void(int f, Local* local)>;

  //   F  #F by 3 faces
  ElementMatrix2D(const Eigen::MatrixXi& F, int num_vertices);

  void assemble(const LocalFunction& local);
  // upper() += shift I (Tikhonov regularization).
  void add_to_diagonal(double shift);

  // Upper triangle, column-major compressed, 2|V| by 2|V|.
  const Eigen::SparseMatrix<double>& upper() const { return upper_; }
  // Mean of the diagonal of the last assembled matrix (before any shift).
  double mean_diagonal() const { return mean_diagonal_; }
  // The full symmetric matrix (for tests and small problems).
  Eigen::SparseMatrix<double> full() const;

 private:
  static constexpr int kSlotsPerFace = 21;  // 3 edge blocks x 4 + 3 diagonal blocks x 3 (upper)

  Eigen::MatrixXi F_;
  Eigen::SparseMatrix<double> upper_;
  std::vector<double> face_buffer_;    // #F x 21 local values
  std::vector<int> gather_offsets_;    // per nonzero: its contributions in gather_sources_
  std::vector<int> gather_sources_;    // indices into face_buffer_
  std::vector<int> diagonal_entries_;  // nonzero index of each (i, i)
  double mean_diagonal_ = 0;
};

}  // namespace akvf
