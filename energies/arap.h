#pragma once
// ARAP [Liu et al. 2008]: |J - R(J)|_F^2 with R the closest rotation,
// sum_i (sigma_i - 1)^2, minimum 0 at rotations. +infinity when det J <= 0,
// as every density here.
//
// ARAP itself stays finite as an element collapses, so its infimum over the
// flip-free maps may lie on a collapsed element: every method then steps
// ever closer to det J = 0 under the flip-free bound and stalls there. A
// collapse barrier b = -(r - 1)^2 log r in r = det J / g_hat, below g_hat =
// collapse_area_ratio() in 2D, collapse_volume_ratio() in 3D (IPC's
// barrier, Li et al. 2020, zero with its first two derivatives at r = 1),
// puts the minimum inside, where the gradient vanishes. It changes no map
// whose elements all keep at least g_hat of their rest measure. Being O(1)
// in r, like ARAP's own density, it
// meets ARAP's O(1) pull on a collapsing element while det J is still a
// fair fraction of g_hat, where its curvature (of order 1 / g_hat^2) keeps
// Newton's steps accurate; IPC's form in det J itself, 1 / g_hat^2 weaker,
// lets the element sink to det J ~ g_hat^2 and the gradient stays far above
// the tolerance there.
#include "energies/invariant_density_2d.h"

namespace akvf {

// In 2D sigma_1 + sigma_2 = sqrt(s + 2g) for g > 0, so f = s - 2 sqrt(s + 2g) + 2,
// plus the collapse barrier below g_hat.
class Arap2D final : public InvariantDensity2D {
 public:
  std::string name() const override { return "arap"; }
  double lower_bound() const override { return 0.0; }
  // g_hat: a triangle shrunk below a thousandth of its rest area is
  // collapsed for any texture use; ARAP's density there is already at least
  // (1 - sqrt(g_hat))^2 = 0.94 (sigma_min <= sqrt(det J)), against 1 at
  // full collapse.
  static constexpr double collapse_area_ratio() { return 1e-3; }
  bool collapse_barrier_hessian(const Matrix& J, Hessian* H) const override;
  double collapse_barrier_onset() const override { return collapse_area_ratio(); }

 protected:
  InvariantDerivatives2D derivatives(double s, double g) const override;
};

// In 3D through the SVD J = U diag(sigma) V^T, R = U V^T. Gradient 2 (J - R);
// Hessian 2 I - 2 dR/dJ, where dR/dJ has the eigenvalue 2 / (sigma_i +
// sigma_j) on each twist U (e_i e_j^T - e_j e_i^T) V^T / sqrt(2) and 0
// elsewhere; plus the collapse barrier below collapse_volume_ratio().
class Arap3D final : public DistortionDensity3D, public SingularValueDerivative<3>, public HessianEigensystem<3> {
 public:
  std::string name() const override { return "arap"; }
  double lower_bound() const override { return 0.0; }
  // g_hat: a tet shrunk below a thousandth of its rest volume is collapsed
  // (as Arap2D's area ratio).
  static constexpr double collapse_volume_ratio() { return 1e-3; }
  bool collapse_barrier_hessian(const Matrix& J, Hessian* H) const override;
  double collapse_barrier_onset() const override { return collapse_volume_ratio(); }
  double value(const Matrix& J) const override;
  double value_and_gradient(const Matrix& J, Matrix* dD_dJ) const override;
  Hessian hessian(const Matrix& J) const override;
  // Closed form (singular_eigensystem_3d.h): Psi_i = 2 (sigma_i - 1), so the
  // twists have 2 - 4 / (sigma_i + sigma_j), the flips and scalings 2; the
  // barrier's own eigenvalues added.
  Hessian projected_hessian(const Matrix& J) const override { return filtered_hessian(J, false); }
  Hessian absolute_hessian(const Matrix& J) const override { return filtered_hessian(J, true); }
  Eigenpairs hessian_eigensystem(const Matrix& J) const override;
  Eigen::Vector3d singular_value_gradient(const Eigen::Vector3d& sigma) const override;

 private:
  Hessian filtered_hessian(const Matrix& J, bool absolute) const;
};

}  // namespace akvf
