#pragma once
// The registries of everything a user can pick by name: energies,
// preconditioners and line searches. This is the one place that knows all
// built-in implementations (the composition root); the libraries know only
// interfaces. User code adds its own through the mutable_ accessors.
#include <memory>

#include "akvf/distortion_density.h"
#include "akvf/line_search.h"
#include "akvf/mesh_objective.h"
#include "akvf/preconditioner.h"
#include "akvf/registry.h"

namespace akvf {

// Options of the energies that have them.
struct EnergySettings {
  double exponent = 1.0;  // k of the exponential energies
};

using DensityRegistry2D = Registry<DistortionDensity2D, const EnergySettings&>;
// The options of the built-in preconditioners (akvf/internal/preconditioner_settings.h);
// a registered preconditioner receives them and may ignore them.
struct PreconditionerSettings2D;
struct PreconditionerSettings3D;
// The settings the built-in preconditioners take by default, to create one
// by name outside a run: preconditioners_3d().create("newton", objective,
// default_preconditioner_settings_3d()).
const PreconditionerSettings2D& default_preconditioner_settings_2d();
const PreconditionerSettings3D& default_preconditioner_settings_3d();

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

// The registry tag of preconditioners that AQP's momentum accompanies by
// default (the Laplacian, as AQP pairs them).
inline constexpr const char* kMomentumByDefault = "momentum-by-default";

// OptimizerOptions::acceleration_eta for an --acceleration mode: "auto" turns
// AQP's momentum (eta = 100) on for preconditioners tagged
// kMomentumByDefault, "on" and "off" force it. OptionsError for any other mode.
double acceleration_eta(const std::string& mode, bool momentum_by_default);

using DensityRegistry3D = Registry<DistortionDensity<3>, const EnergySettings&>;
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
