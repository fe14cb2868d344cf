#include "preconditioners/factored_preconditioner.h"

#include <Eigen/IterativeLinearSolvers>
#include <algorithm>
#include <cmath>

#include "akvf/error.h"
#include "framework/mesh/mesh_topology.h"
#include "framework/process/physical_memory.h"

namespace akvf {

namespace {

FactorOptions with_added_diagonal(FactorOptions options, const Eigen::VectorXd& added) {
  if (options.extra_diagonal.size() == 0) options.extra_diagonal = added;
  return options;
}

}  // namespace

template <int D>
FactoredPreconditioner<D>::FactoredPreconditioner(const MeshObjective<D>& objective, FactorOptions options)
    : FactoredPreconditioner(objective.elements(), objective.num_vertices(),
                             with_added_diagonal(std::move(options), objective.added_hessian_diagonal()),
                             Matrix(objective.elements(), objective.num_vertices())) {}

template <int D>
FactoredPreconditioner<D>::FactoredPreconditioner(const MeshObjective<D>& objective, FactorOptions options,
                                                  const Matrix& same_elements)
    : FactoredPreconditioner(objective, std::move(options), Matrix::with_pattern_of(same_elements)) {}

template <int D>
FactoredPreconditioner<D>::FactoredPreconditioner(const MeshObjective<D>& objective, FactorOptions options,
                                                  Matrix&& matrix)
    : FactoredPreconditioner(objective.elements(), objective.num_vertices(),
                             with_added_diagonal(std::move(options), objective.added_hessian_diagonal()),
                             std::move(matrix)) {}

template <int D>
FactoredPreconditioner<D>::FactoredPreconditioner(const Eigen::MatrixXi& elements, int num_vertices,
                                                  FactorOptions options)
    : FactoredPreconditioner(elements, num_vertices, std::move(options), Matrix(elements, num_vertices)) {}

template <int D>
FactoredPreconditioner<D>::FactoredPreconditioner(const Eigen::MatrixXi& elements, int num_vertices,
                                                  FactorOptions options, Matrix matrix)
    : options_(options), matrix_(std::move(matrix)), relative_shift_(options_.tikhonov) {
  if (!(options_.tikhonov > 0)) throw OptionsError("Tikhonov shift must be > 0");
  if (!(options_.max_tikhonov >= options_.tikhonov))
    throw OptionsError("the largest Tikhonov shift must be >= the Tikhonov shift");
  if (!(options_.iterative_tikhonov > 0)) throw OptionsError("the iterative solves' Tikhonov shift must be > 0");
  if (!(options_.absolute_shift >= 0)) throw OptionsError("absolute Tikhonov shift must be >= 0");
  if (!(options_.reuse_tolerance >= 0 && options_.reuse_tolerance < 1))
    throw OptionsError("factorization reuse tolerance must be in [0, 1)");
  if (!(options_.cg_tolerance >= 0 && options_.cg_tolerance < 1)) throw OptionsError("CG tolerance must be in [0, 1)");
  if (options_.cg_max_iterations < 1) throw OptionsError("CG needs at least one iteration");
  if (options_.reuse_max_cg < 1) throw OptionsError("factorization reuse needs at least one CG iteration");
  if (options_.reuse_check_from < 1) throw OptionsError("a reuse attempt can be checked from CG iteration 1 on");
  if (!(options_.reuse_cg_flops_per_entry >= 0))
    throw OptionsError("the flops per factor entry of a reuse CG iteration must be >= 0");
  if (!(options_.auto_factor_bytes >= 0)) throw OptionsError("the automatic solver choice's factor limit must be >= 0");
  // Nothing to choose without multigrid, or with the Jacobi CG solve.
  if (options_.linear_solver == LinearSolver::kAuto && (!AlgebraicMultigrid::available() || options_.cg_tolerance > 0))
    options_.linear_solver = LinearSolver::kCholmod;
  if (options_.linear_solver == LinearSolver::kAmg || options_.linear_solver == LinearSolver::kAuto) {
    AlgebraicMultigrid::require_available();
    if (!(options_.amg_tolerance > 0 && options_.amg_tolerance < 1))
      throw OptionsError("the multigrid solve's tolerance must be in (0, 1)");
    if (options_.amg_max_cg < 1 || options_.amg_setup_cycles < 0)
      throw OptionsError("the multigrid solve needs at least one CG iteration and a setup cost >= 0");
    if (options_.cg_tolerance > 0)
      throw OptionsError("choose one of the Jacobi CG solve (a CG tolerance) and the multigrid solve");
  }
  if (options_.extra_diagonal.size() != 0 &&
      (options_.extra_diagonal.size() != static_cast<Eigen::Index>(D) * num_vertices ||
       !(options_.extra_diagonal.array() >= 0).all()))
    throw OptionsError("the extra diagonal of a preconditioner needs one value >= 0 per coordinate");
  int components = 0;
  const std::vector<int> component = vertex_components(elements, num_vertices, &components);
  if (components > 1) {
    auto vertices = std::make_shared<std::vector<std::vector<int>>>(components);
    for (int v = 0; v < num_vertices; ++v)
      if (component[v] >= 0) (*vertices)[component[v]].push_back(v);
    component_vertices_ = std::move(vertices);
  }
}

template <int D>
std::string FactoredPreconditioner<D>::report() const {
  if (statistics_.multigrid_setups > 0)
    return std::to_string(statistics_.multigrid_setups) + " multigrid setups, " +
           std::to_string(statistics_.reused_solves) + " solves with an earlier hierarchy (" +
           std::to_string(statistics_.cg_iterations) + " CG iterations)";
  if (statistics_.cg_solves > 0)
    return std::to_string(statistics_.cg_solves) + " CG solves (" + std::to_string(statistics_.cg_iterations) +
           " iterations), no factorization";
  std::string line = std::to_string(statistics_.factorizations) + " factorizations, " +
                     std::to_string(statistics_.reused_solves) + " solves with an earlier factor (" +
                     std::to_string(statistics_.cg_iterations) + " CG iterations)";
  // Only the large meshes' ordering is worth a word (sparse_cholesky.cpp, use_metis).
  if (cholesky_.ordering() == "metis") line += ", METIS ordering";
  if (shift_increases_ > 0) line += "; " + std::to_string(shift_increases_) + " retried with a 100x larger shift";
  return line;
}

template <int D>
void FactoredPreconditioner<D>::take_over_factorization(FactoredPreconditioner& previous) {
  if (factored_ || !matrix_.same_pattern(previous.matrix_))
    throw NumericalError("take_over_factorization: before the first update, from a matrix of the same pattern");
  if (options_.linear_solver == LinearSolver::kAuto && previous.options_.linear_solver != LinearSolver::kAuto)
    options_.linear_solver = previous.options_.linear_solver;
  cholesky_.take_over(&previous.cholesky_);
  analyzed_contact_version_ = previous.analyzed_contact_version_;
}

template <int D>
void FactoredPreconditioner<D>::choose_linear_solver() {
  analyze();
  const double limit = options_.auto_factor_bytes > 0 ? options_.auto_factor_bytes : 0.5 * physical_memory_bytes();
  if (cholesky_.factor_bytes() <= limit) {
    options_.linear_solver = LinearSolver::kCholmod;
    return;
  }
  options_.linear_solver = LinearSolver::kAmg;
  if (options_.analysis_cache) options_.analysis_cache->forget(matrix_.upper(), D);
  cholesky_.clear();
}

template <int D>
void FactoredPreconditioner<D>::update(const OptimizationState& state) {
  if (options_.contact_curvature) {
    contact_ = options_.contact_curvature->at(state.x, contact_model());
    system_current_ = false;
  }
  if (options_.linear_solver == LinearSolver::kAuto) choose_linear_solver();
  if (options_.linear_solver == LinearSolver::kAmg || options_.cg_tolerance > 0)
    relative_shift_ = std::max(relative_shift_, options_.iterative_tikhonov);
  null_basis_ = component_vertices_ ? ComponentMotions(D, component_vertices_, state.x,
                                                       [this](const Eigen::VectorXd& part) { return null_space(part); })
                                    : ComponentMotions(null_space(state.x));
  // The barrier stiffens a dilation, which K_0's null space holds: P + C's
  // null space is then the rest (P_N (P + C)^-1 g would not descend).
  if (contact_.nonZeros() > 0) null_basis_.keep_unstiffened_by(contact_);
  const auto assemble_shifted = [&] {
    assemble(state, &matrix_);
    add_shift();
  };
  if (options_.linear_solver == LinearSolver::kAmg) {
    // apply() builds or reuses the hierarchy (a constant P is assembled once).
    if (!fixed_system() || !multigrid_.ready()) assemble_shifted();
    return;
  }
  if (fixed_system()) {
    if (!factored_) {
      assemble_shifted();
      factorize_current();
    }
    factor_is_current_ = true;
    return;
  }
  assemble_shifted();
  factor_is_current_ = false;
  if (options_.cg_tolerance > 0) return;  // apply() runs CG on the assembled matrix
  // Without reuse, or before the first factorization, factor now (§5.2);
  // otherwise apply() decides whether the previous factor still serves.
  if (options_.reuse_tolerance <= 0 || !factored_ || !reuse_may_pay()) {
    factorize_current();
  } else if (reuse_backoff_.skip()) {
    factorize_current();
  }
}

template <int D>
int FactoredPreconditioner<D>::reuse_budget() const {
  if (options_.reuse_cg_flops_per_entry <= 0) return options_.reuse_max_cg;
  const double iterations =
      cholesky_.factor_flops() / (options_.reuse_cg_flops_per_entry * cholesky_.factor_nonzeros());
  return static_cast<int>(std::min<double>(options_.reuse_max_cg, std::floor(iterations)));
}

template <int D>
void FactoredPreconditioner<D>::add_shift() {
  system_current_ = false;
  // The Tikhonov shift: relative to mean(diag P), plus the absolute c.
  matrix_.add_to_diagonal(relative_shift_ * matrix_.mean_diagonal() + options_.absolute_shift);
  if (options_.extra_diagonal.size() != 0) matrix_.add_to_diagonal(options_.extra_diagonal);
}

template <int D>
const Eigen::SparseMatrix<double>& FactoredPreconditioner<D>::system() {
  // Until a term comes within reach C has no entry, and P + C is P.
  if (!options_.contact_curvature || contact_.nonZeros() == 0) return matrix_.upper();
  if (system_current_) return system_;
  const Eigen::SparseMatrix<double>& P = matrix_.upper();
  const int version = options_.contact_curvature->pattern_version();
  if (version != system_contact_version_ || P.nonZeros() != system_p_nonzeros_) {
    // The pattern of P + C, and where each of their nonzeros lands in it.
    system_ = P + contact_;
    system_contact_version_ = version;
    system_p_nonzeros_ = P.nonZeros();
    const auto slots = [this](const Eigen::SparseMatrix<double>& part, std::vector<int>* slot) {
      slot->resize(static_cast<std::size_t>(part.nonZeros()));
      for (int column = 0; column < part.outerSize(); ++column) {
        int k = system_.outerIndexPtr()[column];
        for (int p = part.outerIndexPtr()[column]; p < part.outerIndexPtr()[column + 1]; ++p) {
          while (system_.innerIndexPtr()[k] < part.innerIndexPtr()[p]) ++k;
          (*slot)[static_cast<std::size_t>(p)] = k;
        }
      }
    };
    slots(P, &system_slot_of_p_);
    slots(contact_, &system_slot_of_c_);
  } else {
    // The expression's sums: P's value plus C's where both have one, each
    // alone (plus 0) elsewhere.
    double* values = system_.valuePtr();
    std::fill(values, values + system_.nonZeros(), 0.0);
    for (std::size_t p = 0; p < system_slot_of_p_.size(); ++p) values[system_slot_of_p_[p]] += P.valuePtr()[p];
    for (std::size_t c = 0; c < system_slot_of_c_.size(); ++c) values[system_slot_of_c_[c]] += contact_.valuePtr()[c];
  }
  system_current_ = true;
  return system_;
}

template <int D>
void FactoredPreconditioner<D>::analyze() {
  // P + C's pattern grows with C's (contact_curvature.h); until C has a
  // pair it is P's, which the cache keeps.
  const int version = options_.contact_curvature ? options_.contact_curvature->pattern_version() : 0;
  if (cholesky_.analyzed()) {
    if (analyzed_contact_version_ == version) return;
    cholesky_.clear();
  }
  analyzed_contact_version_ = version;
  const BlockOrdering* order = options_.vertex_ordering.get();
  if (options_.analysis_cache && version == 0) {
    // The cache says whether it computed the analysis or copied a kept one.
    if (options_.analysis_cache->analyze(matrix_.upper(), D, &cholesky_, order)) ++statistics_.symbolic_analyses;
    return;
  }
  cholesky_.analyze(system(), D, order);
  ++statistics_.symbolic_analyses;
}

template <int D>
void FactoredPreconditioner<D>::factorize_current() {
  analyze();
  for (;;) {
    try {
      cholesky_.factorize(system());
      break;
    } catch (const NotPositiveDefinite& error) {
      if (reassemble_semidefinite(&matrix_)) {
        add_shift();
        continue;
      }
      if (relative_shift_ * 100 > options_.max_tikhonov)
        throw NotPositiveDefinite(std::string(error.what()) + " with a Tikhonov shift of " +
                                  std::to_string(relative_shift_) + " times its mean diagonal");
      // P + eps I becomes P + 100 eps I (mean(diag P) taken with the shift:
      // a relative 1e-12 of it).
      matrix_.add_to_diagonal(99 * relative_shift_ * matrix_.mean_diagonal());
      system_current_ = false;
      relative_shift_ *= 100;
      ++shift_increases_;
    }
  }
  factored_null_basis_ = null_basis_;
  factor_is_current_ = true;
  factored_ = true;
  ++statistics_.factorizations;
}

template <int D>
void FactoredPreconditioner<D>::apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) {
  if (options_.cg_tolerance > 0 && !fixed_system()) {
    solve_by_conjugate_gradients(gradient, result);
    return;
  }
  if (options_.linear_solver == LinearSolver::kAmg) {
    solve_by_multigrid(gradient, result);
    return;
  }
  if (!factor_is_current_) {
    if (solve_with_previous_factor(gradient, result)) {
      ++statistics_.reused_solves;
      reuse_backoff_.succeeded();
      return;
    }
    reuse_backoff_.failed();
    factorize_current();
  }
  cholesky_.solve(gradient, result);
  null_basis_.project_out(result);
  // An indefinite P that rounding let through the factorization.
  if (!(gradient.dot(*result) > 0) && reassemble_semidefinite(&matrix_)) {
    add_shift();
    factorize_current();
    cholesky_.solve(gradient, result);
    null_basis_.project_out(result);
  }
}

template <int D>
bool FactoredPreconditioner<D>::solve_with_previous_factor(const Eigen::VectorXd& g, Eigen::VectorXd* d) {
  if (options_.reuse_in_single_precision) cholesky_.round_factor_to_single();
  const auto inverse = [this](const Eigen::VectorXd& r, Eigen::VectorXd* z) { cholesky_.solve(r, z); };
  return projected_cg(g, factored_null_basis_, inverse, options_.reuse_tolerance, reuse_budget(),
                      options_.reuse_check_from, d)
      .converged;
}

template <int D>
void FactoredPreconditioner<D>::solve_by_multigrid(const Eigen::VectorXd& g, Eigen::VectorXd* d) {
  const auto inverse = [this](const Eigen::VectorXd& r, Eigen::VectorXd* z) { multigrid_.apply(r, z); };
  if (multigrid_.ready()) {
    // A constant P keeps its hierarchy; otherwise the old one serves while it
    // costs less than a new setup (module comment).
    const int budget = fixed_system()
                           ? options_.amg_max_cg
                           : std::min(options_.amg_max_cg, fresh_multigrid_iterations_ + options_.amg_setup_cycles);
    const CgOutcome reused =
        projected_cg(g, multigrid_null_basis_, inverse, options_.amg_tolerance, budget, fixed_system() ? 0 : 2, d);
    if (reused.converged || fixed_system()) {
      ++statistics_.reused_solves;
      return;
    }
  }
  multigrid_.setup(system(), D);
  multigrid_null_basis_ = null_basis_;
  ++statistics_.multigrid_setups;
  fresh_multigrid_iterations_ =
      projected_cg(g, multigrid_null_basis_, inverse, options_.amg_tolerance, options_.amg_max_cg, 0, d).iterations;
}

template <int D>
typename FactoredPreconditioner<D>::CgOutcome FactoredPreconditioner<D>::projected_cg(
    const Eigen::VectorXd& g, const ComponentMotions& built_null_basis, const Inverse& inverse, double tolerance,
    int max_iterations, int give_up_from, Eigen::VectorXd* d) {
  // CG on A = P(x) + eps I restricted to the complement of the current null
  // space N, with the symmetric PSD preconditioner
  //   M^-1 = P_N P_N' Minv P_N' P_N,
  // where Minv is `inverse` (built from an older matrix P'), N' the null
  // space when it was built and P_X the orthogonal projector onto the
  // complement of X.
  const auto project = [](const ComponentMotions& motions, Eigen::VectorXd& v) { motions.project_out(&v); };
  const auto A = system().template selfadjointView<Eigen::Upper>();
  Eigen::VectorXd projected;  // the residual projected, kept to be reused
  const auto precondition = [&](const Eigen::VectorXd& r, Eigen::VectorXd* z) {
    projected = r;
    project(null_basis_, projected);
    project(built_null_basis, projected);
    inverse(projected, z);
    project(built_null_basis, *z);
    project(null_basis_, *z);
  };
  CgOutcome outcome;
  Eigen::VectorXd r = g;
  project(null_basis_, r);
  const double target = tolerance * g.norm();
  const double initial_residual = r.norm();
  d->setZero(g.size());
  Eigen::VectorXd z, p, q;
  precondition(r, &z);
  p = z;
  double rz = r.dot(z);
  if (!(rz > 0)) return outcome;  // d = 0: no direction from a preconditioner that is not positive definite here
  for (int k = 1; k <= max_iterations; ++k) {
    ++statistics_.cg_iterations;
    outcome.iterations = k;
    q.noalias() = A * p;
    const double curvature = p.dot(q);
    if (!(curvature > 0)) break;
    const double alpha = rz / curvature;
    *d += alpha * p;
    r -= alpha * q;
    const double residual = r.norm();
    if (residual <= target) {
      outcome.converged = true;
      break;
    }
    // Give up early when the mean contraction so far, continued to the last
    // allowed iteration, would still miss the target by a wide margin.
    if (give_up_from > 0 && k >= give_up_from && k < max_iterations) {
      const double rate = std::pow(residual / initial_residual, 1.0 / k);
      if (residual * std::pow(rate, max_iterations - k) > 3 * target) break;
    }
    precondition(r, &z);
    const double rz_next = r.dot(z);
    if (!(rz_next > 0)) break;  // the preconditioner is not positive definite here
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  project(null_basis_, *d);
  return outcome;
}

template <int D>
void FactoredPreconditioner<D>::solve_by_conjugate_gradients(const Eigen::VectorXd& g, Eigen::VectorXd* d) {
  // Eigen's CG reads only the upper triangle; Jacobi preconditioning.
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Upper> cg;
  cg.setTolerance(options_.cg_tolerance);
  cg.setMaxIterations(options_.cg_max_iterations);
  cg.compute(system());
  Eigen::VectorXd rhs = g;
  null_basis_.project_out(&rhs);
  *d = cg.solve(rhs);
  null_basis_.project_out(d);
  ++statistics_.cg_solves;
  statistics_.cg_iterations += static_cast<int>(cg.iterations());
}

template class FactoredPreconditioner<2>;
template class FactoredPreconditioner<3>;

}  // namespace akvf
