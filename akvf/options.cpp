#include "akvf/internal/options.h"

#include "akvf/catalog.h"
#include "akvf/error.h"

namespace akvf {
namespace {

// EigenFilter::kAuto keeps each method's own (newton clamps, as the
// literature's projected Newton does; akvf-newton's Newton phase uses the
// exact Hessian while it is positive definite); a named filter applies to both.
template <class Settings>
void set_eigen_filters(EigenFilter filter, Settings* settings) {
  if (filter == EigenFilter::kAuto) return;
  settings->newton_filter = settings->newton_phase_filter =
      filter == EigenFilter::kClamp      ? EigenvalueFilter::kClamp
      : filter == EigenFilter::kAbsolute ? EigenvalueFilter::kAbsolute
      : filter == EigenFilter::kAdaptive ? EigenvalueFilter::kAdaptive
                                         : EigenvalueFilter::kExact;
}

// grad_tol, or for "auto" 1e-3 (the paper's Table 1), and 1e-4 for an
// energy that is 0 at an isometry (ARAP): its minima on real meshes are a
// few hundredths where the others' are near their positive isometric value,
// so at the same gradient norm a linearly converging method stops
// relatively much further above it (SLIM on camel_b 0.6 % at 1e-3, 0.007 %
// at 1e-4).
double gradient_tolerance(const std::optional<double>& grad_tol, double isometric_value) {
  if (grad_tol) return *grad_tol;
  return isometric_value == 0 ? 1e-4 : 1e-3;
}

}  // namespace

ParamConfig param_config(const ParameterizeOptions& o) {
  ParamConfig c;
  c.energy = o.energy;
  c.energy_settings.exponent = o.exponent;
  c.solver = o.preconditioner == kLbfgsMethod ? Solver::kLbfgs : o.solver;  // --precond lbfgs: the alias
  c.preconditioner = o.preconditioner;
  c.line_search = o.line_search;
  c.acceleration = o.acceleration;
  c.preconditioner_settings.akvf.factor.reuse_tolerance = o.akvf_reuse;
  // --newton-reuse auto: plain newton factors every iteration (the
  // literature's method); akvf-newton's Newton phase reuses as AKVF does.
  c.preconditioner_settings.newton.reuse_tolerance = o.newton_reuse.value_or(0);
  c.preconditioner_settings.newton_phase = c.preconditioner_settings.newton;
  c.preconditioner_settings.newton_phase.reuse_tolerance = o.newton_reuse.value_or(o.akvf_reuse);
  c.line_search_settings.rho = o.ls_rho;
  // --local-sweep auto: the methods tagged kSweepsByDefault (the default
  // one) sweep on energies tagged kCollapseBarrier; the others run as
  // published. 4: the vertices whose |g_v| is
  // above twice the root mean square, the few where the gradient gathers
  // about the elements that set the bound (docs/design.md, "Local Newton
  // sweeps").
  const bool sweeps_by_default = preconditioners_2d().has_tag(o.preconditioner, kSweepsByDefault) &&
                                 energies_2d().has_tag(o.energy, kCollapseBarrier);
  c.local_sweep = o.local_sweep.value_or(sweeps_by_default ? 4 : 0);
  // --akvf-compression auto: on where K stiffens under compression faster
  // than the energy (akvf_preconditioner_2d.h); 1, the point where K starts
  // to curve more than the energy along the face's compression.
  const double compression = o.akvf_compression.value_or(energies_2d().has_tag(o.energy, kCollapseBarrier) ? 0 : 1);
  if (compression > 0) c.preconditioner_settings.akvf.compression_stiffness = compression;
  set_eigen_filters(o.eigen_filter, &c.preconditioner_settings);
  c.init_from_file = o.init == InitialMap::kFile;
  c.init = o.init == InitialMap::kCotan ? TutteWeights::kCotangent : TutteWeights::kUniform;
  const auto candidate = [&o](InitialMap map) {
    return o.init == InitialMap::kAuto ? ConformalStart::kAuto
           : o.init == map             ? ConformalStart::kAlways
                                       : ConformalStart::kNever;
  };
  c.conformal = candidate(InitialMap::kConformal);
  c.boundary_first = candidate(InitialMap::kBoundaryFirst);
  c.optimize_flaps = o.flaps;
  c.global_injectivity = o.injectivity == Injectivity::kGlobal;
  c.cut = o.cut != Cut::kNone;
  c.seams = o.cut == Cut::kSeams;
  c.max_distortion = o.max_distortion;
  c.min_coverage = o.min_coverage;
  // A wider gutter would leave the charts little of the texture.
  if (o.gutter * 16 > o.texture_size)
    throw OptionsError("gutter " + number_text(o.gutter) + " is more than 1/16 of texture_size " +
                       std::to_string(o.texture_size) + " (both in texels)");
  c.gutter = o.gutter / o.texture_size;
  c.repair = o.repair == Repair::kAuto;
  c.optimizer.gradient_tolerance =
      gradient_tolerance(o.grad_tol, energies_2d().create(c.energy, c.energy_settings)->lower_bound());
  c.optimizer.max_iterations = o.max_iters;
  c.optimizer.time_limit = o.time_limit;
  c.warm_start_max_iterations = o.warm_start_iters;
  c.linear_solver = o.linear_solver;
  c.threads = o.threads;
  return c;
}

void check_options(const ParameterizeOptions& options) {
  check_all(parameterize_option_fields(), options, [](const auto& field) { return field.key; });
}

DeformConfig deform_config(const DeformOptions& o) {
  DeformConfig c;
  c.energy = o.energy;
  c.energy_settings.exponent = o.exponent;
  c.preconditioner = o.preconditioner;
  c.line_search = o.line_search;
  c.acceleration = o.acceleration;
  c.weight = o.weight;
  c.hard_constraints = o.hard;
  c.preconditioner_settings.set_cg_tolerance(o.cg_tol);
  set_eigen_filters(o.eigen_filter, &c.preconditioner_settings);
  c.akvf_as_written = o.akvf_as_written;
  c.optimizer.gradient_tolerance =
      gradient_tolerance(o.grad_tol, energies_3d().create(c.energy, c.energy_settings)->lower_bound());
  c.optimizer.max_iterations = o.max_iters;
  c.optimizer.time_limit = o.time_limit;
  c.linear_solver = o.linear_solver;
  c.threads = o.threads;
  return c;
}

void check_options(const DeformOptions& options) {
  check_all(deform_option_fields(), options, [](const auto& field) { return field.key; });
}

RunStatistics run_statistics(const OptimizerResult& result, const PreconditionerStatistics& preconditioner) {
  RunStatistics statistics;
  statistics.preconditioner = preconditioner;
  if (result.trace.empty()) return statistics;
  statistics.iterations = result.trace.back().iteration;
  statistics.seconds = result.trace.back().seconds;
  for (const IterationSummary& row : result.trace) {
    statistics.preconditioner_seconds += row.precond_seconds;
    statistics.line_search_seconds += row.line_search_seconds;
  }
  return statistics;
}

}  // namespace akvf
