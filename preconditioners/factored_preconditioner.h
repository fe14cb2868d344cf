#pragma once
// Shared machinery of the preconditioners that solve with a sparse SPD
// matrix P(x) assembled per triangle (AKVF, projected Newton, Laplacian):
// P + eps I factored by CHOLMOD (symbolic analysis once), the known null
// space projected out of every direction, and optional factorization reuse
// through conjugate gradients.
//
// Null space. P(x) may be singular along motions that do not change the
// energy (rigid motions for the Killing operator, translations for the
// Laplacian). We factor P + eps I with eps = tikhonov * mean(diag P) and
// project those motions out of the solution (§5.1). For a gradient
// orthogonal to them (the gradient of every rigid-invariant energy is) this
// is P^+ g (the paper's pseudoinverse, §4.2) up to a relative eps / lambda
// in each eigen-direction of P with eigenvalue lambda; the shift keeps a
// plain supernodal Cholesky (no pivoting, reusable analysis) well defined,
// and the projection removes what the shifted solve lets through.
//
// The shift's size. It only has to outweigh rounding along the null
// directions: Cholesky's backward error there is about u * |P| times a
// factor that grows with the factor's column counts (u = 1.1e-16), so
// tikhonov = 1e-12 leaves a margin of 10^4 over u. A larger shift is not
// harmless: it damps every direction whose eigenvalue is not far above it.
// Long thin regions bend with eigenvalues of K below 1e-8 * mean(diag K):
// a shift of 1e-8 makes the bending of hilbert_b (a strip folded into a
// Hilbert curve) converge linearly, 29 AKVF iterations to the gradient
// tolerance instead of 15. Should rounding still tip
// a pivot below zero, the factorization is retried with a shift 100 times
// larger, up to max_tikhonov (kept for the later factorizations); a matrix
// that fails even then is not positive semidefinite, and the error stands.
// The iterative solves (multigrid, Jacobi CG) keep iterative_tikhonov = 1e-8:
// stopped at a relative residual of 1e-2, they leave the softest modes
// unresolved whatever the shift, and a smaller one only slows their CG
// (hilbert_b with multigrid: 19432 CG iterations in 70 AKVF iterations
// with 1e-12 against 7851 in 40).
//
// Reuse (tau > 0). Before factoring P(x), try CG on P(x) d = g preconditioned
// by the last factor, projected so that neither the old factor's response to
// its own null space nor the current null space enters the iterates; accept
// when ||P d - g|| <= tau ||g|| within max_cg iterations (a CG iterate is
// always a descent direction: g^T d = d^T P d > 0), else factor and skip
// further attempts for 1, 2, 4, ... iterations after consecutive failures.
// With reuse_cg_flops_per_entry, the cost of one CG iteration in flops per
// entry of the factor, a reuse gets at most the iterations its factor's
// flops per entry pay for (floor(flops per entry / that), at most max_cg):
// past them it costs more than factoring anew. Below two none is tried: the
// first also pays for preparing the factor (catalog.cpp).
// An attempt is abandoned as soon as its mean residual contraction, continued
// to max_cg, would miss tau by more than 3x (that saves most of the cost of
// a failed attempt; on horse_b it turns 1.05 s into 1.0 s), checked from CG
// iteration reuse_check_from on. From the second by default; akvf-newton
// checks from the first: an earlier factor that serves is close to an exact
// inverse, and its first iteration already contracts the residual by about
// what the tolerance asks of every iteration, while one that fails mostly
// leaves it where it was (at 1.27 M vertices a CG iteration costs a fifth of
// a factorization). The paper's AKVF keeps the second: on camelhead one of
// its reuses contracts less at first and converges, and checking from the
// first took it from 82 to 86 iterations.
// With reuse_in_single_precision the earlier factor is rounded to single
// precision in place before its first reuse (SparseCholesky::
// round_factor_to_single): its solves, most of a CG iteration's cost and
// bound by memory bandwidth, read half the bytes (horse_b: about 0.4 of a
// factorization per CG iteration instead of 0.6), and a factorization
// brings it back to double. CG then solves K(x) d = g with a preconditioner
// whose L carries a relative 6e-8 per entry, far below tau, so the
// directions of akvf-newton's AKVF phase, the far phase, keep their
// iteration counts. Near a minimum the soft modes of K + eps I (eps a
// relative 1e-12) lie below that rounding, and the paper's AKVF taken to
// a gradient of 1e-6 stalled at 5e-6 on horse_b; so only that phase uses it.
//
// Algebraic multigrid (linear_solver = kAmg). Instead of a factorization,
// hypre's BoomerAMG builds a hierarchy of P(x) (solvers/algebraic_multigrid.h)
// and CG preconditioned by one V-cycle solves to amg_tolerance, with the null
// space projected as above. The hierarchy is reused at later iterations as a
// factor is: CG on the new P(x) with the old hierarchy, accepted if it
// converges within the iterations a fresh hierarchy took plus
// amg_setup_cycles (the setup costs about that many CG iterations, measured
// with akvf_benchmarks), else a new hierarchy is built. A solve that does
// not reach the tolerance within amg_max_cg iterations still gives a descent
// direction (its last CG iterate).
//
// Automatic choice (linear_solver = kAuto). CHOLMOD was the faster solver at
// every size measured on the 2-core machine (up to 10.2 M
// faces), so the only reason to leave it is memory: before the first
// factorization the symbolic analysis tells the factor's size, and if it
// exceeds auto_factor_bytes (default half the physical memory: the rest of a
// run took 0.75 to 0.8 times as much again as its factor, measured at 2.5 M
// and 10.2 M faces, so the whole run then stays within about 90 % of the
// memory) the multigrid path is taken instead, when this build has it.
#include <functional>
#include <memory>
#include <string>

#include "akvf/choices.h"
#include "akvf/mesh_objective.h"
#include "akvf/motion_bases.h"
#include "akvf/preconditioner.h"
#include "framework/optimization/element_matrix.h"
#include "preconditioners/backoff.h"
#include "preconditioners/contact_curvature.h"
#include "solvers/algebraic_multigrid.h"
#include "solvers/sparse_cholesky.h"
#include "solvers/symbolic_analysis_cache.h"

namespace akvf {

struct FactorOptions {
  LinearSolver linear_solver = LinearSolver::kCholmod;
  // kAuto: the largest factor (bytes) CHOLMOD may build; 0 = half the
  // physical memory (module comment).
  double auto_factor_bytes = 0;
  double amg_tolerance = 1e-2;  // relative residual of the multigrid-preconditioned CG
  int amg_max_cg = 200;
  // A hierarchy's setup in CG iterations, the reuse budget's slack: a setup
  // measured 22-25 V-cycles on K of horse_b and horse_b x16, and a CG
  // iteration is a cycle plus a product with P.
  int amg_setup_cycles = 20;
  double tikhonov = 1e-12;           // shift relative to mean(diag P) (module comment)
  double max_tikhonov = 1e-4;        // largest relative shift the retries reach
  double iterative_tikhonov = 1e-8;  // the relative shift of the multigrid and Jacobi CG solves
  double absolute_shift = 0;         // added to the relative shift: c of K + c I (§6.2 uses 1e-4)
  double reuse_tolerance = 0;        // tau; 0 factors at every update
  int reuse_max_cg = 8;
  int reuse_check_from = 2;  // the first CG iteration at which a reuse may be abandoned (module comment)
  // > 0: one reuse CG iteration costs about this many flops per entry of
  // the factor, and a reuse gets at most the CG iterations a factorization
  // costs (module comment); 0: reuse_max_cg, whatever the factor.
  double reuse_cg_flops_per_entry = 0;
  // Reuse with the earlier factor rounded to single precision (module comment).
  bool reuse_in_single_precision = false;
  // > 0: never factor; solve (P + shift) d = g by Jacobi-preconditioned
  // conjugate gradients to this relative residual (§6.2 uses 1 %), at most
  // cg_max_iterations iterations (the last iterate is still a descent direction).
  double cg_tolerance = 0;
  int cg_max_iterations = 1000;
  // Empty, or one value per dof added to P's diagonal: the Hessian of a
  // quadratic term of the problem that P should include (soft positional
  // constraints: 2 w on the constrained coordinates).
  Eigen::VectorXd extra_diagonal;
  // Set: analyses of sparsity patterns are taken from and added to it, so
  // repeated solves on one mesh analyze once (symbolic_analysis_cache.h).
  std::shared_ptr<SymbolicAnalysisCache> analysis_cache;
  // Set: the fill-reducing ordering of the mesh's vertices (computed once
  // for the mesh's matrices, solvers/fill_reducing_ordering.h), which the
  // analyses use instead of ordering P's pattern themselves.
  std::shared_ptr<const BlockOrdering> vertex_ordering;
  // Set (2D, global injectivity): the boundary barrier's curvature C(x),
  // added to P (contact_curvature.h); P + C is what is factored and solved.
  std::shared_ptr<ContactCurvature> contact_curvature;
};

// Default options with an absolute Tikhonov shift c (P + c I).
inline FactorOptions shifted_factor_options(double absolute_shift) {
  FactorOptions options;
  options.absolute_shift = absolute_shift;
  return options;
}

using FactorStatistics = PreconditionerStatistics;

template <int D>
class FactoredPreconditioner : public Preconditioner {
 public:
  void update(const OptimizationState& state) final;
  void apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) final;
  std::string report() const override;

  using Matrix = ElementMatrix<D, D + 1>;
  const Matrix& matrix() const { return matrix_; }
  // Before this preconditioner's first update: takes `previous`'s symbolic
  // analysis (and the memory of its factor, which the next factorization
  // overwrites) and its choice of linear solver. P must be on previous's
  // sparsity pattern (built with its matrix as `same_elements`). akvf-newton
  // hands AKVF's over at the switch, where AKVF is released.
  void take_over_factorization(FactoredPreconditioner& previous);
  // For a preconditioner about to be released: its matrix's storage, for a
  // successor on the same elements (ElementMatrix::taking_storage_of; this
  // one keeps no values and must not be updated again). Call before the
  // successor's take_over_factorization.
  Matrix hand_over_matrix() { return Matrix::taking_storage_of(&matrix_); }
  PreconditionerStatistics statistics() const final { return statistics_; }
  // The CG iterations a reuse of the last factor may take: reuse_max_cg, or
  // fewer by FactorOptions::reuse_cg_flops_per_entry (module comment).
  int reuse_budget() const;

 protected:
  //   elements  #E by D + 1 (faces or tets)
  FactoredPreconditioner(const Eigen::MatrixXi& elements, int num_vertices, FactorOptions options);
  // On the objective's elements, with the Hessian diagonal of the terms the
  // problem adds to it (MeshObjective::added_hessian_diagonal) as the
  // extra diagonal, unless `options` already has one.
  FactoredPreconditioner(const MeshObjective<D>& objective, FactorOptions options);
  // The same, with P on the sparsity pattern of `same_elements`, a matrix
  // already built on the objective's elements (shared, not rebuilt).
  FactoredPreconditioner(const MeshObjective<D>& objective, FactorOptions options, const Matrix& same_elements);
  // The same with `matrix`, on the objective's elements (hand_over_matrix).
  FactoredPreconditioner(const MeshObjective<D>& objective, FactorOptions options, Matrix&& matrix);

  // True if P's systems are solved by a CHOLMOD factorization (not by
  // multigrid or Jacobi CG): the factorization tells whether P is positive
  // definite. Decided by the time assemble() is called.
  bool solves_by_factorization() const {
    return options_.linear_solver == LinearSolver::kCholmod && options_.cg_tolerance <= 0;
  }
  // The vertices of each connected component when the mesh has several (the
  // charts of a cut mesh), else null.
  const std::vector<std::vector<int>>* component_vertices() const { return component_vertices_.get(); }
  // How the barrier's terms enter C (FactorOptions::contact_curvature).
  virtual ContactModel contact_model() const { return ContactModel::kGaussNewton; }
  // The barrier's curvature added to P, or null (FactorOptions::contact_curvature).
  const ContactCurvature* contact_curvature() const { return options_.contact_curvature.get(); }
  // C(x) again, by contact_model(): for a subclass whose model changed
  // after update() computed C (in assemble() or reassemble_semidefinite()).
  void refresh_contact(const Eigen::VectorXd& x) {
    if (!options_.contact_curvature) return;
    contact_ = options_.contact_curvature->at(x, contact_model());
    system_current_ = false;
  }
  // P's extra diagonal (FactorOptions::extra_diagonal as used).
  const Eigen::VectorXd& extra_diagonal() const { return options_.extra_diagonal; }

  // Fills matrix with P(x) (without the shift).
  virtual void assemble(const OptimizationState& state, Matrix* matrix) = 0;
  // Orthonormal basis (D|V| by k, k may be 0) of the motions to project out at x.
  virtual Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const = 0;
  // True if P does not depend on x: assembled and factored once.
  virtual bool is_constant() const { return false; }
  // Called when the assembled P turns out not to be positive definite (the
  // factorization fails) or gives no descent direction: a subclass whose
  // P may be indefinite by design (the exact Hessian) fills `matrix` with a
  // positive semidefinite P at the same x, without the shift, and returns
  // true; the default returns false, and the shift is raised instead.
  virtual bool reassemble_semidefinite(Matrix*) { return false; }

 private:
  FactoredPreconditioner(const Eigen::MatrixXi& elements, int num_vertices, FactorOptions options, Matrix matrix);
  void analyze();
  // The matrix solved: P with its shift, plus C(x) when the barrier's
  // curvature is included (FactorOptions::contact_curvature).
  const Eigen::SparseMatrix<double>& system();
  // True if the solved matrix does not depend on x: a constant P and no C.
  bool fixed_system() const { return is_constant() && !options_.contact_curvature; }
  // Adds the Tikhonov shift and the extra diagonal to the assembled P.
  void add_shift();
  // Whether a reuse is tried: always without a cost per CG iteration, else
  // when its budget holds two iterations (module comment).
  bool reuse_may_pay() const { return options_.reuse_cg_flops_per_entry <= 0 || reuse_budget() >= 2; }
  // Factors the assembled matrix; when it is not positive definite, raises
  // the shift (module comment) and retries.
  void factorize_current();
  // kAuto: CHOLMOD or multigrid, from the analysis (module comment).
  void choose_linear_solver();
  void solve_by_conjugate_gradients(const Eigen::VectorXd& g, Eigen::VectorXd* d);
  bool solve_with_previous_factor(const Eigen::VectorXd& g, Eigen::VectorXd* d);
  void solve_by_multigrid(const Eigen::VectorXd& g, Eigen::VectorXd* d);
  // CG on (P(x) + shift) d = g in the complement of the current null space,
  // preconditioned by `inverse` (an older factor or hierarchy, built when
  // the null space was `built_null_basis`), to tolerance * |g| within
  // max_iterations; from iteration give_up_from on (0: never) it stops once
  // its mean contraction would miss the tolerance by more than 3x. d is the
  // last iterate.
  struct CgOutcome {
    bool converged = false;
    int iterations = 0;
  };
  using Inverse = std::function<void(const Eigen::VectorXd&, Eigen::VectorXd*)>;
  CgOutcome projected_cg(const Eigen::VectorXd& g, const ComponentMotions& built_null_basis, const Inverse& inverse,
                         double tolerance, int max_iterations, int give_up_from, Eigen::VectorXd* d);

  FactorOptions options_;
  Matrix matrix_;
  Eigen::SparseMatrix<double> contact_;  // C at the last update
  Eigen::SparseMatrix<double> system_;   // P + C, when C is included
  bool system_current_ = false;          // system_ holds the current P + C
  // Where each nonzero of P and of C lands in system_, for C's pattern of
  // this version and P's of this many nonzeros (-1: not built).
  std::vector<int> system_slot_of_p_, system_slot_of_c_;
  int system_contact_version_ = -1;
  Eigen::Index system_p_nonzeros_ = -1;
  int analyzed_contact_version_ = 0;  // C's pattern when cholesky_ was analyzed
  SparseCholesky cholesky_;
  AlgebraicMultigrid multigrid_;
  ComponentMotions multigrid_null_basis_;  // at the hierarchy's setup
  int fresh_multigrid_iterations_ = 0;     // CG iterations of the last solve with a new hierarchy
  // Vertices of each connected component, if there are several (the charts
  // of a cut mesh): null_space() applies to each on its own.
  std::shared_ptr<const std::vector<std::vector<int>>> component_vertices_;
  ComponentMotions null_basis_;           // at the current x
  ComponentMotions factored_null_basis_;  // at the last factorization
  bool factored_ = false;                 // a factor exists (from any earlier update)
  bool factor_is_current_ = false;
  Backoff reuse_backoff_;    // the updates that factor without trying a reuse
  double relative_shift_;    // eps / mean(diag P): tikhonov, raised by retries
  int shift_increases_ = 0;  // factorizations retried with a larger shift
  FactorStatistics statistics_;
};

using FactoredPreconditioner2D = FactoredPreconditioner<2>;
using FactoredPreconditioner3D = FactoredPreconditioner<3>;

}  // namespace akvf
