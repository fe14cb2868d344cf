#pragma once
// A preconditioner P(x) for the optimizer's search direction d = -P^-1 grad E.
// update() builds and factors P at the current iterate; apply() solves.
#include <Eigen/Core>
#include <string>

namespace akvf {

struct OptimizationState {
  const Eigen::VectorXd& x;
  const Eigen::VectorXd& gradient;
  double energy;
  int iteration;
  // The previous iteration's accepted step and its flip-free bound alpha_max
  // (0 before the first step).
  double previous_step = 0;
  double previous_max_step = 0;
  // Whether that step's line search rejected a longer trial first.
  bool previous_backtracked = false;
};

// The work a preconditioner did, as numbers (all zero for those that do no
// linear algebra of their own).
struct PreconditionerStatistics {
  int factorizations = 0;     // numeric Cholesky factorizations
  int cg_solves = 0;          // directions from plain (Jacobi) CG
  int reused_solves = 0;      // directions from CG with an older factorization
  int cg_iterations = 0;      // over both kinds of CG solve
  int symbolic_analyses = 0;  // sparsity patterns analyzed (not taken from an earlier solve)
  int multigrid_setups = 0;   // algebraic multigrid hierarchies built (--linear-solver amg)
};

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  virtual std::string name() const = 0;
  // Build and factor P(x). Called once per iteration, before apply().
  virtual void update(const OptimizationState& state) = 0;
  // result = P^-1 gradient (the optimizer searches along its negative).
  virtual void apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) = 0;
  // A line for reports on the work done so far ("12 factorizations"), or "".
  virtual std::string report() const { return ""; }
  virtual PreconditionerStatistics statistics() const { return {}; }
  // Whether P carries each element's own curvature (the energy's projected
  // Hessian, as Newton's), so that its step already takes what a local
  // Newton step of one vertex would add (ParameterizeOptions::local_sweep
  // skips the sweep after it).
  virtual bool has_element_curvature() const { return false; }
};

}  // namespace akvf
