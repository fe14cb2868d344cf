#include "experiments/deformation.h"

#include "framework/distortion_objective.h"
#include "framework/error.h"
#include "framework/tet_validation.h"
#include "preconditioners/fixed_vertices_preconditioner.h"

namespace akvf {

namespace {

// The settings with the constraints on the preconditioners' diagonals:
// the penalty's Hessian (soft), or a large pin that restricts P to the free
// coordinates (hard, see fixed_vertices_preconditioner.h).
Preconditioner3DSettings with_constraint_diagonal(const DeformConfig& config, const Eigen::VectorXd& diagonal) {
  Preconditioner3DSettings settings = config.preconditioner_settings;
  for (FactorOptions* options : {&settings.akvf.factor, &settings.newton, &settings.laplacian, &settings.slim})
    options->extra_diagonal = diagonal;
  if (config.akvf_as_written && !config.hard_constraints) {
    settings.akvf.factor.extra_diagonal.resize(0);
    settings.akvf.secant_scaling = false;
  }
  return settings;
}

}  // namespace

DeformRun run_deformation(const TetMesh& input, const std::string& name, const PositionConstraints& constraints,
                          const DeformConfig& config, const std::vector<IterationCallback>& callbacks) {
  std::string invalid;
  if (!config.optimizer.is_valid(&invalid) || !config.line_search_settings.is_valid(&invalid))
    throw OptionsError(invalid);
  std::shared_ptr<const DistortionDensity<3>> density = energies_3d().create(config.energy, config.energy_settings);
  preconditioners_3d().require(config.preconditioner);
  OptimizerOptions optimizer = config.optimizer;
  optimizer.acceleration_eta = acceleration_eta(config.acceleration, config.preconditioner);
  DeformRun run;
  run.mesh = prepare_tet_mesh(input, name, &run.warnings);
  const TetObjective energy(run.mesh.T, rest_tets(run.mesh), density, run.mesh.num_vertices());
  auto line_search = line_searches().create(config.line_search, config.line_search_settings);
  const Eigen::VectorXd rest = stack_rows(run.mesh.V);
  if (config.hard_constraints) {
    const FixedVerticesObjective objective(energy, 3, constraints.vertices);
    const Eigen::VectorXd start = place_at_targets(rest, 3, constraints);
    if (const int inverted = energy.count_inverted(start); inverted > 0)
      throw ValidationError(name + ": placing the " + std::to_string(constraints.vertices.size()) +
                            " constrained vertices at their targets inverts " + std::to_string(inverted) +
                            " tets; hard constraints need a start without inverted tets (use soft constraints, "
                            "the default, or smaller displacements)");
    const Eigen::VectorXd pin = 1e10 * (Eigen::VectorXd::Ones(rest.size()) - objective.free_mask());
    FixedVerticesPreconditioner preconditioner(
        preconditioners_3d().create(config.preconditioner, energy, with_constraint_diagonal(config, pin)),
        objective.free_mask());
    run.result = minimize(objective, preconditioner, *line_search, start, optimizer, callbacks);
    run.preconditioner_report = preconditioner.report();
    return run;
  }
  const SoftConstrainedObjective objective(energy, 3, constraints, config.weight);
  auto preconditioner = preconditioners_3d().create(config.preconditioner, energy,
                                                    with_constraint_diagonal(config, objective.hessian_diagonal()));
  run.result = minimize(objective, *preconditioner, *line_search, rest, optimizer, callbacks);
  run.preconditioner_report = preconditioner->report();
  return run;
}

}  // namespace akvf
