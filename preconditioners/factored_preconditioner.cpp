#include "preconditioners/factored_preconditioner.h"

#include <Eigen/IterativeLinearSolvers>
#include <cmath>

#include "framework/mesh/mesh_topology.h"
#include "framework/process/error.h"

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
                             with_added_diagonal(std::move(options), objective.added_hessian_diagonal())) {}

template <int D>
FactoredPreconditioner<D>::FactoredPreconditioner(const Eigen::MatrixXi& elements, int num_vertices,
                                                  FactorOptions options)
    : options_(options), matrix_(elements, num_vertices) {
  if (!(options_.tikhonov > 0)) throw OptionsError("Tikhonov shift must be > 0");
  if (!(options_.absolute_shift >= 0)) throw OptionsError("absolute Tikhonov shift must be >= 0");
  if (!(options_.reuse_tolerance >= 0 && options_.reuse_tolerance < 1))
    throw OptionsError("factorization reuse tolerance must be in [0, 1)");
  if (!(options_.cg_tolerance >= 0 && options_.cg_tolerance < 1)) throw OptionsError("CG tolerance must be in [0, 1)");
  if (options_.cg_max_iterations < 1) throw OptionsError("CG needs at least one iteration");
  if (options_.reuse_max_cg < 1) throw OptionsError("factorization reuse needs at least one CG iteration");
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
  if (statistics_.cg_solves > 0)
    return std::to_string(statistics_.cg_solves) + " CG solves (" + std::to_string(statistics_.cg_iterations) +
           " iterations), no factorization";
  return std::to_string(statistics_.factorizations) + " factorizations, " + std::to_string(statistics_.reused_solves) +
         " solves with an earlier factor (" + std::to_string(statistics_.cg_iterations) + " CG iterations)";
}

template <int D>
void FactoredPreconditioner<D>::update(const OptimizationState& state) {
  null_basis_ = component_vertices_ ? ComponentMotions(D, component_vertices_, state.x,
                                                       [this](const Eigen::VectorXd& part) { return null_space(part); })
                                    : ComponentMotions(null_space(state.x));
  // P(x) plus the Tikhonov shift: relative to mean(diag P), plus the absolute c.
  const auto assemble_shifted = [&] {
    assemble(state, &matrix_);
    matrix_.add_to_diagonal(options_.tikhonov * matrix_.mean_diagonal() + options_.absolute_shift);
    if (options_.extra_diagonal.size() != 0) matrix_.add_to_diagonal(options_.extra_diagonal);
  };
  if (is_constant()) {
    if (!cholesky_.analyzed()) {
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
  if (options_.reuse_tolerance <= 0 || !cholesky_.analyzed()) {
    factorize_current();
  } else if (skip_reuse_ > 0) {
    --skip_reuse_;
    factorize_current();
  }
}

template <int D>
void FactoredPreconditioner<D>::factorize_current() {
  if (!cholesky_.analyzed()) {
    const bool computed = options_.analysis_cache ? options_.analysis_cache->analyze(matrix_.upper(), D, &cholesky_)
                                                  : (cholesky_.analyze(matrix_.upper(), D), true);
    if (computed) ++statistics_.symbolic_analyses;
  }
  cholesky_.factorize(matrix_.upper());
  factored_null_basis_ = null_basis_;
  factor_is_current_ = true;
  ++statistics_.factorizations;
}

template <int D>
void FactoredPreconditioner<D>::apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) {
  if (options_.cg_tolerance > 0 && !is_constant()) {
    solve_by_conjugate_gradients(gradient, result);
    return;
  }
  if (!factor_is_current_) {
    if (solve_with_previous_factor(gradient, result)) {
      ++statistics_.reused_solves;
      failure_backoff_ = 1;
      return;
    }
    skip_reuse_ = failure_backoff_;
    failure_backoff_ *= 2;
    factorize_current();
  }
  cholesky_.solve(gradient, result);
  null_basis_.project_out(result);
}

template <int D>
bool FactoredPreconditioner<D>::solve_with_previous_factor(const Eigen::VectorXd& g, Eigen::VectorXd* d) {
  // CG on A = P(x) + eps I restricted to the complement of the current null
  // space N, with the symmetric PSD preconditioner
  //   M^-1 = P_N P_N' (P' + eps I)^-1 P_N' P_N,
  // where P' is the factored (older) matrix, N' its null space and P_X the
  // orthogonal projector onto the complement of X.
  const auto project = [](const ComponentMotions& motions, Eigen::VectorXd& v) { motions.project_out(&v); };
  const auto A = matrix_.upper().template selfadjointView<Eigen::Upper>();
  const auto precondition = [&](Eigen::VectorXd r, Eigen::VectorXd* z) {
    project(null_basis_, r);
    project(factored_null_basis_, r);
    cholesky_.solve(r, z);
    project(factored_null_basis_, *z);
    project(null_basis_, *z);
  };
  Eigen::VectorXd r = g;
  project(null_basis_, r);
  const double target = options_.reuse_tolerance * g.norm();
  const double initial_residual = r.norm();
  d->setZero(g.size());
  Eigen::VectorXd z, p, q;
  precondition(r, &z);
  p = z;
  double rz = r.dot(z);
  for (int k = 1; k <= options_.reuse_max_cg; ++k) {
    ++statistics_.cg_iterations;
    q = A * p;
    const double curvature = p.dot(q);
    if (!(curvature > 0)) return false;
    const double alpha = rz / curvature;
    *d += alpha * p;
    r -= alpha * q;
    const double residual = r.norm();
    if (residual <= target) {
      project(null_basis_, *d);
      return true;
    }
    // Give up early when the mean contraction so far, continued to the last
    // allowed iteration, would still miss the target by a wide margin.
    if (k >= 2 && k < options_.reuse_max_cg) {
      const double rate = std::pow(residual / initial_residual, 1.0 / k);
      if (residual * std::pow(rate, options_.reuse_max_cg - k) > 3 * target) return false;
    }
    precondition(r, &z);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  return false;
}

template <int D>
void FactoredPreconditioner<D>::solve_by_conjugate_gradients(const Eigen::VectorXd& g, Eigen::VectorXd* d) {
  // Eigen's CG reads only the upper triangle; Jacobi preconditioning.
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Upper> cg;
  cg.setTolerance(options_.cg_tolerance);
  cg.setMaxIterations(options_.cg_max_iterations);
  cg.compute(matrix_.upper());
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
