#pragma once
// The parameterization energy of Eq. (1), normalized by the total rest area:
//   E(x) = sum_f A_hat_f D(J_f(x)) / sum_f A_hat_f,
// assembled in parallel over triangles with a deterministic gather (the same
// input and any thread count give bitwise-identical results).
//
// Variables: x in R^{2|V|}, interleaved (u_0, v_0, u_1, v_1, ...).
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "framework/distortion_density.h"
#include "framework/mesh_topology.h"
#include "framework/objective.h"
#include "framework/rest_geometry.h"

namespace akvf {

class ParamObjective final : public Objective {
 public:
  //   F  #F by 3 faces of the mesh being parameterized
  ParamObjective(Eigen::MatrixXi F, RestTriangles rest, std::shared_ptr<const DistortionDensity2> density,
                 int num_vertices);

  int num_variables() const override { return 2 * num_vertices_; }
  double value(const Eigen::VectorXd& x) const override;
  double value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const override;
  double max_feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const override;
  int count_inverted(const Eigen::VectorXd& x) const override;
  double lower_bound() const override { return density_->lower_bound(); }

  // J_f = Ds Dm^-1 (§3) for face f at x.
  Eigen::Matrix2d jacobian(const Eigen::VectorXd& x, int f) const;
  // D(J_f) per face (#F); +infinity for inverted faces.
  Eigen::VectorXd face_distortion(const Eigen::VectorXd& x) const;

  const Eigen::MatrixXi& faces() const { return F_; }
  const RestTriangles& rest() const { return rest_; }
  // A_hat_f / sum A_hat: the weight of face f in E.
  const Eigen::VectorXd& weights() const { return weights_; }
  const DistortionDensity2& density() const { return *density_; }
  int num_vertices() const { return num_vertices_; }

 private:
  Eigen::Matrix2d edge_matrix(const Eigen::VectorXd& x, int f) const;
  double sum_face_values() const;

  Eigen::MatrixXi F_;
  RestTriangles rest_;
  std::shared_ptr<const DistortionDensity2> density_;
  int num_vertices_;
  Eigen::VectorXd weights_;
  VertexFaces incidence_;
  // Scratch reused across calls (so calls on one object must not overlap).
  mutable std::vector<double> face_value_;
  mutable std::vector<Eigen::Matrix2d> face_gradient_;  // dE/dDs per face
};

// Stack a #V by 2 matrix into interleaved x, and back.
Eigen::VectorXd stack_uv(const Eigen::MatrixXd& UV);
Eigen::MatrixXd unstack_uv(const Eigen::VectorXd& x);

}  // namespace akvf
