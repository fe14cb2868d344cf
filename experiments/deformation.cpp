#include "experiments/deformation.h"

#include "framework/distortion_objective.h"
#include "framework/error.h"
#include "framework/tet_validation.h"

namespace akvf {

DeformRun run_deformation(const TetMesh& input, const std::string& name, const PositionConstraints& constraints,
                          const DeformConfig& config, const std::vector<IterationCallback>& callbacks) {
  std::string invalid;
  if (!config.optimizer.is_valid(&invalid) || !config.line_search_settings.is_valid(&invalid))
    throw OptionsError(invalid);
  std::shared_ptr<const DistortionDensity<3>> density = energies_3d().create(config.energy, config.energy_settings);
  preconditioners_3d().require(config.preconditioner);
  DeformRun run;
  run.mesh = prepare_tet_mesh(input, name, &run.warnings);
  const TetObjective energy(run.mesh.T, rest_tets(run.mesh), density, run.mesh.num_vertices());
  const SoftConstrainedObjective objective(energy, 3, constraints, config.weight);
  auto preconditioner = preconditioners_3d().create(config.preconditioner, energy, config.akvf);
  auto line_search = line_searches().create(config.line_search, config.line_search_settings);
  run.result = minimize(objective, *preconditioner, *line_search, stack_rows(run.mesh.V), config.optimizer, callbacks);
  run.preconditioner_report = preconditioner->report();
  return run;
}

}  // namespace akvf
