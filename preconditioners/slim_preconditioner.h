#pragma once
// The SLIM proxy of Rabinovich, Poranne, Panozzo and Sorkine-Hornung 2017 as
// a preconditioner, on triangles and on tets. At the current iterate, each
// element gets the reweighted ARAP proxy  w_e |W_e (J_e - R_e)|_F^2  with
// J_e = U S V^T, R_e = U V^T and W_e = U diag(w_1..w_D) U^T,
// w_i^2 = (dD/dsigma_i) / (2 (sigma_i - 1)), chosen so that the proxy's
// gradient equals the energy's gradient at x. For a scale-invariant density
// (MIPS) R_e is the nearest similarity instead, (prod sigma)^(1/D) U V^T,
// and w_i^2 = (dD/dsigma_i) / (2 (sigma_i - (prod sigma)^(1/D))), as
// libigl's SLIM does for its conformal energy; in 2D these weights are
// positive, so the gradient property holds exactly. The proxy is quadratic with
// Hessian
//   P = sum_e w_e G_e^T (I_D (x) 2 W_e^T W_e) G_e,
// so the proxy minimizer x* satisfies P (x* - x) = -grad E(x): SLIM's
// search direction x* - x is -P^-1 grad E, a preconditioned gradient.
//
// A scale-invariant density is constant on J's similarity orbit s Q J (Q a
// rotation), whose tangents at J are (s I + Omega) J, Omega skew: its
// gradient has no component along them (in 2D, where I + t Omega is a
// scaled rotation, it is constant along those lines), while the proxy,
// pulling J towards one fixed
// similarity, is as stiff along them as across: each step could then move
// an element's scale and turn only as far as that stiffness lets the
// anisotropic part pull, and SLIM would crawl
// (docs/notes/2026-12-01-slim-mips-invariant-directions.md). For such
// densities each element's proxy Hessian is restricted to the complement
// of those directions, keeping kInvariantShare of its curvature along them
// (soften_invariant_directions): only anisotropy is resisted, as by the
// energy itself (MIPS on horse_b: 16 iterations). The share keeps P
// positive definite: the
// similarities of the whole map are such directions for every element, so
// P's curvature there is the share times its usual one, which 1e-6 keeps
// as far (a factor 1e6) above the factorization's relative shift (1e-12,
// factored_preconditioner.h) as below the proxy's curvature elsewhere.
// Needs an energy that exposes its singular-value derivative
// (SingularValueDerivative<D>). Where w_i^2 <= 0 (possible for AMIPS, for
// MIPS in 3D, for ARAP near its collapse barrier, where det J < 1e-3 pulls
// sigma_1 > 1 further up, and for user energies) no weight gives the
// gradient; there 2 w_i^2 is the energy's second derivative along sigma_i
// instead (at least 2e-8), and the gradient property holds only
// approximately. In 3D
// deformation SLIM's soft constraints enter through
// FactorOptions::extra_diagonal, as in SLIM's own solve.
#include "akvf/mesh_objective.h"
#include "preconditioners/factored_preconditioner.h"

namespace akvf {

template <int D>
class SlimPreconditioner final : public FactoredPreconditioner<D> {
 public:
  using Square = Eigen::Matrix<double, D, D>;
  using SquareHessian = Eigen::Matrix<double, D * D, D * D>;  // in vec(J), column-major

  // Throws OptionsError if the objective's density has no singular-value derivative.
  explicit SlimPreconditioner(const MeshObjective<D>& objective, FactorOptions options = {},
                              MotionProjection projection = D == 2 ? MotionProjection::kTranslations
                                                                   : MotionProjection::kNone);
  std::string name() const override { return "slim"; }

  // W_e^T W_e (the squared per-element weight matrix) and R_e at J.
  static void proxy_weights(const SingularValueDerivative<D>& density, const Square& J, Square* WtW, Square* R);
  // The share of the proxy's curvature kept along a scale-invariant
  // density's invariant directions (module comment).
  static constexpr double kInvariantShare = 1e-6;
  // H restricted to the complement of the directions (s I + Omega) J, plus
  // kInvariantShare of its block along them.
  static void soften_invariant_directions(const Square& J, SquareHessian* H);

 private:
  using Matrix = typename FactoredPreconditioner<D>::Matrix;
  void assemble(const OptimizationState& state, Matrix* matrix) override;
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override { return motion_basis(D, projection_, x); }

  const MeshObjective<D>& objective_;
  const SingularValueDerivative<D>& density_;
  MotionProjection projection_;
};

using SlimPreconditioner2D = SlimPreconditioner<2>;
using SlimPreconditioner3D = SlimPreconditioner<3>;

}  // namespace akvf
