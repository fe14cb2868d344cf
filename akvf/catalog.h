#pragma once
// The registries of everything a user can pick by name: energies,
// preconditioners and line searches. This is the one place that knows all
// built-in implementations (the composition root); the libraries know only
// interfaces. User code adds its own through the mutable_ accessors.
#include <memory>

#include "akvf/choices.h"
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
inline constexpr const char* kLbfgsMethod = "lbfgs";
// (name, one-line description) of each solver (choice_words(Solver)).
const std::vector<std::pair<std::string, std::string>>& solvers();

// OptionsError listing every valid --precond name (and the alias lbfgs) when
// `name` is none.
void require_method(const std::string& name);

// The registry tag of preconditioners that AQP's momentum accompanies by
// default (the Laplacian, as AQP pairs them).
inline constexpr const char* kMomentumByDefault = "momentum-by-default";

// The registry tag of 2D preconditioners that local Newton sweeps follow by
// default (--local-sweep auto; the default method, akvf-newton).
inline constexpr const char* kSweepsByDefault = "sweeps-by-default";

// The registry tag of 2D energies whose density grows without bound as
// det J falls to 0 (a barrier at collapse over its whole range): the local
// Newton sweeps' premise (local_newton_sweep.h), so --local-sweep auto
// sweeps only for them. ARAP's barrier acts only below 1e-3 of the rest
// area. A user energy carries it when registered with it (akvf/extend.h).
inline constexpr const char* kCollapseBarrier = "collapse-barrier";

// OptimizerOptions::acceleration_eta for an acceleration mode: kAuto turns
// AQP's momentum (eta = 100) on for preconditioners tagged
// kMomentumByDefault, kOn and kOff force it.
double acceleration_eta(Acceleration mode, bool momentum_by_default);

// The line search settings of a run: with AQP's momentum no parabola is
// fitted (LineSearchSettings::fit_parabola). Its momentum is the last step,
// x_k - x_{k-1}, as backtracking alone makes it (Kovalsky et al. 2016); a
// step shortened to the parabola's minimizer damps it
// (docs/notes/2026-11-30-rounding-batch.md).
LineSearchSettings line_search_settings(LineSearchSettings settings, double acceleration_eta);

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
