#include "akvf/deform.h"

#include <vector>

#include "akvf/error.h"
#include "akvf/internal/deformation.h"
#include "akvf/internal/options.h"
#include "framework/optimization/distortion_objective.h"

namespace akvf {

bool DeformOptions::is_valid(std::string* error) const { return passes_checks(*this, error); }

struct Deformer::State {
  TetMesh mesh;
  DeformSetup setup;
  // The symbolic analyses of the mesh's matrices, kept across solves.
  std::shared_ptr<SymbolicAnalysisCache> analyses = std::make_shared<SymbolicAnalysisCache>();
};

Deformer::Deformer(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T) : state_(std::make_unique<State>()) {
  require_columns(V, 3, "V (vertex positions x, y, z)");
  require_columns(T, 4, "T (tetrahedra)");
  state_->mesh.V = V;
  state_->mesh.T = T;
  state_->setup = prepare_deformation(state_->mesh, "mesh");
}

Deformer::~Deformer() = default;
Deformer::Deformer(Deformer&&) noexcept = default;
Deformer& Deformer::operator=(Deformer&&) noexcept = default;

DeformResult Deformer::solve(const PositionConstraints& constraints, const DeformOptions& options) const {
  const Eigen::Index num_vertices = state_->mesh.V.rows();
  if (constraints.targets.rows() != static_cast<Eigen::Index>(constraints.vertices.size()) ||
      (constraints.targets.size() > 0 && constraints.targets.cols() != 3))
    throw InputError("constraints: " + std::to_string(constraints.vertices.size()) + " indices but targets of " +
                     std::to_string(constraints.targets.rows()) + " by " + std::to_string(constraints.targets.cols()) +
                     " (expected #C by 3)");
  std::vector<int> first(static_cast<std::size_t>(num_vertices), -1);  // the constraint naming each vertex
  for (std::size_t c = 0; c < constraints.vertices.size(); ++c) {
    const int v = constraints.vertices[c];
    if (v < 0 || v >= num_vertices)
      throw InputError("constraint " + std::to_string(c) + ": vertex index " + std::to_string(v) + " out of range (" +
                       std::to_string(num_vertices) + " vertices, 0-based)");
    // As the constraints file: one target per vertex, never an average.
    if (first[v] >= 0)
      throw InputError("constraint " + std::to_string(c) + ": vertex " + std::to_string(v) +
                       " is already constrained by constraint " + std::to_string(first[v]));
    first[v] = static_cast<int>(c);
  }
  check_options(options);
  DeformConfig config = deform_config(options);
  config.preconditioner_settings.share_analyses(state_->analyses);
  const DeformRun run = run_deformation(state_->setup, constraints, config, options.callbacks);
  DeformResult result;
  result.x = run.prepared.in_input_numbering(unstack_rows(run.result.x, 3), state_->mesh).V;
  fill_run_fields(run.result, run.preconditioner_statistics, run.preconditioner_report, run.warnings, &result);
  return result;
}

DeformResult deform(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, const PositionConstraints& constraints,
                    const DeformOptions& options) {
  check_options(options);
  return Deformer(V, T).solve(constraints, options);
}

}  // namespace akvf
