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
    result.uv_faces = output_uv_faces(from);
    fill_run_fields(run.result, run.preconditioner_statistics, run.preconditioner_report, from.warnings, &result);
    result.boundary_crossings = run.boundary_crossings;
    result.overlap_fraction = run.overlap.fraction();
    result.distortion_energy = run.distortion_energy;
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
  ParamSetup from = state_->setup;
  from.warm_start = {};
  from.x0 = start_from_map(state_->setup, uv0, "the start map", false, nullptr);
  return state_->run(from);
}

void Parameterizer::set_options(const ParameterizeOptions& options) {
  const ParameterizeOptions& old = state_->options;
  const bool new_start = options.init != old.init || options.cut != old.cut || options.flaps != old.flaps ||
                         options.energy != old.energy || options.exponent != old.exponent ||
                         options.warm_start_iters != old.warm_start_iters || options.injectivity != old.injectivity;
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
