#pragma once
// The registries of everything a user can pick by name: energies,
// preconditioners and line searches. This is the one place that knows all
// built-in implementations (the composition root); the libraries know only
// interfaces. User code adds its own through the mutable_ accessors.
#include <memory>

#include "framework/optimization/distortion_density.h"
#include "framework/optimization/line_search.h"
#include "framework/optimization/mesh_objective.h"
#include "framework/optimization/preconditioner.h"
#include "framework/optimization/registry.h"
#include "preconditioners/akvf_preconditioner_2d.h"
#include "preconditioners/akvf_preconditioner_3d.h"
#include "preconditioners/newton_preconditioner.h"
#include "preconditioners/switching_preconditioner.h"

namespace akvf {

// Options of the energies that have them.
struct EnergySettings {
  double exponent = 1.0;  // k of the exponential energies
};

using DensityRegistry2D = Registry<DistortionDensity2D, const EnergySettings&>;
// Options of the preconditioners that have them, set from the command line.
struct PreconditionerSettings2D {
  AkvfOptions2D akvf;
  FactorOptions newton;  // factored every iteration unless reuse is set
  // The Newton phase of akvf-newton: reuses factorizations as AKVF does
  // (docs/performance.md, "Factorization reuse in the Newton phase").
  FactorOptions newton_phase = AkvfOptions2D{}.factor;
  FactorOptions laplacian;  // constant: factored once
  FactorOptions slim;       // factored every iteration unless reuse is set
  // When akvf-newton switches; its isometric step is the energy's (set by
  // the catalog), its backtracking factor the line search's.
  SwitchRule akvf_newton_switch;
  EigenvalueFilter newton_filter = EigenvalueFilter::kClamp;  // newton
  // akvf-newton's Newton phase: the exact Hessian while it is positive
  // definite (newton_preconditioner.h; docs/design.md says why).
  EigenvalueFilter newton_phase_filter = EigenvalueFilter::kExact;

  // Every factored preconditioner takes its symbolic analyses from `cache`.
  void share_analyses(const std::shared_ptr<SymbolicAnalysisCache>& cache) {
    for (FactorOptions* options : {&akvf.factor, &newton, &newton_phase, &laplacian, &slim})
      options->analysis_cache = cache;
  }
  // Every factored preconditioner solves with `solver`.
  void set_linear_solver(LinearSolver solver) {
    for (FactorOptions* options : {&akvf.factor, &newton, &newton_phase, &laplacian, &slim})
      options->linear_solver = solver;
  }
  // Every factored preconditioner's analysis eliminates the vertices in
  // `ordering` (the mesh's, computed once; null: each orders its own).
  void share_vertex_ordering(const std::shared_ptr<const BlockOrdering>& ordering) {
    for (FactorOptions* options : {&akvf.factor, &newton, &newton_phase, &laplacian, &slim})
      options->vertex_ordering = ordering;
  }
};

using PreconditionerRegistry2D = Registry<Preconditioner, const MeshObjective2D&, const PreconditionerSettings2D&>;
using LineSearchRegistry = Registry<LineSearch, const LineSearchSettings&>;

// The solvers of a parameterization (`--solver`): the preconditioned,
// flip-free descent of Algorithm 1 with any preconditioner, or L-BFGS through
// Ceres, which takes no preconditioner. `--precond lbfgs` is kept as an alias
// of `--solver lbfgs`.
inline constexpr const char* kDescentSolver = "descent";
inline constexpr const char* kLbfgsMethod = "lbfgs";
// (name, one-line description) of each solver.
const std::vector<std::pair<std::string, std::string>>& solvers();
// OptionsError listing the solvers when `name` is none.
void require_solver(const std::string& name);

// OptionsError listing every valid --precond name (and the alias lbfgs) when
// `name` is none.
void require_method(const std::string& name);

// --linear-solver: "cholmod" (sparse Cholesky), "amg" (CG with algebraic
// multigrid, solvers/algebraic_multigrid.h) or "auto": CHOLMOD unless its
// factor, known from the symbolic analysis, would take more than half the
// physical memory, then multigrid (LinearSolver::kAuto,
// preconditioners/factored_preconditioner.h; CHOLMOD when this build has no
// multigrid). OptionsError for any other name.
void require_linear_solver(const std::string& name);
LinearSolver linear_solver_for(const std::string& name);

// The registry tag of preconditioners that AQP's momentum accompanies by
// default (the Laplacian, as AQP pairs them).
inline constexpr const char* kMomentumByDefault = "momentum-by-default";

// OptimizerOptions::acceleration_eta for an --acceleration mode: "auto" turns
// AQP's momentum (eta = 100) on for preconditioners tagged
// kMomentumByDefault, "on" and "off" force it. OptionsError for any other mode.
double acceleration_eta(const std::string& mode, bool momentum_by_default);

using DensityRegistry3D = Registry<DistortionDensity<3>, const EnergySettings&>;
// Options of the 3D preconditioners. In deformation, newton, laplacian and
// slim carry the constraint term's Hessian in their extra_diagonal.
struct PreconditionerSettings3D {
  AkvfOptions3D akvf;
  FactorOptions newton = shifted_factor_options(1e-4);
  FactorOptions laplacian = shifted_factor_options(1e-4);
  FactorOptions slim = shifted_factor_options(1e-4);
  SwitchRule akvf_newton_switch;  // as in 2D
  EigenvalueFilter newton_filter = EigenvalueFilter::kClamp;
  EigenvalueFilter newton_phase_filter = EigenvalueFilter::kExact;  // as in 2D

  // Jacobi-CG to this relative residual instead of factoring, for every
  // matrix that changes per iteration (akvf, newton, slim; the Laplacian is
  // factored once). 0 = factor.
  void set_cg_tolerance(double tolerance) {
    for (FactorOptions* options : {&akvf.factor, &newton, &slim}) options->cg_tolerance = tolerance;
  }
  // Every factored preconditioner takes its symbolic analyses from `cache`.
  void share_analyses(const std::shared_ptr<SymbolicAnalysisCache>& cache) {
    for (FactorOptions* options : {&akvf.factor, &newton, &laplacian, &slim}) options->analysis_cache = cache;
  }
  // Every factored preconditioner solves with `solver`.
  void set_linear_solver(LinearSolver solver) {
    for (FactorOptions* options : {&akvf.factor, &newton, &laplacian, &slim}) options->linear_solver = solver;
  }
};
using PreconditionerRegistry3D = Registry<Preconditioner, const MeshObjective3D&, const PreconditionerSettings3D&>;

const DensityRegistry2D& energies_2d();
const DensityRegistry3D& energies_3d();
const PreconditionerRegistry3D& preconditioners_3d();
const PreconditionerRegistry2D& preconditioners_2d();
const LineSearchRegistry& line_searches();

// The same registries for adding user-defined parts by name (registry.h:
// add() refuses a name that is taken). Register before runs start: a
// registry is not guarded against concurrent registration and use.
DensityRegistry2D& mutable_energies_2d();
DensityRegistry3D& mutable_energies_3d();
PreconditionerRegistry3D& mutable_preconditioners_3d();
PreconditionerRegistry2D& mutable_preconditioners_2d();
LineSearchRegistry& mutable_line_searches();

}  // namespace akvf
