#include "akvf/parameterize.h"

#include "akvf/catalog.h"
#include "akvf/options.h"
#include "akvf/parameterization.h"
#include "framework/process/error.h"

namespace akvf {

bool ParameterizeOptions::is_valid(std::string* error) const { return passes_checks(*this, error); }

struct Parameterizer::State {
  TriMesh mesh;
  ParameterizeOptions options;
  ParamConfig config;
  ParamSetup setup;
  // The symbolic analyses of the mesh's matrices, kept across solves.
  std::shared_ptr<SymbolicAnalysisCache> analyses = std::make_shared<SymbolicAnalysisCache>();

  void configure() {
    check_options(options);
    config = param_config(options);
    config.preconditioner_settings.share_analyses(analyses);
  }
  void prepare() {
    configure();
    setup = prepare_parameterization(mesh, "mesh", config);
  }

  ParameterizeResult run(const ParamSetup& from) const {
    const ParamRun run = run_parameterization(from, config, options.callbacks);
    ParameterizeResult result;
    result.uv = output_uv(from, run.result.x);
    fill_run_fields(run.result, run.preconditioner_statistics, run.preconditioner_report, from.warnings, &result);
    return result;
  }
};

Parameterizer::Parameterizer(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ParameterizeOptions& options)
    : state_(std::make_unique<State>()) {
  require_columns(V, 3, "V (vertex positions x, y, z)");
  require_columns(F, 3, "F (triangles)");
  state_->mesh.V = V;
  state_->mesh.F = F;
  state_->options = options;
  state_->prepare();
}

Parameterizer::~Parameterizer() = default;
Parameterizer::Parameterizer(Parameterizer&&) noexcept = default;
Parameterizer& Parameterizer::operator=(Parameterizer&&) noexcept = default;

ParameterizeResult Parameterizer::solve() { return state_->run(state_->setup); }

ParameterizeResult Parameterizer::solve(const Eigen::MatrixXd& uv0) {
  const ParamSetup& setup = state_->setup;
  if (uv0.rows() != setup.disk.num_input_vertices || uv0.cols() != 2)
    throw OptionsError("the start map must be #V by 2 (" + std::to_string(setup.disk.num_input_vertices) +
                       " by 2), found " + std::to_string(uv0.rows()) + " by " + std::to_string(uv0.cols()));
  ParamSetup from = setup;
  from.warm_start = {};
  // The optimizer works on the mesh scaled to area 1: the start map is
  // scaled alike (its vertices in the compacted numbering).
  const double scale = setup.unit_scale * setup.normalization.scale;
  Eigen::MatrixXd compact(setup.disk.mesh.num_vertices(), 2);
  for (int v = 0; v < compact.rows(); ++v) compact.row(v) = scale * uv0.row(setup.disk.input_vertex[v]);
  if (!compact.allFinite()) throw ValidationError("the start map has a coordinate that is not finite");
  from.x0 = stack_uv(compact);
  if (setup.objective->count_inverted(from.x0) > 0)
    throw ValidationError("the start map inverts a triangle: " + setup.objective->first_bad_element(from.x0));
  return state_->run(from);
}

void Parameterizer::set_options(const ParameterizeOptions& options) {
  const ParameterizeOptions& old = state_->options;
  const bool new_start = options.init != old.init || options.flaps != old.flaps || options.energy != old.energy ||
                         options.exponent != old.exponent || options.warm_start_iters != old.warm_start_iters;
  const ParameterizeOptions previous = state_->options;
  state_->options = options;
  try {
    if (new_start) {
      state_->prepare();
    } else {
      state_->configure();
    }
  } catch (...) {
    state_->options = previous;
    state_->config = param_config(previous);
    throw;
  }
}

const ParameterizeOptions& Parameterizer::options() const { return state_->options; }

Eigen::MatrixXd Parameterizer::initial_uv() const { return output_uv(state_->setup, state_->setup.x0); }

Eigen::MatrixXd Parameterizer::uv_of(const Eigen::VectorXd& x) const { return output_uv(state_->setup, x); }

ParameterizeResult parameterize(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                const ParameterizeOptions& options) {
  return Parameterizer(V, F, options).solve();
}

}  // namespace akvf
