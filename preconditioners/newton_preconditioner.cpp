#include "preconditioners/newton_preconditioner.h"

#include <algorithm>
#include <cmath>

#include "energies/invariant_density_2d.h"
#include "energies/invariant_density_3d.h"
#include "framework/optimization/element_derivatives.h"

namespace akvf {

namespace {

// The log-area damping's weight, (w) g_hat / det(J)^2 (newton_preconditioner.h),
// 0 where it overflows (an element collapsed to rounding), as the filters
// drop a NaN eigenvalue.
double log_area_damping(double weighted_onset, double det) {
  const double mu = weighted_onset / (det * det);
  return std::isfinite(mu) ? mu : 0.0;
}

// d det J / dvec(J), the cofactor, in vec(J)'s column-major order.
Eigen::Vector4d determinant_gradient(const Eigen::Matrix2d& J) { return cofactor_2d(J); }
Eigen::Matrix<double, 9, 1> determinant_gradient(const Eigen::Matrix3d& J) {
  const Eigen::Matrix3d C = cofactor_3d(J);
  return Eigen::Map<const Eigen::Matrix<double, 9, 1>>(C.data());
}

// The exact Hessian's curvature along the rotation of the vertices
// `vertices` of a 2D map (one chart), r^T H r / |r|^2 with
// r_i = Q (x_i - c) (c their centroid, Q the quarter turn). E(R_t x) = E(x)
// for every rotation R_t of the chart, so differentiating twice at t = 0,
// r^T H r = -grad E . d^2/dt^2 R_t x = grad E . (x - c) over the chart (its
// gradient sums to zero over each coordinate), and |r| = |x - c|. It is
// negative wherever expanding the chart lowers the energy, however close to
// the minimum, and vanishes with the gradient.
double rotation_curvature_2d(const Eigen::VectorXd& x, const Eigen::VectorXd& gradient,
                             const std::vector<int>& vertices) {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (int v : vertices) centroid += x.segment<2>(2 * v);
  centroid /= static_cast<double>(vertices.size());
  double along = 0, squared_norm = 0;
  for (int v : vertices) {
    const Eigen::Vector2d offset = x.segment<2>(2 * v) - centroid;
    along += gradient.segment<2>(2 * v).dot(offset);
    squared_norm += offset.squaredNorm();
  }
  return along / squared_norm;
}

}  // namespace

template <int D>
NewtonPreconditioner<D>::NewtonPreconditioner(const MeshObjective<D>& objective, FactorOptions options,
                                              MotionProjection projection, EigenvalueFilter filter)
    : FactoredPreconditioner<D>(objective, std::move(options)),
      objective_(objective),
      projection_(projection),
      filter_(filter),
      area_damping_(objective.density().collapse_barrier_onset()) {}

template <int D>
NewtonPreconditioner<D>::NewtonPreconditioner(const MeshObjective<D>& objective,
                                              const ElementMatrix<D, D + 1>& same_elements, FactorOptions options,
                                              MotionProjection projection, EigenvalueFilter filter)
    : NewtonPreconditioner(objective, ElementMatrix<D, D + 1>::with_pattern_of(same_elements), std::move(options),
                           projection, filter) {}

template <int D>
NewtonPreconditioner<D>::NewtonPreconditioner(const MeshObjective<D>& objective, ElementMatrix<D, D + 1>&& matrix,
                                              FactorOptions options, MotionProjection projection,
                                              EigenvalueFilter filter)
    : FactoredPreconditioner<D>(objective, std::move(options), std::move(matrix)),
      objective_(objective),
      projection_(projection),
      filter_(filter),
      area_damping_(objective.density().collapse_barrier_onset()) {}

template <int D>
double NewtonPreconditioner<D>::exact_curvature(const Eigen::VectorXd& x, const Eigen::VectorXd& s) const {
  double curvature = 0;
  for (int e = 0; e < objective_.weights().size(); ++e) {
    // J is linear in the positions, so jacobian(s) is the change of J along s.
    const auto dJ = objective_.jacobian(s, e);
    const Eigen::Map<const Eigen::Matrix<double, D * D, 1>> v(dJ.data());
    curvature += objective_.weights()[e] * v.dot(objective_.density().hessian(objective_.jacobian(x, e)) * v);
  }
  const Eigen::VectorXd& added = objective_.added_hessian_diagonal();
  if (added.size() == s.size()) curvature += s.dot(added.cwiseProduct(s));
  return curvature;
}

template <int D>
EigenvalueFilter NewtonPreconditioner<D>::adaptive_choice(const OptimizationState& state) {
  EigenvalueFilter choice = EigenvalueFilter::kAbsolute;
  if (previous_x_.size() == state.x.size()) {
    const Eigen::VectorXd s = state.x - previous_x_;
    const double predicted = -(previous_gradient_.dot(s) + 0.5 * exact_curvature(previous_x_, s));
    const double rho = (previous_energy_ - state.energy) / predicted;
    if (std::abs(rho - 1) < adaptive_tolerance) choice = EigenvalueFilter::kClamp;
  }
  previous_x_ = state.x;
  previous_gradient_ = state.gradient;
  return choice;
}

template <int D>
bool NewtonPreconditioner<D>::model_held_near_minimum(const OptimizationState& state) const {
  if (!(state.previous_step == 1 && !state.previous_backtracked)) return false;
  // Not halved where E_lb is unknown (-inf) or there is no earlier energy (NaN).
  const double lower_bound = objective_.lower_bound();
  const bool halved = state.energy - lower_bound < 0.5 * (previous_energy_ - lower_bound);
  return !halved;
}

template <int D>
void NewtonPreconditioner<D>::assemble(const OptimizationState& state, Matrix* matrix) {
  const ContactModel contact_used = contact_model();  // update()'s C(x), before this assembly's choices
  if (filter_ == EigenvalueFilter::kAdaptive) {
    last_filter_ = adaptive_choice(state);
  } else if (filter_ == EigenvalueFilter::kExact) {
    // The last exact Hessian served (no fallback since): try it at once next time.
    if (last_filter_ == EigenvalueFilter::kExact) exact_backoff_.succeeded();
    if (last_filter_ == EigenvalueFilter::kExact && range_exact_) range_backoff_.succeeded();
    // Only a factorization tells whether the exact Hessian is positive
    // definite; it is tried where Newton's model held, never before the
    // first step, which uses the clamp (module comment).
    const bool model_held = model_held_near_minimum(state);
    if (state.previous_step == 0) start_fallback_at_clamp();
    const bool waiting = exact_backoff_.skip();
    last_filter_ = waiting || !model_held || !this->solves_by_factorization() ? EigenvalueFilter::kClamp
                                                                              : EigenvalueFilter::kExact;
  } else {
    last_filter_ = filter_;
  }
  mirrored_assemblies_ += last_filter_ == EigenvalueFilter::kAbsolute;
  // kExact's fallback served (no failure since): the next keeps less of the
  // negative part after a unit step, more after a step the flip-free bound
  // set (module comment).
  if (partial_ && !partial_failed_) {
    const bool bound_set = state.previous_step > 0 && state.previous_step < 1 && !state.previous_backtracked;
    if (bound_set)
      negative_share_ = std::min(1.0, 4 * negative_share_);
    else if (model_held_near_minimum(state))
      negative_share_ = std::max(kLeastNegativeShare, negative_share_ / 4);
  }
  previous_energy_ = state.energy;
  partial_ = filter_ == EigenvalueFilter::kExact && last_filter_ == EigenvalueFilter::kClamp &&
             this->solves_by_factorization();
  partial_failed_ = false;
  if (last_filter_ == EigenvalueFilter::kExact) ++exact_assemblies_;
  // The barriers' ranges kept exact where they have settled (module comment).
  range_exact_ = false;
  if (last_filter_ == EigenvalueFilter::kExact && !range_backoff_.skip())
    range_exact_ = barrier_ranges_settled(state.x);
  range_exact_tries_ += range_exact_;
  if (contact_model() != contact_used) this->refresh_contact(state.x);
  if (filter_ == EigenvalueFilter::kExact) {  // kept for a fallback at the same x
    assembled_x_ = state.x;
    assembled_gradient_ = state.gradient;
  }
  assemble_current(state.x, state.gradient, matrix);
}

template <int D>
void NewtonPreconditioner<D>::assemble_current(const Eigen::VectorXd& x, const Eigen::VectorXd& gradient,
                                               Matrix* matrix) const {
  const bool exact_based = last_filter_ == EigenvalueFilter::kExact || (partial_ && negative_share_ < 1);
  assemble_filtered(x, last_filter_, matrix, partial_ ? negative_share_ : 1.0);
  if (exact_based && projection_ == MotionProjection::kRigidMotions && D == 2) add_rotation_shifts(x, gradient, matrix);
}

template <int D>
void NewtonPreconditioner<D>::add_rotation_shifts(const Eigen::VectorXd& x, const Eigen::VectorXd& gradient,
                                                  Matrix* matrix) const {
  // Twice the negative curvature along each chart's rotation, on that
  // chart's coordinates (newton_preconditioner.h).
  const auto* charts = this->component_vertices();
  if (!charts) {
    std::vector<int> all(static_cast<size_t>(x.size() / D));
    for (size_t v = 0; v < all.size(); ++v) all[v] = static_cast<int>(v);
    const double curvature = rotation_curvature_2d(x, gradient, all);
    if (curvature < 0) matrix->add_to_diagonal(-2 * curvature);
    return;
  }
  Eigen::VectorXd shift = Eigen::VectorXd::Zero(x.size());
  for (const std::vector<int>& chart : *charts) {
    const double curvature = rotation_curvature_2d(x, gradient, chart);
    if (curvature < 0)
      for (int v : chart) shift.template segment<D>(D * v).setConstant(-2 * curvature);
  }
  matrix->add_to_diagonal(shift);
}

template <int D>
void NewtonPreconditioner<D>::assemble_filtered(const Eigen::VectorXd& x, EigenvalueFilter filter, Matrix* matrix,
                                                double negative_share) const {
  if (const auto* eigensystem = dynamic_cast<const HessianEigensystem<D>*>(&objective_.density())) {
    assemble_from_modes(x, *eigensystem, filter, matrix, negative_share);
    return;
  }
  matrix->assemble([&](int e, typename Matrix::Local* local) {
    const auto G = jacobian_map<D>(objective_.rest().Dm_inv[e]);
    const auto J = objective_.jacobian(x, e);
    using ElementHessian = decltype(objective_.density().hessian(J));
    ElementHessian H;
    if (filter == EigenvalueFilter::kAbsolute)
      H = objective_.density().absolute_hessian(J);
    else if (clamped_in_range(J.determinant(), filter))  // clamped in exact-based assemblies (module comment)
      H = objective_.density().projected_hessian(J);
    else if (filter == EigenvalueFilter::kExact)
      H = objective_.density().hessian(J);
    else if (negative_share < 1)  // H + share N, N = clamped - exact: negative eigenvalues times 1 - share
      H = (1 - negative_share) * objective_.density().hessian(J) +
          negative_share * objective_.density().projected_hessian(J);
    else
      H = objective_.density().projected_hessian(J);
    if (area_damping_ > 0) {  // the log-area damping (module comment)
      const auto c = determinant_gradient(J);
      H += log_area_damping(area_damping_, J.determinant()) * c * c.transpose();
    }
    *local = objective_.weights()[e] * G.transpose() * H * G;
  });
}

template <int D>
void NewtonPreconditioner<D>::assemble_from_modes(const Eigen::VectorXd& x, const HessianEigensystem<D>& eigensystem,
                                                  EigenvalueFilter filter, Matrix* matrix,
                                                  double negative_share) const {
  // Each filtered eigenvalue: the exact one, |lambda|, or a negative one
  // times 1 - share (share 1: the clamp), as assemble_filtered's matrices,
  // and clamped in an element within the collapse barrier's range unless
  // the range has settled (module comment); a NaN (overflow at a nearly
  // collapsed element) dropped, as the clamp does.
  // The log-area damping (module comment) is one more term of the sum, along
  // the cofactor c = d det J / dJ with mu = g_hat / det(J)^2.
  const double negative_scale = filter == EigenvalueFilter::kExact ? 1 : 1 - negative_share;
  const auto filtered = [&](double lambda, bool in_range) {
    if (lambda > 0) return lambda;
    if (!(lambda < 0)) return 0.0;
    if (filter == EigenvalueFilter::kAbsolute) return -lambda;
    return in_range ? 0.0 : negative_scale * lambda;
  };
  constexpr int kCorners = D + 1, kSize = D * kCorners;
  // G^T H G = sum_i mu_i u_i u_i^T with u_i = G^T vec(M_i): corner k's part
  // of u_i is M_i grad_k (J = sum_k x_k grad_k^T, grad_k the rest gradient of
  // corner k's hat function). Only the upper triangle is read. A batch's
  // eigensystems come first, one after another: each is a chain of square
  // roots and divisions that the processor overlaps with the next one's
  // (docs/notes/2026-12-02-assembly-batches-and-contact-pattern.md).
  matrix->assemble_batches([&](const int* elements, int count, typename Matrix::Local* locals) {
    typename HessianEigensystem<D>::Eigenpairs batch[Matrix::kBatch];
    Eigen::Matrix<double, D, D> jacobians[Matrix::kBatch];
    for (int b = 0; b < count; ++b) {
      jacobians[b] = objective_.jacobian(x, elements[b]);
      batch[b] = eigensystem.hessian_eigensystem(jacobians[b]);
    }
    for (int b = 0; b < count; ++b) {
      const auto grad = hat_gradients<D>(objective_.rest().Dm_inv[elements[b]]);
      const auto& pairs = batch[b];
      const double weight = objective_.weights()[elements[b]];
      constexpr int kTerms = D * D + 1;
      const int terms = area_damping_ > 0 ? kTerms : D * D;
      double u[kTerms][kSize], scaled[kTerms][kSize];
      const auto add_term = [&](int i, const Eigen::Matrix<double, D, D>& M, double mu) {
        for (int k = 0; k < kCorners; ++k)
          for (int r = 0; r < D; ++r) {
            double sum = 0;
            for (int c = 0; c < D; ++c) sum += M(r, c) * grad[k][c];
            u[i][D * k + r] = sum;
            scaled[i][D * k + r] = mu * sum;
          }
      };
      const bool in_range = clamped_in_range(jacobians[b].determinant(), filter);
      for (int i = 0; i < D * D; ++i) add_term(i, pairs.modes[i], weight * filtered(pairs.values[i], in_range));
      if (area_damping_ > 0) {
        const Eigen::Matrix<double, D, D>& J = jacobians[b];
        const auto c = determinant_gradient(J);
        add_term(D * D, Eigen::Map<const Eigen::Matrix<double, D, D>>(c.data()),
                 log_area_damping(weight * area_damping_, J.determinant()));
      }
      for (int j = 0; j < kSize; ++j)
        for (int r = 0; r <= j; ++r) {
          double sum = 0;
          for (int i = 0; i < terms; ++i) sum += scaled[i][r] * u[i][j];
          locals[b](r, j) = sum;
        }
    }
  });
}

template <int D>
bool NewtonPreconditioner<D>::barrier_ranges_settled(const Eigen::VectorXd& x) const {
  if (assembled_x_.size() != x.size()) return false;
  bool any = false;
  if (const ContactCurvature* contact = this->contact_curvature()) {
    for (const BoundaryContact::ActiveTerm& term : contact->contact().active_terms(x)) {
      const double before = BoundaryContact::argument_at(term, assembled_x_);
      if (!(std::abs(term.argument - before) < kSettledShare * term.reach)) return false;
      any = true;
    }
  }
  if (!(area_damping_ > 0)) return any;
  for (int e = 0; e < objective_.weights().size(); ++e) {
    const double det = objective_.jacobian(x, e).determinant();
    if (!in_collapse_range(det)) continue;
    const double before = objective_.jacobian(assembled_x_, e).determinant();
    if (!(std::abs(det - before) < kSettledShare * area_damping_)) return false;
    any = true;
  }
  return any;
}

template <int D>
bool NewtonPreconditioner<D>::reassemble_semidefinite(Matrix* matrix) {
  if (last_filter_ == EigenvalueFilter::kExact && range_exact_) {  // the same try, the range clamped
    ++range_exact_fallbacks_;
    range_exact_ = false;
    range_backoff_.failed();
    this->refresh_contact(assembled_x_);  // C(x) projected again
    assemble_current(assembled_x_, assembled_gradient_, matrix);
    return true;
  }
  if (last_filter_ == EigenvalueFilter::kExact) {
    ++exact_fallbacks_;
    exact_backoff_.failed();
    last_filter_ = EigenvalueFilter::kClamp;
    partial_ = true;
  } else if (partial_ && negative_share_ < 1) {
    ++partial_fallbacks_;
    negative_share_ = std::min(1.0, 4 * negative_share_);
  } else {
    return false;  // the clamped Hessian: the shift is raised instead
  }
  partial_failed_ = true;
  assemble_current(assembled_x_, assembled_gradient_, matrix);
  return true;
}

template <int D>
std::string NewtonPreconditioner<D>::report() const {
  std::string line = FactoredPreconditioner<D>::report();
  if (exact_assemblies_ > 0)
    line += "; exact Hessian at " + std::to_string(exact_assemblies_ - exact_fallbacks_) + " of " +
            std::to_string(exact_assemblies_) + " tries";
  if (range_exact_tries_ > 0)
    line += " (the barriers' ranges exact at " + std::to_string(range_exact_tries_ - range_exact_fallbacks_) + " of " +
            std::to_string(range_exact_tries_) + ")";
  if (partial_fallbacks_ > 0)
    line += ", its partly filtered fallback not positive definite at " + std::to_string(partial_fallbacks_);
  return line;
}

template class NewtonPreconditioner<2>;
template class NewtonPreconditioner<3>;

}  // namespace akvf
