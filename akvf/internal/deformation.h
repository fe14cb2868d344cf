#pragma once
// Volumetric deformation (§6.2): minimize sum_t V_t D(J_t) / sum_t V_t +
// w sum_i |x_i - p_i|^2 over the vertex positions of a tet mesh scaled to
// rest volume 1 (targets p_i scaled alike, so w does not depend on the
// mesh's units), starting
// from the rest shape, with a flip-free preconditioned descent; or, with hard
// constraints, the distortion alone with the constrained vertices fixed at
// their targets.
#include <string>

#include "akvf/catalog.h"
#include "akvf/constrained_objective.h"
#include "akvf/internal/preconditioner_settings.h"
#include "akvf/mesh.h"
#include "akvf/optimizer.h"
#include "akvf/rest_geometry.h"
#include "framework/mesh/tet_validation.h"

namespace akvf {

struct DeformConfig {
  std::string energy = "symmetric-dirichlet";
  EnergySettings energy_settings;
  std::string preconditioner = "akvf-newton";        // the default method (docs/design.md)
  PreconditionerSettings3D preconditioner_settings;  // c of K + c I, CG instead of the factorization, ...
  std::string line_search = "backtracking";
  Acceleration acceleration = Acceleration::kAuto;  // AQP momentum: see acceleration_eta() in catalog.h
  LineSearchSettings line_search_settings;
  double weight = 1e5;  // w (§6.2)
  // Hard constraints instead: the constrained vertices start at their
  // targets (refused if that inverts a tet) and stay there.
  bool hard_constraints = false;
  // AKVF exactly as §6.2 states it: K + c I, without the constraints'
  // Hessian and without the energy scale (docs/design.md measures both).
  bool akvf_as_written = false;
  LinearSolver linear_solver = LinearSolver::kAuto;  // kAuto: chosen from the factor's size
  int threads = 0;                                   // worker threads during the run; 0 = all cores
  OptimizerOptions optimizer = [] {
    OptimizerOptions o;
    o.max_iterations = 100;  // Figure 8 runs 100 iterations of each method
    return o;
  }();
};

struct DeformRun {
  // The validated rest mesh (orientation fixed, unreferenced vertices
  // dropped), in the optimizer's units: the input's coordinates times
  // `scale`, which brings the rest volume to 1. The trace's energies and
  // gradient norms are in these units; result.x is at the input's scale.
  PreparedTetMesh prepared;
  double scale = 1;
  OptimizerResult result;
  std::string preconditioner_report;
  PreconditionerStatistics preconditioner_statistics;
  Warnings warnings;
};

// What does not depend on the options or the constraints: the validated
// mesh at unit rest volume and its rest geometry, made once for repeated runs.
struct DeformSetup {
  PreparedTetMesh prepared;  // as DeformRun::prepared
  double scale = 1;          // input coordinates times scale = the optimizer's units
  RestTets rest;             // of prepared.mesh
  std::string name;          // for messages
  int index_base = 0;        // how the source numbers vertices and tets
  Warnings warnings;
};

// Throws InputError / ValidationError naming `name`.
DeformSetup prepare_deformation(const TetMesh& input, const std::string& name);
DeformRun run_deformation(const DeformSetup& setup, const PositionConstraints& constraints, const DeformConfig& config,
                          const std::vector<IterationCallback>& callbacks = {});

// Both steps at once. `constraints` number vertices as `input` does
// (0-based). Throws InputError / ValidationError / OptionsError naming `name`.
DeformRun run_deformation(const TetMesh& input, const std::string& name, const PositionConstraints& constraints,
                          const DeformConfig& config, const std::vector<IterationCallback>& callbacks = {});

}  // namespace akvf
