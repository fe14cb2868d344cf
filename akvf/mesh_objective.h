#pragma once
// What the mesh preconditioners need from an objective, as an interface: an
// Objective over the stacked vertex positions x of a triangle (D = 2) or tet
// (D = 3) mesh whose value is
//   E(x) = sum_e w_e D(J_e(x)) + (terms with a diagonal Hessian),
// Eq. (1) plus, for deformation, the soft constraints of §6.2. The
// preconditioners (AKVF, projected Newton, SLIM, Laplacian) see only this;
// DistortionObjective (distortion_objective.h) is the implementation the
// library builds, and user code may supply its own (more terms, other
// weights) and reuse every preconditioner on it.
#include <Eigen/Core>
#include <type_traits>

#include "akvf/distortion_density.h"
#include "akvf/objective.h"
#include "akvf/rest_geometry.h"

namespace akvf {

template <int D>
class MeshObjective : public Objective {
 public:
  using Matrix = Eigen::Matrix<double, D, D>;
  using Rest = std::conditional_t<D == 2, RestTriangles, RestTets>;

  // #E by D + 1 vertex indices: the faces (D = 2) or tets (D = 3).
  virtual const Eigen::MatrixXi& elements() const = 0;
  virtual int num_vertices() const = 0;
  // The rest shapes (Dm^-1, areas or volumes) of the elements.
  virtual const Rest& rest() const = 0;
  // w_e: the weight of element e in E (M_e / sum M for Eq. (1)).
  virtual const Eigen::VectorXd& weights() const = 0;
  virtual const DistortionDensity<D>& density() const = 0;
  // J_e = Ds Dm^-1 (§3) for element e at x.
  virtual Matrix jacobian(const Eigen::VectorXd& x, int e) const = 0;
  // The Hessian diagonal (one value per variable, or empty) of the quadratic
  // terms added to the distortion: soft positional constraints (2 w on the
  // constrained coordinates) or the pins of hard ones. Every matrix
  // preconditioner includes it, so a new one gets the constraints without
  // being listed anywhere.
  virtual const Eigen::VectorXd& added_hessian_diagonal() const = 0;
  // Objective::rotation_following_term from the elements at x: per vertex
  // a_v = W_v d_v, with W_v the skew part of the velocity gradient of d
  // (Dd Ds^-1) averaged over the vertex's elements, weighted by their
  // current measure (rotation_following_path.cpp).
  bool rotation_following_term(const Eigen::VectorXd& x, const Eigen::VectorXd& d, Eigen::VectorXd* a) const override;
};

using MeshObjective2D = MeshObjective<2>;
using MeshObjective3D = MeshObjective<3>;

}  // namespace akvf
