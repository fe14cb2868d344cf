#include "akvf/parameterize.h"

#include <atomic>

#include "akvf/catalog.h"
#include "akvf/error.h"
#include "akvf/internal/options.h"
#include "akvf/internal/parameterization.h"

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
    setup.gutter = config.gutter;  // the outputs' packing: no new start
    setup.min_coverage = config.min_coverage;
  }
  void prepare() {
    configure();
    setup = prepare_parameterization(mesh, "mesh", config);
  }

  // Set while a solve or set_options runs (Busy below).
  std::atomic<bool> busy{false};

  ParameterizeResult run(const ParamSetup& from, const std::vector<IterationCallback>& more) const {
    std::vector<IterationCallback> callbacks = options.callbacks;
    callbacks.insert(callbacks.end(), more.begin(), more.end());
    const ParamRun run = run_parameterization(from, config, callbacks);
    ParameterizeResult result;
    result.uv = output_uv(final_setup(from, run), run.result.x);
    result.uv_faces = output_uv_faces(final_setup(from, run));
    fill_run_fields(run.result, run.preconditioner_statistics, run.preconditioner_report, from.warnings, &result);
    result.initial_map = from.initial_map;
    result.boundary_crossings = run.boundary_crossings;
    result.overlap_fraction = run.overlap.fraction();
    result.distortion_energy = run.distortion_energy;
    result.seams_added = run.seams.seams;
    result.seam_length = run.seams.seam_length;
    result.overlap_pieces = run.seams.overlap_pieces;
    result.parted_charts = run.seams.parted_charts;
    result.packing_splits = run.packing_splits;
    result.chart_distortion = run.seams.chart_distortion;
    result.distortion_bounded = run.seams.bound_met;
    result.seam_stop_reason = run.seams.stop_reason;
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

namespace {
// Marks a Parameterizer busy for its lifetime; a second one at the same time
// (another thread, or a callback of the running solve) throws.
class Busy {
 public:
  Busy(std::atomic<bool>* flag, const char* what) : flag_(flag) {
    if (flag_->exchange(true))
      throw OptionsError(std::string("Parameterizer::") + what +
                         ": this Parameterizer is solving (in another thread, or this is its own callback); use one "
                         "Parameterizer per thread, and change options between solves");
  }
  ~Busy() { flag_->store(false); }
  Busy(const Busy&) = delete;
  Busy& operator=(const Busy&) = delete;

 private:
  std::atomic<bool>* flag_;
};
}  // namespace

ParameterizeResult Parameterizer::solve(const std::vector<IterationCallback>& callbacks) {
  const Busy busy(&state_->busy, "solve");
  return state_->run(state_->setup, callbacks);
}

ParameterizeResult Parameterizer::solve(const Eigen::MatrixXd& uv0, const std::vector<IterationCallback>& callbacks) {
  const Busy busy(&state_->busy, "solve");
  ParamSetup from = state_->setup;
  from.warm_start = {};
  from.x0 = start_from_map(state_->setup, state_->config, uv0, "the start map", false, nullptr);
  from.initial_map = InitialMap::kFile;
  return state_->run(from, callbacks);
}

void Parameterizer::set_options(const ParameterizeOptions& options) {
  const Busy busy(&state_->busy, "set_options");
  const ParameterizeOptions& old = state_->options;
  bool new_start = false;
  for (const auto& field : parameterize_option_fields())
    if (field.recomputes_start && field.format(options) != field.format(old)) new_start = true;
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

Eigen::MatrixXd Parameterizer::uv_of(const Eigen::VectorXd& x) const {
  const Eigen::Index expected = 2 * static_cast<Eigen::Index>(state_->setup.disk.mesh.num_vertices());
  if (x.size() != expected)
    throw OptionsError("Parameterizer::uv_of: x has " + std::to_string(x.size()) + " values, this mesh's maps " +
                       std::to_string(expected) +
                       " (with cut seams, a later round's x is of the mesh its seams opened)");
  return output_uv(state_->setup, x);
}

ParameterizeResult parameterize(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                const ParameterizeOptions& options) {
  return Parameterizer(V, F, options).solve();
}

}  // namespace akvf
