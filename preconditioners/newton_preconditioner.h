#pragma once
// Projected Newton: P(x) = sum_e w_e G_e^T [d^2 D / dvec(J)^2]_+ G_e, the
// energy's Hessian with every element block projected to PSD (the density's
// projected_hessian), where G_e maps the element's corner positions to
// vec(J_e) (framework/optimization/element_derivatives.h). The baseline of TinyAD-style
// second-order solvers; shift, projection and factorization reuse as in
// factored_preconditioner.h. In 3D deformation the constraint term's Hessian
// comes in through FactorOptions::extra_diagonal.
//
// The element Hessians' negative eigenvalues are filtered by `filter`:
// clamped to 0 (the default, TinyAD's projected Newton), mirrored to their
// absolute values, or adaptively as in Chen et al. 2024 ("Trust-Region
// Eigenvalue Filtering for Projected Newton"): clamped when the last step's
// actual decrease matched the exact quadratic model's prediction,
//   rho = (E(x_prev) - E(x)) / -(g_prev^T s + s^T H(x_prev) s / 2),
//   s = x - x_prev, H the unfiltered Hessian,
// to within |rho - 1| < adaptive_tolerance (theirs: 0.01), mirrored
// otherwise (and at the first iteration, where there is no step yet).
//
// Or not filtered at all (kExact): the exact Hessian, wherever its sum is
// positive definite, which is all Newton's method needs. The per-element
// projection makes P stiffer than the Hessian along every direction that
// compresses some elements (their twist eigenvalues are negative and
// clamped to 0), so near a minimum that is not an isometry projected Newton
// converges only linearly: on camelhead its gradient norm falls by 0.87 per
// iteration from 1e-3 on. In 2D the Hessian's
// curvature along the rotation of each chart, grad E . (x - c) / |x - c|^2
// over the chart, is negative wherever the chart would rather expand, so P
// adds twice its magnitude to the chart's diagonal (the direction never
// moves along the rotations, which are projected out; the shift vanishes
// with the gradient). When the
// factorization finds the exact Hessian not positive definite, or its
// direction is not a descent direction, the fallback at that x is the
// exact Hessian plus a share mu of its negative part's magnitude,
//   P = H + mu N = (1 - mu) H + mu H_clamped,  N = H_clamped - H >= 0,
// each element's negative eigenvalues scaled by 1 - mu (mu = 1 is the
// clamp); the exact one is tried again after 1, 2, 4, ... iterations
// (consecutive failures double the wait, a success resets it), as
// factorization reuse backs off, and the iterations between use the
// fallback. mu starts at 1/16 (at 1 before a run's first step, below), is
// quadrupled while P does not factor (each try costs a factorization; at most
// three: 1/16, 1/4, 1), and after a fallback that factored at its first try it
// follows the step, as a trust region's radius does: quartered (down to 1/16)
// after Newton's model held near the minimum (below), quadrupled
// (up to the clamp) after a step the flip-free bound set (the model's minimizer
// lay beyond an inversion: more damping shortens the direction toward the
// collapsing elements, and a share the next factorization would reject is not
// tried again and again), kept after one the line search shortened. A
// Levenberg-Marquardt damping whose regularizer is the part of the Hessian the
// clamp removes, not the identity. Why not the clamp at once: where the exact
// Hessian is only slightly indefinite (a plateau or saddle of a heavily
// compressed map), the clamp throws away every element's negative curvature and
// P is much stiffer than H along the directions that matter; on cow_closed cut
// to a disk the default's Newton phase crept with unit steps for 384 iterations
// that way, and takes 33 with the partial fallback. The exact Hessian is tried
// only where Newton's model held near a minimum, where the Hessian is positive
// definite: after a unit step accepted at once that left more than half of
// E - E_lb (E_lb the energy's infimum). A unit step that took E more than
// halfway down to E_lb was made far from the minimum: there the exponential
// energies' Newton steps lower log E by about 1 each (E - E_lb falls by a
// factor of about e), and their Hessian is rarely positive definite (on
// camelhead's exp-SD, tries after every unit step cost 23 factorizations that
// fail in 114 iterations: docs/notes/2026-11-29-exact-tries-far-from-minimum.md).
// Above a minimum E* > E_lb the gap halves at most
// log2((E - E_lb) / (E* - E_lb)) times, so near it every try is made; near an
// isometric minimum (E* = E_lb), where it may halve at every step, the clamp
// and the exact Hessian differ by the compressed elements' twist curvature,
// which vanishes there. Where E_lb is unknown a unit step accepted at once
// suffices. Before the first step
// nothing has tested the model, and the run's first assembly is the clamp,
// which always factors (mu starts at 1 and follows the steps from there): after
// the exponential energies' warm start the exact Hessian is not positive
// definite at the first iterate of camelhead's and horse_b's AMIPS, and trying
// it and then the partial shares took up to four factorizations there where one
// serves. After a step the flip-free bound or the line search shortened (a
// switch from AKVF's far phase included), the model's minimizer was not
// acceptable and the exact Hessian is usually indefinite there, so the try
// would cost a numeric factorization that fails; the fallback (with its mu) is
// used at once instead. On the SLIM cube the default then reaches the 1e-4 band
// in 6 iterations instead of 7 after its switch (docs/design.md); on the disk
// meshes of ../shared/meshes/tri the iterations are unchanged. So it is after
// a switch from AKVF, whatever its last step (start_on_fallback): that step
// tested AKVF's model, not Newton's, and after AKVF's unit step the exact
// Hessian did not factor at MIPS's switch on 4 of 4 disk meshes, nor at
// ARAP's on 6 of 6 (camelhead's MIPS: the switch iteration's preconditioner
// took 27 ms against 14 without the try). Where the caller
// knows the Hessian to be far from positive definite (akvf-newton's switch with
// the soft constraints still far, switching_preconditioner.h), the first
// fallback is the clamp instead of mu = 1/16 (start_fallback_at_clamp), saving
// the tries that would fail. Only a factorization tells
// whether the Hessian is positive definite: with multigrid or Jacobi CG
// (FactorOptions) kExact clamps.
//
// Where the density's collapse barrier acts only below det J = g_hat
// (ARAP's, energies/arap.h: collapse_barrier_onset), no Hessian sees it
// above, and a triangle pushed toward a collapse is blind to it until it
// is in range: Newton's direction sends it past det J = 0, the flip-free
// bound cuts the step to 0.8 of the way there, and the next iteration does
// the same with the next triangle (jittered camelhead: about 500 triangles
// end near the barrier, settled about one per iteration, 894 iterations).
// So P adds, per element, the Gauss-Newton Hessian of g_hat (-log det J),
//   w_e g_hat c c^T / det(J)^2,  c = d det J / dvec(J),
// a damping of g_hat (d det J / det J)^2 per unit rest measure. Under an
// O(1) pull on its area (ARAP's slope in a compressed triangle's singular
// values, 2 (sigma - 1), is at most 2 in magnitude) the model changes its area
// by about det J / g_hat times itself: the triangles slow down as they near
// the barrier's range, and the others hardly notice (at a third of its rest
// area, 0.3 % of ARAP's own curvature along the area). It changes the
// direction, not the energy. On the jittered hilbert_b strips the
// default's Newton phase then no longer closes in on one collapse; it is
// held by the bound behind AKVF's pace instead, which sends it back there
// as well (switching_preconditioner.h).
//
// Within the barrier's range (det J < g_hat) an element's negative
// eigenvalues are clamped in every assembly, the exact tries and the partly
// filtered fallback included. There the barrier's slope b_g < 0 adds to the
// element's twist eigenvalue, in 2D 2 - 4 / (sigma_1 + sigma_2) + b_g
// (ARAP's own curvature is at most 2), and b_g moves fast with det J: about
// -32 at r = det J / g_hat = 0.9, where a change of det J by 1 % of g_hat
// moves it by 6, and about -1 / det J deeper in. So the exact Hessian is
// positive definite only very near a minimum where such elements rest;
// anywhere else a try costs a factorization that fails, and so does the
// fallback with a small share (docs/notes/2026-12-04-barrier-range-clamp.md
// counts them). Near such a minimum the clamp leaves their twist out of the
// model and the tail is linear, so an exact try keeps them exact where every
// element in the range has settled: det J moved by less than
// kSettledShare = 1 % of g_hat since the last assembly. Over such a move the
// barrier's curvature b'' changes by 4-11 % where 0.2 <= r <= 0.9
// (|b''' / b''| is 4-11 there, about 2 / r deeper in), so its quadratic
// model holds.
//
// The boundary barrier of global injectivity (boundary_contact.h) enters P
// through its active terms, each term's Hessian b'' (dq/dx)(dq/dx)^T +
// b' d^2q/dx^2 projected to be positive semi-definite (contact_curvature.h):
// the negative part of b' d^2q/dx^2 (b' < 0) is left out, and near a
// minimum the barrier holds, the tail is linear
// (docs/notes/2026-12-05-settled-contact-exact.md). So the same exact
// tries keep the terms' Hessians whole where every active term has
// settled: its argument q moved by less
// than kSettledShare of its reach eps since the last assembly. With
// b = w (eps / q - 1)^2, |b''' / b''| eps is 6-9 for 0.5 <= q / eps <= 1 and
// 14 at 0.3, so over such a move b'' changes by 6-14 % there.
//
// The collapse barrier's range and the boundary barrier's terms (the
// barriers' ranges) are kept exact together, where both have settled. If
// that try does not factor, it is made again at the same x with both
// clamped, and they wait 1, 2, 4, ... exact tries before they are kept
// exact again (a success resets the wait).
#include <limits>
#include <string>

#include "akvf/mesh_objective.h"
#include "preconditioners/factored_preconditioner.h"

namespace akvf {

enum class EigenvalueFilter { kClamp, kAbsolute, kAdaptive, kExact };
// The motions projected out of the direction by default: rigid motions in 2D
// (the energy's null space), none in 3D (the constraints fix the motion).
constexpr MotionProjection default_newton_projection(int dimension) {
  return dimension == 2 ? MotionProjection::kRigidMotions : MotionProjection::kNone;
}

template <int D>
class NewtonPreconditioner final : public FactoredPreconditioner<D> {
 public:
  explicit NewtonPreconditioner(const MeshObjective<D>& objective, FactorOptions options = {},
                                MotionProjection projection = default_newton_projection(D),
                                EigenvalueFilter filter = EigenvalueFilter::kClamp);
  // The same on the sparsity pattern of `same_elements`, another
  // preconditioner's matrix on the objective's elements (akvf-newton hands
  // over AKVF's at the switch).
  NewtonPreconditioner(const MeshObjective<D>& objective, const ElementMatrix<D, D + 1>& same_elements,
                       FactorOptions options, MotionProjection projection, EigenvalueFilter filter);
  // The same on `matrix`'s storage (FactoredPreconditioner::hand_over_matrix).
  NewtonPreconditioner(const MeshObjective<D>& objective, ElementMatrix<D, D + 1>&& matrix, FactorOptions options,
                       MotionProjection projection, EigenvalueFilter filter);
  std::string name() const override { return "newton"; }
  bool has_element_curvature() const override { return true; }
  // The filter the last assembly used (kClamp, kAbsolute or kExact), and
  // how many assemblies mirrored.
  EigenvalueFilter last_filter() const { return last_filter_; }
  int mirrored_assemblies() const { return mirrored_assemblies_; }
  // kExact: assemblies with the exact Hessian, and how many of them were
  // replaced by the clamped one (not positive definite).
  int exact_assemblies() const { return exact_assemblies_; }
  int exact_fallbacks() const { return exact_fallbacks_; }
  // kExact's fallback (module comment): whether the last assembly was it,
  // the share of the negative part it kept, and how often it was itself
  // not positive definite (the share then quadruples, up to the clamp).
  bool last_partly_filtered() const { return partial_; }
  double negative_share() const { return negative_share_; }
  int partial_fallbacks() const { return partial_fallbacks_; }
  // kExact: the next fallback is the clamp (mu = 1), relaxed to 1/4 and
  // 1/16 as fallbacks factor at their first try; where the exact Hessian is
  // known to be far from positive definite (akvf-newton's switch with the
  // constraints still far: switching_preconditioner.h).
  void start_fallback_at_clamp() { negative_share_ = 1; }
  // kExact: the first assembly is the fallback, the exact Hessian is tried
  // from the second on; where the last step was another method's
  // (akvf-newton's switch), so nothing has tested Newton's model yet.
  void start_on_fallback() { exact_backoff_.skip_next(1); }
  std::string report() const override;

  // kExact: tries that kept the barriers' ranges exact (the elements within
  // the collapse barrier's range, the boundary barrier's active terms), and
  // how many of them did not factor (module comment).
  int range_exact_tries() const { return range_exact_tries_; }
  int range_exact_fallbacks() const { return range_exact_fallbacks_; }

  static constexpr double adaptive_tolerance = 0.01;
  static constexpr double kLeastNegativeShare = 1.0 / 16;
  static constexpr double kSettledShare = 0.01;

 private:
  // The barrier's terms as the elements: each term's whole Hessian,
  // projected unless the barriers' ranges are kept exact (module comment).
  ContactModel contact_model() const override {
    return range_exact_ && last_filter_ == EigenvalueFilter::kExact ? ContactModel::kHessian
                                                                    : ContactModel::kProjectedHessian;
  }
  using Matrix = typename FactoredPreconditioner<D>::Matrix;
  void assemble(const OptimizationState& state, Matrix* matrix) override;
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override { return motion_basis(D, projection_, x); }
  bool reassemble_semidefinite(Matrix* matrix) override;
  // kExact in 2D: adds to P's diagonal, on each chart's coordinates, twice
  // the Hessian's negative curvature along that chart's rotation (module comment).
  void add_rotation_shifts(const Eigen::VectorXd& x, const Eigen::VectorXd& gradient, Matrix* matrix) const;
  // Fills matrix with sum_e w_e G_e^T H_e G_e, H_e the element Hessian at x
  // filtered by `filter` (kClamp, kAbsolute or kExact).
  // negative_share < 1 with kClamp: kExact's fallback, the exact Hessian
  // plus that share of its negative part's magnitude (module comment).
  void assemble_filtered(const Eigen::VectorXd& x, EigenvalueFilter filter, Matrix* matrix,
                         double negative_share = 1) const;
  // The same from the density's eigensystem (HessianEigensystem), each
  // eigenvalue filtered: no element Hessian formed.
  void assemble_from_modes(const Eigen::VectorXd& x, const HessianEigensystem<D>& eigensystem, EigenvalueFilter filter,
                           Matrix* matrix, double negative_share) const;
  // P at x by last_filter_ (and the fallback's share), with the rotation
  // shifts where it is based on the exact Hessian.
  void assemble_current(const Eigen::VectorXd& x, const Eigen::VectorXd& gradient, Matrix* matrix) const;
  // kAdaptive's choice at `state` (and remembers the state for the next).
  EigenvalueFilter adaptive_choice(const OptimizationState& state);
  // kExact: the last step was Newton's unit step accepted at once and left
  // more than half of E - E_lb, where the model held near the minimum
  // (module comment).
  bool model_held_near_minimum(const OptimizationState& state) const;
  // det J below the density's collapse barrier onset g_hat: the element's
  // negative eigenvalues are clamped unless the range has settled (module
  // comment).
  bool in_collapse_range(double det) const { return area_damping_ > 0 && det < area_damping_; }
  // Some element of x is within the collapse range or some boundary barrier
  // term is active, and each such element's det J (term's q) differs from
  // its value at assembled_x_ by less than kSettledShare g_hat (its reach).
  bool barrier_ranges_settled(const Eigen::VectorXd& x) const;
  // The element's negative eigenvalues are clamped in an assembly by `filter`.
  bool clamped_in_range(double det, EigenvalueFilter filter) const {
    return in_collapse_range(det) && !(filter == EigenvalueFilter::kExact && range_exact_);
  }
  // s^T H(x) s with the unfiltered Hessian, the constraints' term included.
  double exact_curvature(const Eigen::VectorXd& x, const Eigen::VectorXd& s) const;

  const MeshObjective<D>& objective_;
  MotionProjection projection_;
  EigenvalueFilter filter_;
  double area_damping_;  // mu of the log-area damping: the density's collapse_barrier_onset()
  EigenvalueFilter last_filter_ = EigenvalueFilter::kClamp;
  int mirrored_assemblies_ = 0;
  int exact_assemblies_ = 0, exact_fallbacks_ = 0;
  Backoff exact_backoff_;  // kExact: the iterations on the fallback before the exact Hessian is tried again
  // kExact: whether the last exact try kept the barriers' ranges exact, and
  // the exact tries that clamp them before they are kept again.
  bool range_exact_ = false;
  Backoff range_backoff_;
  int range_exact_tries_ = 0, range_exact_fallbacks_ = 0;
  Eigen::VectorXd assembled_x_, assembled_gradient_;  // kExact: where P was last assembled
  // kExact's fallback (module comment): whether the last assembly was it,
  // whether it failed since, and the share of the negative part it keeps.
  bool partial_ = false, partial_failed_ = false;
  double negative_share_ = kLeastNegativeShare;
  int partial_fallbacks_ = 0;
  Eigen::VectorXd previous_x_, previous_gradient_;                     // kAdaptive: at the last assembly
  double previous_energy_ = std::numeric_limits<double>::quiet_NaN();  // at the last assembly
};

using NewtonPreconditioner2D = NewtonPreconditioner<2>;
using NewtonPreconditioner3D = NewtonPreconditioner<3>;

}  // namespace akvf
