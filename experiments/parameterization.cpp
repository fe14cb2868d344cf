#include "experiments/parameterization.h"

#include <cmath>

#include "experiments/catalog.h"
#include "experiments/uv_svg.h"
#include "framework/error.h"
#include "solvers/lbfgs_solver.h"

namespace akvf {

namespace {
// The energy whose minimizer starts energies that are infinite at the Tutte map.
constexpr const char* kWarmStartEnergy = "symmetric-dirichlet";

void warm_start(const ParamConfig& config, ParamSetup* setup);
}  // namespace

ParamSetup prepare_parameterization(const TriMesh& input, const std::string& name, const ParamConfig& config) {
  std::string invalid;
  if (!config.optimizer.is_valid(&invalid)) throw OptionsError(invalid);
  if (!config.line_search_settings.is_valid(&invalid)) throw OptionsError(invalid);
  // Resolve names first so a typo fails before any work.
  std::shared_ptr<const DistortionDensity2> density = energies_2d().create(config.energy, config.energy_settings);
  require_method(config.preconditioner);
  acceleration_eta(config.acceleration, config.preconditioner);  // validates the mode
  line_searches().require(config.line_search);

  ParamSetup setup;
  setup.disk = prepare_disk_mesh(input, name);
  setup.warnings = setup.disk.warnings;
  TriMesh normalized = setup.disk.mesh;
  setup.normalization = normalize_to_unit_area(&normalized);

  Eigen::MatrixXd UV = tutte_embedding(normalized, setup.disk.boundary_loop, config.init, &setup.warnings);
  if (config.optimize_flaps) setup.flaps_moved = optimize_flaps(normalized, &UV);
  setup.x0 = stack_uv(UV);
  setup.objective =
      std::make_shared<ParamObjective>(normalized.F, rest_triangles(normalized), density, normalized.num_vertices());
  if (!std::isfinite(setup.objective->value(setup.x0)) && config.energy != kWarmStartEnergy) warm_start(config, &setup);
  return setup;
}

ParamRun run_parameterization(const ParamSetup& setup, const ParamConfig& config,
                              const std::vector<IterationCallback>& callbacks) {
  ParamRun run;
  OptimizerOptions optimizer = config.optimizer;
  optimizer.acceleration_eta = acceleration_eta(config.acceleration, config.preconditioner);
  if (config.preconditioner == kLbfgsMethod) {
    run.preconditioner_name = kLbfgsMethod;
    run.result = minimize_lbfgs(*setup.objective, setup.x0, config.optimizer, {}, callbacks);  // no momentum
    return run;
  }
  auto preconditioner =
      preconditioners_2d().create(config.preconditioner, *setup.objective, config.preconditioner_settings);
  auto line_search = line_searches().create(config.line_search, config.line_search_settings);
  run.preconditioner_name = preconditioner->name();
  run.result = minimize(*setup.objective, *preconditioner, *line_search, setup.x0, optimizer, callbacks);
  run.preconditioner_report = preconditioner->report();
  return run;
}

Eigen::MatrixXd output_uv(const ParamSetup& setup, const Eigen::VectorXd& x) {
  const Eigen::MatrixXd UV = unstack_uv(x);
  const Eigen::MatrixXi& F = setup.objective->faces();
  double uv_area = 0;
  for (int f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector2d e1 = UV.row(F(f, 1)) - UV.row(F(f, 0)), e2 = UV.row(F(f, 2)) - UV.row(F(f, 0));
    uv_area += 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
  }
  const double scale = std::sqrt(setup.normalization.input_area / uv_area);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(setup.disk.num_input_vertices, 2);
  for (int v = 0; v < UV.rows(); ++v) out.row(setup.disk.input_vertex[v]) = scale * UV.row(v);
  return out;
}

namespace {

void warm_start(const ParamConfig& config, ParamSetup* setup) {
  // The exponential energies overflow at the Tutte map's slivers. Start them
  // instead from the symmetric Dirichlet minimizer (AKVF, gradient 1e-3),
  // which is finite for every energy here.
  ParamConfig sd_config;
  sd_config.energy = kWarmStartEnergy;
  sd_config.optimizer.max_iterations = config.optimizer.max_iterations;
  ParamSetup sd_setup = *setup;
  sd_setup.objective =
      std::make_shared<ParamObjective>(setup->objective->faces(), setup->objective->rest(),
                                       energies_2d().create(kWarmStartEnergy, {}), setup->objective->num_vertices());
  const OptimizerResult warm = run_parameterization(sd_setup, sd_config).result;
  if (!is_normal_termination(warm.status) || !std::isfinite(setup->objective->value(warm.x))) {
    setup->warnings.push_back(config.energy +
                              " is infinite at the initial map and at the symmetric Dirichlet "
                              "minimizer; the run will stop at once");
    return;
  }
  setup->x0 = warm.x;
  setup->warnings.push_back(config.energy +
                            " is infinite at the Tutte map; starting from the symmetric Dirichlet "
                            "minimizer instead (" +
                            std::to_string(warm.trace.back().iteration) + " AKVF iterations)");
}

}  // namespace

void write_layout_svg(const std::string& path, const ParamSetup& setup, const Eigen::VectorXd& x,
                      const std::string& title) {
  const Eigen::VectorXd excess = setup.objective->face_distortion(x).array() - setup.objective->density().lower_bound();
  const Eigen::MatrixXd UV = output_uv(setup, x);
  const TriMesh& mesh = setup.disk.mesh;
  Eigen::MatrixXd compact_uv(mesh.num_vertices(), 2);
  for (int v = 0; v < mesh.num_vertices(); ++v) compact_uv.row(v) = UV.row(setup.disk.input_vertex[v]);
  write_uv_svg(path, compact_uv, mesh.F, excess, title);
}

}  // namespace akvf
