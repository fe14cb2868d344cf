#include "akvf/internal/deformation.h"

#include <cmath>

#include "akvf/error.h"
#include "akvf/rest_geometry.h"
#include "akvf/threads.h"
#include "framework/optimization/distortion_objective.h"
#include "preconditioners/fixed_vertices_preconditioner.h"

namespace akvf {

namespace {

// The settings of the 3D preconditioners: as configured, and for AKVF as
// §6.2 states it (K + c I: no constraint Hessian, energy scale or divergence
// weight) when asked
// and the constraints are soft. The constraints reach every preconditioner
// through the objective (DistortionObjective::added_hessian_diagonal).
PreconditionerSettings3D preconditioner_settings(const DeformConfig& config) {
  PreconditionerSettings3D settings = config.preconditioner_settings;
  settings.set_linear_solver(available_linear_solver(config.linear_solver));
  settings.akvf_newton_switch.backtracking_factor = config.line_search_settings.rho;
  if (config.akvf_as_written && !config.hard_constraints) {
    settings.akvf.include_problem_hessian = false;
    settings.akvf.secant_scaling = false;
    settings.akvf.divergence_weight = 1;
  }
  return settings;
}

// The constraints with the vertices renumbered as in the prepared mesh; a
// constraint on a dropped vertex (in no tet) is left out with a warning.
PositionConstraints in_mesh_numbering(const PositionConstraints& constraints, const PreparedTetMesh& prepared,
                                      const std::string& name, Warnings* warnings) {
  std::vector<int> new_index(prepared.num_input_vertices, -1);
  for (std::size_t i = 0; i < prepared.input_vertex.size(); ++i)
    new_index[prepared.input_vertex[i]] = static_cast<int>(i);
  PositionConstraints out;
  std::vector<int> kept;
  int ignored = 0, first_ignored = -1;
  for (std::size_t c = 0; c < constraints.vertices.size(); ++c) {
    const int v = constraints.vertices[c];
    if (v >= 0 && v < prepared.num_input_vertices && new_index[v] >= 0) {
      out.vertices.push_back(new_index[v]);
      kept.push_back(static_cast<int>(c));
    } else if (ignored++ == 0) {
      first_ignored = v;
    }
  }
  out.targets.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t k = 0; k < kept.size(); ++k) out.targets.row(k) = constraints.targets.row(kept[k]);
  if (ignored > 0)
    warnings->push_back(name + ": " + std::to_string(ignored) + " constraints are on vertices in no tet (first: " +
                        std::to_string(first_ignored) + ", 0-based); they are ignored");
  if (out.vertices.empty() && !constraints.vertices.empty())
    throw ValidationError(name + ": every constrained vertex is in no tet; nothing to deform");
  return out;
}

// Callbacks see the iterate at the input's scale, as the result gives it.
std::vector<IterationCallback> at_input_scale(const std::vector<IterationCallback>& callbacks, double scale) {
  if (scale == 1) return callbacks;
  std::vector<IterationCallback> wrapped;
  for (const IterationCallback& callback : callbacks)
    wrapped.push_back(
        [callback, scale](const IterationSummary& row, const Eigen::VectorXd& x) { return callback(row, x / scale); });
  return wrapped;
}

}  // namespace

DeformSetup prepare_deformation(const TetMesh& input, const std::string& name) {
  DeformSetup setup;
  setup.name = name;
  setup.index_base = input.index_base;
  // An exact power of two first (extents like 1e-100 or 1e+100 would under-
  // or overflow volumes), then the rest volume is brought to 1, so that the
  // energy, the penalty and the gradient do not depend on the input's units.
  const double unit = power_of_two_unit_scale(input.V, name);
  TetMesh unit_input = input;
  unit_input.V *= unit;
  setup.prepared = prepare_tet_mesh(unit_input, name, &setup.warnings);
  TetMesh& mesh = setup.prepared.mesh;
  const double to_unit_volume = 1 / std::cbrt(rest_tets(mesh).total_volume);
  mesh.V *= to_unit_volume;
  setup.scale = unit * to_unit_volume;
  setup.rest = rest_tets(mesh);
  return setup;
}

DeformRun run_deformation(const TetMesh& input, const std::string& name, const PositionConstraints& input_constraints,
                          const DeformConfig& config, const std::vector<IterationCallback>& callbacks) {
  return run_deformation(prepare_deformation(input, name), input_constraints, config, callbacks);
}

DeformRun run_deformation(const DeformSetup& setup, const PositionConstraints& input_constraints,
                          const DeformConfig& config, const std::vector<IterationCallback>& user_callbacks) {
  std::string invalid;
  if (!config.optimizer.is_valid(&invalid) || !config.line_search_settings.is_valid(&invalid))
    throw OptionsError(invalid);
  std::shared_ptr<const DistortionDensity<3>> density = energies_3d().create(config.energy, config.energy_settings);
  preconditioners_3d().require(config.preconditioner);
  OptimizerOptions optimizer = config.optimizer;
  optimizer.acceleration_eta =
      acceleration_eta(config.acceleration, preconditioners_3d().has_tag(config.preconditioner, kMomentumByDefault));
  const ThreadLimit threads(config.threads);
  DeformRun run;
  run.prepared = setup.prepared;
  run.scale = setup.scale;
  run.warnings = setup.warnings;
  const std::string& name = setup.name;
  const TetMesh& mesh = run.prepared.mesh;
  PositionConstraints constraints = in_mesh_numbering(input_constraints, run.prepared, name, &run.warnings);
  constraints.targets *= run.scale;
  const std::vector<IterationCallback> callbacks = at_input_scale(user_callbacks, run.scale);
  DistortionObjective3D energy(mesh.T, setup.rest, density, mesh.num_vertices());
  energy.set_file_numbering(run.prepared.input_vertex, setup.index_base);
  auto line_search = line_searches().create(
      config.line_search, line_search_settings(config.line_search_settings, optimizer.acceleration_eta));
  const Eigen::VectorXd rest = stack_rows(mesh.V);
  if (config.hard_constraints) {
    const FixedVerticesObjective objective(energy, 3, constraints.vertices);
    const Eigen::VectorXd start = place_at_targets(rest, 3, constraints);
    if (const int inverted = energy.count_inverted(start); inverted > 0)
      throw ValidationError(name + ": placing the " + std::to_string(constraints.vertices.size()) +
                            " constrained vertices at their targets inverts " + std::to_string(inverted) +
                            " tets; hard constraints need a start without inverted tets (use soft constraints, "
                            "the default, or smaller displacements)");
    // A large pin on the fixed coordinates restricts P to the free ones
    // (fixed_vertices_preconditioner.h).
    energy.set_added_hessian_diagonal(1e10 * (Eigen::VectorXd::Ones(rest.size()) - objective.free_mask()));
    FixedVerticesPreconditioner preconditioner(
        preconditioners_3d().create(config.preconditioner, energy, preconditioner_settings(config)),
        objective.free_mask());
    run.result = minimize(objective, preconditioner, *line_search, start, optimizer, callbacks);
    run.preconditioner_report = preconditioner.report();
    run.preconditioner_statistics = preconditioner.statistics();
    run.result.x /= run.scale;
    return run;
  }
  const SoftConstrainedObjective objective(energy, 3, constraints, config.weight);
  energy.set_added_hessian_diagonal(objective.hessian_diagonal());  // the penalty's: 2 w on constrained coordinates
  auto preconditioner = preconditioners_3d().create(config.preconditioner, energy, preconditioner_settings(config));
  run.result = minimize(objective, *preconditioner, *line_search, rest, optimizer, callbacks);
  run.preconditioner_report = preconditioner->report();
  run.preconditioner_statistics = preconditioner->statistics();
  run.result.x /= run.scale;
  return run;
}

}  // namespace akvf
