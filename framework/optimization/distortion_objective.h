#pragma once
// The distortion energy of Eq. (1) over the elements of a mesh, normalized by
// the total rest measure:
//   E(x) = sum_e M_e D(J_e(x)) / sum_e M_e,
// with M_e the rest area (triangles mapped to the plane, D = 2) or volume
// (tets deformed in space, D = 3) and J_e = Ds Dm^-1 (§3). Assembled in
// parallel over elements with a deterministic gather (the same input and any
// thread count give bitwise-identical results).
//
// Variables: x in R^{D|V|}, interleaved (x_0, y_0[, z_0], x_1, ...).
#include <Eigen/Core>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "akvf/distortion_density.h"
#include "akvf/mesh_objective.h"
#include "akvf/rest_geometry.h"
#include "framework/mesh/mesh_topology.h"

namespace akvf {

template <int D>
class DistortionObjective final : public MeshObjective<D> {
 public:
  using Matrix = typename MeshObjective<D>::Matrix;
  using Rest = typename MeshObjective<D>::Rest;
  static constexpr int kCorners = D + 1;

  //   elements  #E by D + 1 vertex indices (faces or tets)
  DistortionObjective(Eigen::MatrixXi elements, Rest rest, std::shared_ptr<const DistortionDensity<D>> density,
                      int num_vertices);

  int num_variables() const override { return D * num_vertices_; }
  double value(const Eigen::VectorXd& x) const override;
  double value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const override;
  double max_feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const override;
  int count_inverted(const Eigen::VectorXd& x) const override;
  // The first bad element in element order, e.g. "triangle 12 (vertices 4,
  // 5, 9): inverted or collapsed (det = -3e-05)"; checks coordinates,
  // orientation, then D and dD/dJ.
  std::string first_bad_element(const Eigen::VectorXd& x) const override;
  double lower_bound() const override { return density_->lower_bound(); }

  // MeshObjective::added_hessian_diagonal: the constraints' Hessian diagonal.
  void set_added_hessian_diagonal(Eigen::VectorXd diagonal) { added_hessian_diagonal_ = std::move(diagonal); }
  const Eigen::VectorXd& added_hessian_diagonal() const override { return added_hessian_diagonal_; }

  // How messages number vertices and elements: vertex v is called
  // vertex_number[v] + index_base (the source's numbering after unused
  // vertices were dropped; empty = v itself), element e is e + index_base.
  void set_file_numbering(std::vector<int> vertex_number, int index_base) {
    vertex_number_ = std::move(vertex_number);
    index_base_ = index_base;
  }

  Matrix jacobian(const Eigen::VectorXd& x, int e) const override;
  // D(J_e) per element; +infinity for inverted elements.
  Eigen::VectorXd face_distortion(const Eigen::VectorXd& x) const;

  // MeshObjective: the faces (D = 2) or tets (D = 3), their rest shapes,
  // M_e / sum M as the weights, the density.
  const Eigen::MatrixXi& elements() const override { return elements_; }
  const Rest& rest() const override { return rest_; }
  const Eigen::VectorXd& weights() const override { return weights_; }
  const DistortionDensity<D>& density() const override { return *density_; }
  int num_vertices() const override { return num_vertices_; }

 private:
  Matrix edge_matrix(const Eigen::VectorXd& x, int e) const;
  double sum_element_values() const;

  Eigen::MatrixXi elements_;
  Rest rest_;
  std::shared_ptr<const DistortionDensity<D>> density_;
  int num_vertices_;
  Eigen::VectorXd weights_;
  VertexFaces incidence_;
  std::vector<int> vertex_number_;
  int index_base_ = 0;
  Eigen::VectorXd added_hessian_diagonal_;
  // Scratch reused across calls (so calls on one object must not overlap).
  mutable std::vector<double> element_value_;
  mutable std::vector<Matrix> element_gradient_;  // dE/dDs per element
};

using DistortionObjective2D = DistortionObjective<2>;  // triangle mesh -> plane
using DistortionObjective3D = DistortionObjective<3>;  // tet mesh -> space

// Stack a #V by D matrix into interleaved x, and back.
Eigen::VectorXd stack_rows(const Eigen::MatrixXd& P);
Eigen::MatrixXd unstack_rows(const Eigen::VectorXd& x, int dimension);
inline Eigen::VectorXd stack_uv(const Eigen::MatrixXd& UV) { return stack_rows(UV); }
inline Eigen::MatrixXd unstack_uv(const Eigen::VectorXd& x) { return unstack_rows(x, 2); }

}  // namespace akvf
