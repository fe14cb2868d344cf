#include "akvf/options.h"

#include <cmath>
#include <sstream>

#include "akvf/catalog.h"
#include "framework/error.h"

namespace akvf {

namespace {

std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

void require(bool ok, const std::string& what, double found) {
  if (!ok) throw OptionsError(what + ", found " + number(found));
}

void check_common(double exponent, int threads, const OptimizerOptions& optimizer,
                  const LineSearchSettings& line_search) {
  require(exponent > 0, "exponent must be > 0", exponent);
  require(threads >= 0, "threads must be >= 0 (0 = all cores)", threads);
  std::string invalid;
  if (!optimizer.is_valid(&invalid)) throw OptionsError(invalid);
  if (!line_search.is_valid(&invalid)) throw OptionsError(invalid);
}

}  // namespace

ParamConfig param_config(const ParameterizeOptions& o) {
  ParamConfig c;
  c.energy = o.energy;
  c.energy_settings.exponent = o.exponent;
  c.preconditioner = o.preconditioner;
  c.line_search = o.line_search;
  c.acceleration = o.acceleration;
  c.preconditioner_settings.akvf.factor.reuse_tolerance = o.akvf_reuse;
  c.line_search_settings.rho = o.ls_rho;
  c.init = parse_tutte_weights(o.init);
  c.optimize_flaps = o.flaps;
  c.optimizer.gradient_tolerance = o.grad_tol;
  c.optimizer.max_iterations = o.max_iters;
  c.optimizer.time_limit = o.time_limit;
  c.warm_start_max_iterations = o.warm_start_iters;
  c.threads = o.threads;
  return c;
}

void validate(const ParamConfig& c) {
  check_common(c.energy_settings.exponent, c.threads, c.optimizer, c.line_search_settings);
  const double tau = c.preconditioner_settings.akvf.factor.reuse_tolerance;
  require(tau >= 0 && tau < 1, "akvf reuse tolerance must be in [0, 1)", tau);
  require(c.warm_start_max_iterations >= 0, "warm start iterations must be >= 0", c.warm_start_max_iterations);
  energies_2d().require(c.energy);
  require_method(c.preconditioner);
  acceleration_eta(c.acceleration, c.preconditioner);
  line_searches().require(c.line_search);
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
  c.akvf_as_written = o.akvf_as_written;
  c.optimizer.gradient_tolerance = o.grad_tol;
  c.optimizer.max_iterations = o.max_iters;
  c.optimizer.time_limit = o.time_limit;
  c.threads = o.threads;
  return c;
}

void validate(const DeformConfig& c) {
  check_common(c.energy_settings.exponent, c.threads, c.optimizer, c.line_search_settings);
  require(c.weight > 0, "constraint weight must be > 0", c.weight);
  const double cg = c.preconditioner_settings.akvf.factor.cg_tolerance;
  require(cg >= 0 && cg < 1, "CG tolerance must be in [0, 1)", cg);
  energies_3d().require(c.energy);
  preconditioners_3d().require(c.preconditioner);
  acceleration_eta(c.acceleration, c.preconditioner);
  line_searches().require(c.line_search);
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
