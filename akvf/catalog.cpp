#include "akvf/catalog.h"
#include "akvf/internal/preconditioner_settings.h"

#include "akvf/backtracking_line_search.h"
#include "energies/amips.h"
#include "energies/arap.h"
#include "energies/exp_symmetric_dirichlet.h"
#include "energies/mips.h"
#include "energies/symmetric_dirichlet.h"
#include "preconditioners/akvf_preconditioner_3d.h"
#include "preconditioners/energy_scale.h"
#include "preconditioners/identity_preconditioner.h"
#include "preconditioners/laplacian_preconditioner.h"
#include "preconditioners/newton_preconditioner.h"
#include "preconditioners/slim_preconditioner.h"
#include "preconditioners/switching_preconditioner.h"
#include "solvers/wolfe_bisection_line_search.h"

namespace akvf {

namespace {

// The options of akvf-newton's Newton phase: in 2D its own (it reuses
// factorizations as AKVF does: --newton-reuse auto), in 3D projected
// Newton's (AKVF does not reuse there).
const FactorOptions& newton_phase_options(const PreconditionerSettings2D& settings) { return settings.newton_phase; }
const FactorOptions& newton_phase_options(const PreconditionerSettings3D& settings) { return settings.newton; }

// The default's AKVF phase: in 2D it factors c K (akvf_preconditioner_2d.h),
// in 3D AKVF scales K by s_k, the energy's curvature along its last step
// (akvf_preconditioner_3d.h, s_1 = c), so that in both its Newton step at
// an isometry, the switch rule's unit (energy_scale.h,
// switching_preconditioner.h), is 1. In 2D the faces whose thinnest height
// the map stretched more than 100 times, where K holds below 1e-4 of the
// energy's curvature, carry that curvature too (akvf_preconditioner_2d.h):
// a round factor between ordinary distortion and the slivers of an input
// (docs/notes/2026-12-02-sliver-curvature.md has the stretches measured);
// it keeps K on compressed faces.
AkvfOptions2D far_phase(AkvfOptions2D options) {
  options.energy_scaling = true;
  options.sliver_stretch = 100;
  // K's stiffening under compression is Newton's phase to resolve here:
  // with the compression rule too, ARAP took more iterations on camelhead
  // (397 -> 455) and fewer on cow_b (142 -> 106).
  options.compression_stiffness.reset();
  return options;
}
AkvfOptions3D far_phase(AkvfOptions3D options) { return options; }

SwitchRule akvf_switch_rule(const MeshObjective2D& objective, const PreconditionerSettings2D& settings) {
  SwitchRule rule = settings.akvf_newton_switch;
  rule.isometric_step = 1.0;
  rule.energy_lower_bound = objective.lower_bound();
  return rule;
}
SwitchRule akvf_switch_rule(const MeshObjective3D& objective, const PreconditionerSettings3D& settings) {
  SwitchRule rule = settings.akvf_newton_switch;
  rule.isometric_step =
      settings.akvf.secant_scaling ? 1.0 : isometric_newton_step(objective.density(), objective.rest().total_volume);
  rule.energy_lower_bound = objective.lower_bound();
  // Soft constraints: the run's energy is the objective's value plus theirs
  // (hard ones pin with the same diagonal but add no energy: share 0).
  if (objective.added_hessian_diagonal().size() != 0)
    rule.distortion_energy = [&objective](const Eigen::VectorXd& x) { return objective.value(x); };
  return rule;
}

// AKVF, then projected Newton on the same matrix pattern, and AKVF again if
// Newton's steps meet the flip-free bound (switching_preconditioner.h): each
// takes over the other's symbolic analysis and factor memory at a switch,
// where the other is released, so a switch costs no setup the pure methods
// do not pay before their start, and no second analysis or factor is kept.
// Both phases give up a failed factorization reuse after one CG iteration
// (factored_preconditioner.h, reuse_check_from); the AKVF phase reuses its
// factor rounded to single precision (reuse_in_single_precision), for at
// most the CG iterations a factorization costs (reuse_cg_flops_per_entry).
//
// What a CG iteration costs: a solve with the single-precision factor, a
// product with K, the projections and vector updates, about 1.5 solves
// (horse_b: 0.67, 0.33 and about 0.2 ms against a 0.80 ms solve;
// `akvf_benchmarks` Solve/single, SymmetricProduct, Solve). A factorization
// costs a solve per 11-13 of its flops per entry (camelhead at 175 flops
// per entry 14 solves, horse_b at 86 7-8: NumericFactorization). So a CG
// iteration costs about 20 flops per entry: horse_b's reuses get 4
// iterations, camelhead's the 8 of reuse_max_cg, and a factor below 40
// flops per entry (CHOLMOD's own supernodal switch) none (camel_b, cow_b,
// tricera_b, hilbert_b; hilbert_b's symmetric Dirichlet run took the same
// 15 iterations 8 % sooner without its reuses:
// docs/notes/2026-11-29-first-assembly-and-reuse.md). The far phase's
// steps move the map by much of its flip-free bound, and its reuses took
// 5-6 CG iterations on horse_b, more than the factorization they saved.
// The Newton phase keeps its reuses: the seam rounds start in it, and their
// globally injective end took other paths without them (cow_bunny_calf's
// optimizer time 1.86 -> 4.97 s; docs/notes/2026-11-28-divergence-weight.md).
constexpr double kReuseCgFlopsPerEntry = 20;

template <int D, class Akvf, class Settings>
std::unique_ptr<Preconditioner> akvf_then_newton(const MeshObjective<D>& objective, const Settings& settings) {
  FactorOptions newton = newton_phase_options(settings);
  newton.reuse_check_from = 1;
  const EigenvalueFilter filter = settings.newton_phase_filter;
  auto akvf_options = far_phase(settings.akvf);
  akvf_options.factor.reuse_check_from = 1;
  akvf_options.factor.reuse_cg_flops_per_entry = kReuseCgFlopsPerEntry;
  // The far phase: its reuses may precondition in single precision.
  akvf_options.factor.reuse_in_single_precision = true;
  auto factored = [](Preconditioner& current) -> FactoredPreconditioner<D>& {
    return dynamic_cast<FactoredPreconditioner<D>&>(current);
  };
  return std::make_unique<SwitchingPreconditioner>(
      "akvf-newton", std::make_unique<Akvf>(objective, akvf_options),
      [&objective, newton, filter, factored](Preconditioner& current, SwitchReason why) {
        FactoredPreconditioner<D>& akvf = factored(current);
        // AKVF is released right after: Newton takes its matrix's storage
        // (no copy: 0.9 GB at 10 M triangles) and its factorization.
        auto second = std::make_unique<NewtonPreconditioner<D>>(objective, akvf.hand_over_matrix(), newton,
                                                                default_newton_projection(D), filter);
        second->take_over_factorization(akvf);
        // The last step was AKVF's: Newton's model is untested, and where it
        // followed AKVF's unit step the exact Hessian was not positive
        // definite at MIPS's and ARAP's switches on every disk mesh tried.
        second->start_on_fallback();
        // The last step went 0.8 of the way to a collapse with the
        // constraints still far: the elements it compressed leave the
        // Hessian far from positive definite (switching_preconditioner.h).
        if (why == SwitchReason::kConstraintsFar) second->start_fallback_at_clamp();
        return std::unique_ptr<Preconditioner>(std::move(second));
      },
      akvf_switch_rule(objective, settings),
      [&objective, akvf_options, factored](Preconditioner& current, SwitchReason) {
        auto first = std::make_unique<Akvf>(objective, akvf_options);
        first->take_over_factorization(factored(current));
        return std::unique_ptr<Preconditioner>(std::move(first));
      });
}

}  // namespace

DensityRegistry2D& mutable_energies_2d() {
  static DensityRegistry2D registry = [] {
    DensityRegistry2D r("energy");
    r.add("symmetric-dirichlet", "|J|^2 + |J^-1|^2, Eq. (2); lower bound 4",
          [](const EnergySettings&) { return std::make_unique<SymmetricDirichlet2D>(); }, {kCollapseBarrier});
    r.add("arap",
          "|J - R(J)|^2, R the closest rotation, with a collapse barrier below 1e-3 of the rest area; lower bound 0",
          [](const EnergySettings&) { return std::make_unique<Arap2D>(); });
    r.add("mips", "conformal |J|^2 / det J; lower bound 2",
          [](const EnergySettings&) { return std::make_unique<Mips2D>(); }, {kCollapseBarrier});
    r.add("exp-symmetric-dirichlet", "exp(k (|J|^2 + |J^-1|^2)), k = --exponent; lower bound exp(4k)",
          [](const EnergySettings& e) { return std::make_unique<ExpSymmetricDirichlet2D>(e.exponent); },
          {kCollapseBarrier});
    r.add("amips", "exp(k (|J|^2 / (4 det J) + (det J + 1/det J) / 4)), k = --exponent; lower bound exp(k)",
          [](const EnergySettings& e) { return std::make_unique<Amips2D>(e.exponent); }, {kCollapseBarrier});
    return r;
  }();
  return registry;
}

DensityRegistry3D& mutable_energies_3d() {
  static DensityRegistry3D registry = [] {
    DensityRegistry3D r("3D energy");
    r.add("symmetric-dirichlet", "|J|^2 + |J^-1|^2 on tets; lower bound 6",
          [](const EnergySettings&) { return std::make_unique<SymmetricDirichlet3D>(); });
    r.add("arap", "|J - R(J)|^2 on tets, R the closest rotation (through the SVD); lower bound 0",
          [](const EnergySettings&) { return std::make_unique<Arap3D>(); });
    r.add("mips", "conformal |J|^2 / det(J)^(2/3) on tets; lower bound 3",
          [](const EnergySettings&) { return std::make_unique<Mips3D>(); });
    r.add("exp-symmetric-dirichlet", "exp(k (|J|^2 + |J^-1|^2)) on tets, k = --exponent; lower bound exp(6k)",
          [](const EnergySettings& e) { return std::make_unique<ExpSymmetricDirichlet3D>(e.exponent); });
    r.add("amips", "exp(k (|J|^2 / (6 det(J)^(2/3)) + (det J + 1/det J) / 4)) on tets, k = --exponent; bound exp(k)",
          [](const EnergySettings& e) { return std::make_unique<Amips3D>(e.exponent); });
    return r;
  }();
  return registry;
}

PreconditionerRegistry3D& mutable_preconditioners_3d() {
  static PreconditionerRegistry3D registry = [] {
    PreconditionerRegistry3D r("3D preconditioner");
    r.add("akvf", "s K(x) + c I + constraints' Hessian, K of Eq. (9)-(10), c = 1e-4 (Sec. 6.2), s secant scale",
          [](const MeshObjective3D& objective, const PreconditionerSettings3D& settings) {
            return std::make_unique<AkvfPreconditioner3D>(objective, settings.akvf);
          });
    r.add("newton", "projected Newton: tet Hessians clamped to PSD, plus the constraints' Hessian",
          [](const MeshObjective3D& objective, const PreconditionerSettings3D& settings) {
            return std::make_unique<NewtonPreconditioner3D>(objective, settings.newton, default_newton_projection(3),
                                                            settings.newton_filter);
          });
    r.add("akvf-newton",
          "AKVF while the flip-free bound sets the step, then Newton (the exact Hessian while it is positive "
          "definite, else projected) once the curvature does, AKVF's bound-held steps stall or a bound-held step "
          "leaves the soft constraints far, and AKVF again if Newton's steps close in on a "
          "collapse (preconditioners/switching_preconditioner.h)",
          [](const MeshObjective3D& objective, const PreconditionerSettings3D& settings) {
            return akvf_then_newton<3, AkvfPreconditioner3D>(objective, settings);
          });
    r.add("laplacian",
          "AQP proxy: the rest Laplacian per coordinate at the energy's scale, plus the constraints' Hessian",
          [](const MeshObjective3D& objective, const PreconditionerSettings3D& settings) {
            // L's quadratic form along a unit shear is |S|^2 = 2 (weights sum to 1).
            return std::make_unique<LaplacianPreconditioner3D>(objective, settings.laplacian, MotionProjection::kNone,
                                                               rest_shear_curvature(objective.density()) / 2);
          },
          {kMomentumByDefault});
    r.add("slim",
          "SLIM: reweighted ARAP proxy plus the constraints' Hessian (Rabinovich et al. 2017); for MIPS "
          "towards the nearest similarity, free along it",
          [](const MeshObjective3D& objective, const PreconditionerSettings3D& settings) {
            return std::make_unique<SlimPreconditioner3D>(objective, settings.slim);
          });
    r.add("identity", "no preconditioning: plain gradient descent",
          [](const MeshObjective3D&, const PreconditionerSettings3D&) {
            return std::make_unique<IdentityPreconditioner>();
          });
    return r;
  }();
  return registry;
}

PreconditionerRegistry2D& mutable_preconditioners_2d() {
  static PreconditionerRegistry2D registry = [] {
    PreconditionerRegistry2D r("preconditioner");
    r.add("akvf",
          "Killing operator K(x) of Eq. (5), area-scaled, CHOLMOD (the paper's method; for MIPS without the "
          "divergence term, which MIPS does not feel)",
          [](const MeshObjective2D& objective, const PreconditionerSettings2D& settings) {
            return std::make_unique<AkvfPreconditioner2D>(objective, settings.akvf);
          },
          {kTakesContactCurvature});
    r.add("newton", "projected Newton: element Hessians clamped to PSD, CHOLMOD",
          [](const MeshObjective2D& objective, const PreconditionerSettings2D& settings) {
            return std::make_unique<NewtonPreconditioner2D>(objective, settings.newton, default_newton_projection(2),
                                                            settings.newton_filter);
          },
          {kTakesContactCurvature});
    r.add("akvf-newton",
          "AKVF while the flip-free bound sets the step, then Newton (the exact Hessian while it is positive "
          "definite, else projected) once the curvature does or AKVF's bound-held steps stall, and AKVF again if "
          "Newton's steps close in on a "
          "collapse (preconditioners/switching_preconditioner.h)",
          [](const MeshObjective2D& objective, const PreconditionerSettings2D& settings) {
            return akvf_then_newton<2, AkvfPreconditioner2D>(objective, settings);
          },
          {kSweepsByDefault, kTakesContactCurvature});
    r.add("laplacian",
          "AQP proxy: cotangent Laplacian of the 3D mesh per coordinate, factored once; AQP momentum by default",
          [](const MeshObjective2D& objective, const PreconditionerSettings2D& settings) {
            return std::make_unique<LaplacianPreconditioner2D>(objective, settings.laplacian);
          },
          {kMomentumByDefault, kTakesContactCurvature});
    r.add("slim",
          "SLIM: reweighted ARAP proxy whose gradient is the energy's (Rabinovich et al. 2017); for MIPS "
          "towards the nearest similarity, free along it",
          [](const MeshObjective2D& objective, const PreconditionerSettings2D& settings) {
            return std::make_unique<SlimPreconditioner2D>(objective, settings.slim);
          },
          {kTakesContactCurvature});
    r.add("identity", "no preconditioning: plain gradient descent",
          [](const MeshObjective2D&, const PreconditionerSettings2D&) {
            return std::make_unique<IdentityPreconditioner>();
          });
    return r;
  }();
  return registry;
}

const std::vector<std::pair<std::string, std::string>>& solvers() {
  static const std::vector<std::pair<std::string, std::string>> list = {
      {choice_name(Solver::kDescent), "preconditioned flip-free descent (Algorithm 1) with --precond"},
      {choice_name(Solver::kLbfgs),
       "L-BFGS through Ceres' GradientProblemSolver (Smith & Schaefer 2015 style), no preconditioner"},
  };
  return list;
}

LinearSolver available_linear_solver(LinearSolver solver) {
  return solver == LinearSolver::kAuto && !AlgebraicMultigrid::available() ? LinearSolver::kCholmod : solver;
}

void require_method(const std::string& name) {
  if (name == kLbfgsMethod || preconditioners_2d().contains(name)) return;
  throw OptionsError("unknown preconditioner '" + name + "' (valid: " + preconditioners_2d().names() + ", " +
                     kLbfgsMethod + ")");
}

double acceleration_eta(Acceleration mode, bool momentum_by_default) {
  // AQP's acceleration parameter eta (theta = (1 - 1/sqrt(eta)) / (1 + 1/sqrt(eta)) = 0.82).
  constexpr double kAqpEta = 100;
  return mode == Acceleration::kOn || (mode == Acceleration::kAuto && momentum_by_default) ? kAqpEta : 0;
}

LineSearchSettings line_search_settings(LineSearchSettings settings, double acceleration_eta) {
  if (acceleration_eta > 0) settings.fit_parabola = false;
  return settings;
}

LineSearchRegistry& mutable_line_searches() {
  static LineSearchRegistry registry = [] {
    LineSearchRegistry r("line search");
    r.add("backtracking",
          "Armijo backtracking from min(1, 0.8 alpha_max), flip-free (Sec. 5.3), then the parabola's minimizer where "
          "the step overshot",
          [](const LineSearchSettings& settings) { return std::make_unique<BacktrackingLineSearch>(settings); });
    r.add("wolfe-bisection",
          "bisection on the weak Wolfe conditions (c2 0.9) inside the flip-free bound, as SLIM's code",
          [](const LineSearchSettings& settings) { return std::make_unique<WolfeBisectionLineSearch>(settings); });
    return r;
  }();
  return registry;
}

const DensityRegistry2D& energies_2d() { return mutable_energies_2d(); }
const DensityRegistry3D& energies_3d() { return mutable_energies_3d(); }
const PreconditionerRegistry3D& preconditioners_3d() { return mutable_preconditioners_3d(); }
const PreconditionerRegistry2D& preconditioners_2d() { return mutable_preconditioners_2d(); }
const LineSearchRegistry& line_searches() { return mutable_line_searches(); }

const PreconditionerSettings2D& default_preconditioner_settings_2d() {
  static const PreconditionerSettings2D settings;
  return settings;
}

const PreconditionerSettings3D& default_preconditioner_settings_3d() {
  static const PreconditionerSettings3D settings;
  return settings;
}

}  // namespace akvf
