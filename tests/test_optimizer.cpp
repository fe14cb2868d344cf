// The optimizer loop end to end on built-in meshes: known optima, statuses,
// callbacks, determinism.
#include <doctest/doctest.h>

#include <tbb/global_control.h>

#include <cmath>
#include <limits>

#include "akvf/backtracking_line_search.h"
#include "akvf/catalog.h"
#include "akvf/error.h"
#include "akvf/internal/demo_mesh.h"
#include "akvf/internal/parameterization.h"
#include "akvf/rest_geometry.h"
#include "framework/process/interrupt.h"
#include "preconditioners/identity_preconditioner.h"
#include "preconditioners/switching_preconditioner.h"
#include "tests/test_support.h"

using akvf::ParamConfig;
using akvf::TerminationStatus;

namespace {

akvf::ParamRun run(const akvf::TriMesh& mesh, const ParamConfig& config,
                   const std::vector<akvf::IterationCallback>& callbacks = {}) {
  const auto setup = akvf::prepare_parameterization(mesh, "test", config);
  return akvf::run_parameterization(setup, config, callbacks);
}

// Checks the invariant of every iterate: no inverted triangle.
akvf::IterationCallback no_flips_allowed() {
  return [](const akvf::IterationSummary& s, const Eigen::VectorXd&) {
    CHECK(s.flips == 0);
    return akvf::CallbackAction::kContinue;
  };
}

class AscentPreconditioner final : public akvf::Preconditioner {
 public:
  std::string name() const override { return "ascent"; }
  void update(const akvf::OptimizationState&) override {}
  void apply(const Eigen::VectorXd& g, Eigen::VectorXd* r) override { *r = -g; }
};

// Descends for `good_iterations`, then returns NaN for one vertex.
class PoisoningPreconditioner final : public akvf::Preconditioner {
 public:
  explicit PoisoningPreconditioner(int good_iterations) : good_iterations_(good_iterations) {}
  std::string name() const override { return "poisoning"; }
  void update(const akvf::OptimizationState& state) override { iteration_ = state.iteration; }
  void apply(const Eigen::VectorXd& g, Eigen::VectorXd* r) override {
    *r = 0.01 * g;
    if (iteration_ > good_iterations_) (*r)[7] = std::numeric_limits<double>::quiet_NaN();
  }

 private:
  int good_iterations_, iteration_ = 0;
};

// An objective that hands every call to `base`, for the ones below to
// change one thing.
class ForwardingObjective : public akvf::Objective {
 public:
  explicit ForwardingObjective(const akvf::Objective& base) : base_(base) {}
  int num_variables() const override { return base_.num_variables(); }
  double value(const Eigen::VectorXd& x) const override { return base_.value(x); }
  double value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* g) const override {
    return base_.value_and_gradient(x, g);
  }
  double max_feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const override {
    return base_.max_feasible_step(x, d);
  }
  int count_inverted(const Eigen::VectorXd& x) const override { return base_.count_inverted(x); }

 protected:
  const akvf::Objective& base_;
};

// The distortion objective, except that the gradient at vertex 2 turns NaN
// once the energy falls below `threshold`.
class NanGradientBelow final : public ForwardingObjective {
 public:
  NanGradientBelow(const akvf::Objective& base, double threshold) : ForwardingObjective(base), threshold_(threshold) {}
  double value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* g) const override {
    const double e = base_.value_and_gradient(x, g);
    if (e < threshold_) (*g)[4] = std::numeric_limits<double>::quiet_NaN();
    return e;
  }

 private:
  double threshold_;
};

// The distortion objective, except that every iterate whose energy is below
// `threshold` counts one inverted element: what rounding does to an element
// that an energy without a barrier (ARAP) has collapsed.
class InvertedBelow final : public ForwardingObjective {
 public:
  InvertedBelow(const akvf::Objective& base, double threshold) : ForwardingObjective(base), threshold_(threshold) {}
  int count_inverted(const Eigen::VectorXd& x) const override { return base_.value(x) < threshold_ ? 1 : 0; }

 private:
  double threshold_;
};

}  // namespace

TEST_CASE("symmetric Dirichlet reaches exactly 4 on a developable mesh") {
  ParamConfig config;
  config.optimizer.gradient_tolerance = 1e-7;
  config.optimizer.max_iterations = 500;
  const auto result = run(akvf::bent_bar(31, 6), config, {no_flips_allowed()}).result;
  CAPTURE(result.message);
  CHECK(result.status == TerminationStatus::kConverged);
  CHECK(result.trace.back().energy - 4.0 <= 1e-8);
  CHECK(result.trace.back().energy >= 4.0 - 1e-12);
}

TEST_CASE("the written UVs are the optimized map at the input's scale, in its vertex numbering") {
  ParamConfig config;
  config.optimizer.max_iterations = 10;
  akvf::TriMesh mesh = akvf::test::bumpy_disk(8, 8);
  mesh.V *= 3.0;  // area far from 1
  const auto setup = akvf::prepare_parameterization(mesh, "test", config);
  const auto result = akvf::run_parameterization(setup, config).result;
  const Eigen::MatrixXd UV = akvf::output_uv(setup, result.x);
  REQUIRE(UV.rows() == mesh.num_vertices());
  // The input mesh with the written map has the optimizer's energy.
  const akvf::DistortionObjective2D input(mesh.F, akvf::rest_triangles(mesh),
                                          akvf::energies_2d().create("symmetric-dirichlet", {}), mesh.num_vertices());
  CHECK(input.value(akvf::stack_uv(UV)) == doctest::Approx(setup.objective->value(result.x)).epsilon(1e-12));
  CHECK(setup.normalization.input_area ==
        doctest::Approx(akvf::surface_area(mesh) * setup.unit_scale * setup.unit_scale).epsilon(1e-14));
}

TEST_CASE("the energy never increases and row 0 is the initial map") {
  ParamConfig config;
  config.optimizer.max_iterations = 30;
  const auto result = run(akvf::test::bumpy_disk(12, 12), config, {no_flips_allowed()}).result;
  REQUIRE(result.trace.size() >= 2);
  CHECK(result.trace[0].iteration == 0);
  CHECK(result.trace[0].step == 0);
  for (std::size_t i = 1; i < result.trace.size(); ++i) {
    CHECK(result.trace[i].energy <= result.trace[i - 1].energy);
    CHECK(result.trace[i].seconds >= result.trace[i - 1].seconds);
  }
}

TEST_CASE("identity preconditioning runs end to end and is far slower than AKVF") {
  ParamConfig config;
  config.conformal = akvf::ConformalStart::kNever;  // the bar is developable: its conformal map is the minimum
  config.boundary_first = akvf::ConformalStart::kNever;
  config.optimizer.max_iterations = 40;
  config.optimizer.gradient_tolerance = 0;
  const auto akvf_run = run(akvf::bent_bar(31, 6), config).result;
  config.preconditioner = "identity";
  const auto identity_run = run(akvf::bent_bar(31, 6), config, {no_flips_allowed()}).result;
  CHECK(identity_run.trace.back().energy < identity_run.trace.front().energy);
  CHECK(identity_run.trace.back().energy - 4 > 100 * (akvf_run.trace.back().energy - 4));
}

TEST_CASE("a failed line search ends the run with a status and the last valid iterate") {
  ParamConfig config;
  const auto setup = akvf::prepare_parameterization(akvf::test::bumpy_disk(6, 6), "test", config);
  AscentPreconditioner ascent;
  const akvf::BacktrackingLineSearch search;
  const auto result = akvf::minimize(*setup.objective, ascent, search, setup.x0, config.optimizer);
  CHECK(result.status == TerminationStatus::kLineSearchFailed);
  CHECK(result.message.find("line search failed at iteration 1: search direction is not a descent direction") == 0);
  CHECK(result.x == setup.x0);
  CHECK_FALSE(akvf::is_normal_termination(result.status));
}

TEST_CASE("a non-finite direction or gradient ends the run with a status naming it, the last finite iterate is kept") {
  ParamConfig config;
  const auto setup = akvf::prepare_parameterization(akvf::test::bumpy_disk(6, 6), "test", config);
  const akvf::BacktrackingLineSearch search;

  PoisoningPreconditioner poisoning(3);
  const auto poisoned = akvf::minimize(*setup.objective, poisoning, search, setup.x0, config.optimizer);
  CHECK(poisoned.status == TerminationStatus::kNumericalFailure);
  CHECK(poisoned.message == "the preconditioner returned a non-finite direction at iteration 4 (entry 7 of " +
                                std::to_string(setup.x0.size()) + " is NaN); the last finite iterate is kept");
  CHECK(poisoned.trace.back().iteration == 3);
  CHECK(poisoned.x.allFinite());
  CHECK(setup.objective->value(poisoned.x) == poisoned.trace.back().energy);

  // The gradient of the new iterate is NaN: the objective cannot name an
  // element (the default names no variable, x itself is finite), the run
  // keeps the previous iterate.
  const NanGradientBelow nan_below(*setup.objective, 0.999 * setup.objective->value(setup.x0));
  PoisoningPreconditioner descent(1000);
  const auto stopped = akvf::minimize(nan_below, descent, search, setup.x0, config.optimizer);
  CHECK(stopped.status == TerminationStatus::kNumericalFailure);
  CHECK(stopped.message.find("produced a non-finite energy or gradient or an inverted element (0 inverted); the "
                             "previous iterate is kept") != std::string::npos);
  CHECK(stopped.x.allFinite());
  CHECK(setup.objective->value(stopped.x) == stopped.trace.back().energy);
  CHECK(stopped.trace.back().energy >= 0.999 * stopped.trace.front().energy);
}

// optimizer.cpp: below alpha_max no element inverts in exact arithmetic, so
// an inversion there is an element degenerate to rounding.
TEST_CASE("an element inverted by rounding within the flip-free bound ends the run as stalled, not failed") {
  ParamConfig config;
  const auto setup = akvf::prepare_parameterization(akvf::test::bumpy_disk(6, 6), "test", config);
  const akvf::BacktrackingLineSearch search;
  const InvertedBelow inverted_below(*setup.objective, 0.999 * setup.objective->value(setup.x0));
  akvf::AkvfPreconditioner2D akvf_preconditioner(*setup.objective);
  const auto result = akvf::minimize(inverted_below, akvf_preconditioner, search, setup.x0, config.optimizer);
  CHECK(result.status == TerminationStatus::kStalled);
  CHECK(akvf::is_normal_termination(result.status));
  CHECK(result.message.find("iteration 1 would invert 1 element(s) within the flip-free bound") == 0);
  CHECK(result.x == setup.x0);
  CHECK(result.trace.size() == 1);
}

TEST_CASE("a stall says after how many iterations and below which relative decrease, as a readable number") {
  ParamConfig config;
  config.optimizer.stall_tolerance = 1e6;  // every decrease counts as a stall
  config.optimizer.stall_iterations = 3;
  config.optimizer.gradient_tolerance = 0;
  const auto setup = akvf::prepare_parameterization(akvf::test::bumpy_disk(6, 6), "test", config);
  const akvf::BacktrackingLineSearch search;
  akvf::AkvfPreconditioner2D akvf_preconditioner(*setup.objective);
  const auto result = akvf::minimize(*setup.objective, akvf_preconditioner, search, setup.x0, config.optimizer);
  CHECK(result.status == TerminationStatus::kStalled);
  CHECK(result.message == "energy decreased by less than 1e+06 (relative) for 3 iterations");
  CHECK(result.trace.size() == 4);
  // The default tolerance, 1e-13, printed by std::to_string was "0.000000".
  CHECK(akvf::number_text(1e-13) == "1e-13");
  CHECK(akvf::number_text(0.001) == "0.001");
}

TEST_CASE("the distortion objective names the first bad element of an iterate") {
  ParamConfig config;
  const auto setup = akvf::prepare_parameterization(akvf::test::bumpy_disk(6, 6), "test", config);
  const akvf::Objective& objective = *setup.objective;
  const Eigen::MatrixXi& F = setup.disk.mesh.F;
  CHECK(objective.first_bad_element(setup.x0).empty());
  auto vertices = [&](int f) {
    return "(vertices " + std::to_string(F(f, 0)) + ", " + std::to_string(F(f, 1)) + ", " + std::to_string(F(f, 2)) +
           ")";
  };
  // The first face (in order) that uses vertex v.
  auto first_face_of = [&](int v) {
    for (int f = 0; f < F.rows(); ++f)
      if ((F.row(f).array() == v).any()) return f;
    return -1;
  };
  Eigen::VectorXd x = setup.x0;
  const int v = F(5, 1);
  x[2 * v + 1] = std::numeric_limits<double>::infinity();
  CHECK(objective.first_bad_element(x) == "triangle " + std::to_string(first_face_of(v)) + " " +
                                              vertices(first_face_of(v)) +
                                              " (numbered from 0): a corner has a non-finite coordinate");
  // Collapse triangle 0 onto its first corner: det = 0.
  x = setup.x0;
  for (int k = 1; k < 3; ++k) x.segment<2>(2 * F(0, k)) = x.segment<2>(2 * F(0, 0));
  CHECK(objective.first_bad_element(x) ==
        "triangle 0 " + vertices(0) + " (numbered from 0): inverted or collapsed (det = 0)");
}

TEST_CASE("callbacks can stop the run, iteration and time limits are statuses") {
  ParamConfig config;
  config.optimizer.gradient_tolerance = 0;
  auto stop_at_3 = [](const akvf::IterationSummary& s, const Eigen::VectorXd&) {
    return s.iteration == 3 ? akvf::CallbackAction::kStop : akvf::CallbackAction::kContinue;
  };
  const auto stopped = run(akvf::bent_bar(21, 5), config, {stop_at_3}).result;
  CHECK(stopped.status == TerminationStatus::kUserStopped);
  CHECK(stopped.trace.back().iteration == 3);

  config.optimizer.max_iterations = 5;
  CHECK(run(akvf::bent_bar(21, 5), config).result.status == TerminationStatus::kMaxIterations);
  config.optimizer.max_iterations = 100000;
  config.optimizer.time_limit = 1e-9;
  CHECK(run(akvf::bent_bar(21, 5), config).result.status == TerminationStatus::kTimeLimit);
}

TEST_CASE("an interrupt (Ctrl-C) ends the run after the current iteration with its iterate, for every method") {
  for (const char* method : {"akvf", "lbfgs"}) {
    CAPTURE(method);
    ParamConfig config;
    config.preconditioner = method;
    config.conformal = akvf::ConformalStart::kNever;  // the bar is developable: its conformal map is the minimum
    config.boundary_first = akvf::ConformalStart::kNever;
    config.optimizer.gradient_tolerance = 0;
    Eigen::VectorXd at_3;
    auto interrupt_at_3 = [&](const akvf::IterationSummary& s, const Eigen::VectorXd& x) {
      if (s.iteration == 3) {
        akvf::request_interrupt();  // what the SIGINT handler does
        at_3 = x;
      }
      return akvf::CallbackAction::kContinue;
    };
    const auto result = run(akvf::bent_bar(21, 5), config, {interrupt_at_3}).result;
    akvf::clear_interrupt();
    CHECK(result.status == TerminationStatus::kInterrupted);
    CHECK(akvf::to_string(result.status) == "interrupted");
    CHECK(akvf::is_normal_termination(result.status));
    CHECK(result.trace.back().iteration == 3);
    CHECK(result.x == at_3);
  }
}

TEST_CASE("invalid options and unknown names are reported") {
  ParamConfig config;
  config.optimizer.max_iterations = -1;
  CHECK(akvf::test::error_message([&] { run(akvf::bent_bar(), config); }) == "max iterations must be >= 0");
  config = {};
  config.preconditioner = "magic";
  // The built-in names in their order; a test that registers its own
  // preconditioner (test_extending.cpp) adds it before lbfgs when both run
  // in one process.
  const std::string message = akvf::test::error_message([&] { run(akvf::bent_bar(), config); });
  CHECK(message.find("unknown preconditioner 'magic' (valid: akvf, newton, akvf-newton, laplacian, slim, identity, ") ==
        0);
  CHECK(message.size() >= 8);
  CHECK(message.substr(message.size() - 8) == ", lbfgs)");
  config = {};
  config.energy = "arap2";
  CHECK(akvf::test::error_message([&] { run(akvf::bent_bar(), config); }).find("unknown energy 'arap2' (valid: ") == 0);
}

TEST_CASE("runs are bitwise deterministic for 1 and 2 threads") {
  ParamConfig config;
  config.optimizer.max_iterations = 15;
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(20, 20);
  std::vector<Eigen::VectorXd> results;
  for (int threads : {1, 1, 2, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    results.push_back(run(mesh, config).result.x);
  }
  for (const auto& x : results) CHECK(x == results.front());
}

namespace {

// The run from `setup` with its vertex ordering (and the analysis prepared
// with it, if any) is the run that orders and analyzes K itself, iterate for
// iterate, and analyzes once.
void check_shared_ordering(akvf::ParamSetup setup, const ParamConfig& config) {
  REQUIRE(setup.vertex_ordering);
  CHECK(setup.vertex_ordering->permutation.size() == static_cast<std::size_t>(setup.objective->num_vertices()));
  const akvf::ParamRun shared = akvf::run_parameterization(setup, config);
  setup.vertex_ordering.reset();  // the preconditioner orders K itself
  setup.analyses.reset();         // and analyzes it
  const akvf::ParamRun own = akvf::run_parameterization(setup, config);
  CHECK(shared.result.trace.size() == config.optimizer.max_iterations + 1);
  CHECK(shared.result.x == own.result.x);
  CHECK(shared.preconditioner_statistics.symbolic_analyses == 1);
}

}  // namespace

TEST_CASE(
    "the setup orders the vertex graph once (beside the Tutte solve below 100 K vertices, with K's analysis, where "
    "global injectivity orders its own), and the run with it has the iterates of its own") {
  ParamConfig config;
  config.optimizer.max_iterations = 2;
  config.conformal = akvf::ConformalStart::kNever;  // the flat grids' conformal maps are their minima
  config.boundary_first = akvf::ConformalStart::kNever;
  const akvf::TriMesh small = akvf::test::grid_disk(20, 20, 0.2, 3);
  const akvf::ParamSetup global = akvf::prepare_parameterization(small, "small", config);
  CHECK_FALSE(global.vertex_ordering);  // global injectivity
  CHECK_FALSE(global.analyses);
  for (const int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    ParamConfig local = config;
    local.global_injectivity = false;
    const akvf::ParamSetup setup = akvf::prepare_parameterization(small, "small", local);
    // K's analysis was prepared beside the Tutte solve too, for the run to take.
    REQUIRE(setup.analyses);
    const akvf::ElementMatrix2D K(setup.objective->elements(), setup.objective->num_vertices());
    CHECK(setup.analyses->holds(K.upper(), 2));
    check_shared_ordering(setup, local);
  }
  const akvf::TriMesh mesh = akvf::test::grid_disk(317, 317, 0.2, 3);  // 100 489 vertices
  check_shared_ordering(akvf::prepare_parameterization(mesh, "grid", config), config);
}

TEST_CASE("L-BFGS through Ceres decreases the energy without inverting, with our trace and statuses") {
  ParamConfig config;
  config.preconditioner = "lbfgs";
  config.optimizer.max_iterations = 40;
  config.optimizer.gradient_tolerance = 0;
  const auto setup = akvf::prepare_parameterization(akvf::test::bumpy_disk(10, 10), "test", config);
  const auto run = akvf::run_parameterization(setup, config, {no_flips_allowed()});
  const auto& result = run.result;
  CHECK(run.preconditioner_name == "lbfgs");
  CHECK(result.status == TerminationStatus::kMaxIterations);
  REQUIRE(result.trace.size() >= 2);
  CHECK(result.trace.front().iteration == 0);
  CHECK(result.trace.back().energy < result.trace.front().energy);
  for (std::size_t i = 1; i < result.trace.size(); ++i) CHECK(result.trace[i].energy <= result.trace[i - 1].energy);
  // Ceres' gradient norm is the Euclidean norm we report for every method.
  Eigen::VectorXd g;
  CHECK(setup.objective->value_and_gradient(result.x, &g) == doctest::Approx(result.trace.back().energy));
  CHECK(g.norm() == doctest::Approx(result.trace.back().grad_norm).epsilon(1e-9));
  CHECK(setup.objective->count_inverted(result.x) == 0);
}

TEST_CASE("every method reports a non-finite start with a status and a row 0") {
  for (const char* method : {"akvf", "lbfgs"}) {
    ParamConfig config;
    config.preconditioner = method;
    config.energy = "exp-symmetric-dirichlet";
    config.energy_settings.exponent = 1e6;  // exp overflows at the start
    const auto result = run(akvf::test::bumpy_disk(5, 5), config).result;
    CHECK(result.status == TerminationStatus::kNumericalFailure);
    // The symmetric Dirichlet warm start's rows, then row 0 of the run.
    REQUIRE(result.trace.size() >= 2);
    for (std::size_t i = 0; i + 1 < result.trace.size(); ++i) CHECK(result.trace[i].warm_start);
    CHECK_FALSE(result.trace.back().warm_start);
    CHECK(result.trace.back().iteration == 0);
    CHECK(result.trace.back().energy == std::numeric_limits<double>::infinity());
    CHECK(result.message.find("; first bad element: triangle ") != std::string::npos);
  }
}

TEST_CASE("every energy with every preconditioner and line search: 30 iterations, no flip, energy never rises") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(9, 9);
  for (const auto& [energy, unused] : akvf::energies_2d().entries()) {
    std::vector<std::string> methods;
    for (const auto& [name, description] : akvf::preconditioners_2d().entries()) methods.push_back(name);
    methods.push_back(akvf::kLbfgsMethod);
    for (const std::string& method : methods)
      for (const char* line_search : {"backtracking", "wolfe-bisection"}) {
        if (method == akvf::kLbfgsMethod && std::string(line_search) != "backtracking") continue;  // Ceres' own
        const std::string label = energy + " / " + method + " / " + line_search;
        INFO(label);
        ParamConfig config;
        config.energy = energy;
        config.energy_settings.exponent = 0.1;
        config.preconditioner = method;
        config.line_search = line_search;
        config.optimizer.max_iterations = 30;
        config.optimizer.gradient_tolerance = 0;
        const auto result = run(mesh, config, {no_flips_allowed()}).result;
        INFO(result.message);
        CHECK(akvf::is_normal_termination(result.status));
        REQUIRE(result.trace.size() >= 2);
        CHECK(std::isfinite(result.trace.front().energy));
        for (std::size_t i = 1; i < result.trace.size(); ++i)
          CHECK(result.trace[i].energy <= result.trace[i - 1].energy);
        CHECK(result.trace.back().energy < result.trace.front().energy);
      }
  }
}

TEST_CASE("AQP acceleration keeps the energy non-increasing and never flips") {
  ParamConfig config;
  config.preconditioner = "laplacian";
  config.acceleration = akvf::Acceleration::kOn;
  config.optimizer.max_iterations = 50;
  config.optimizer.gradient_tolerance = 0;
  const auto result = run(akvf::test::bumpy_disk(12, 12), config, {no_flips_allowed()}).result;
  for (std::size_t i = 1; i < result.trace.size(); ++i) CHECK(result.trace[i].energy <= result.trace[i - 1].energy);
}

TEST_CASE("the assembled gradient of E matches finite differences of E for every energy") {
  akvf::TriMesh mesh = akvf::test::bumpy_disk(5, 5);
  akvf::normalize_to_unit_area(&mesh);
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(mesh, 0.2, 3) * 0.9);
  akvf::EnergySettings settings;
  settings.exponent = 0.1;
  for (const auto& entry : akvf::energies_2d().entries()) {
    const std::string& name = entry.first;  // clang 14 cannot capture a structured binding
    CAPTURE(name);
    const akvf::DistortionObjective2D objective(mesh.F, akvf::rest_triangles(mesh),
                                                akvf::energies_2d().create(name, settings), mesh.num_vertices());
    Eigen::VectorXd g;
    const double energy = objective.value_and_gradient(x, &g);
    REQUIRE(std::isfinite(energy));
    CHECK(objective.value(x) == energy);  // bitwise: the line search and the trace see the same E
    const double h = 1e-7;
    for (int i = 0; i < x.size(); i += 3) {
      Eigen::VectorXd plus = x, minus = x;
      plus[i] += h;
      minus[i] -= h;
      const double fd = (objective.value(plus) - objective.value(minus)) / (2 * h);
      CHECK(g[i] == doctest::Approx(fd).epsilon(1e-5).scale(std::max(1.0, g.norm())));
    }
  }
}

namespace {

// A SwitchingPreconditioner factory of identity preconditioners that
// checks the reason it is told.
akvf::SwitchingPreconditioner::Factory identity_expecting(akvf::SwitchReason expected) {
  return [expected](akvf::Preconditioner&, akvf::SwitchReason why) {
    CHECK(why == expected);
    return std::make_unique<akvf::IdentityPreconditioner>();
  };
}

}  // namespace

// switching_preconditioner.h: the switch needs `patience` consecutive steps
// set by curvature (below half the flip-free bound) that do not show AKVF to
// be Newton-like (backtracked to a step of at least sqrt(rho) times AKVF's
// isometric Newton step).
TEST_CASE("akvf-newton switches after two curvature-set steps that do not show AKVF to be Newton-like") {
  akvf::SwitchRule rule;
  rule.isometric_step = 0.25;  // symmetric Dirichlet on a unit-area mesh
  rule.backtracking_factor = 0.5;
  struct Step {
    double step, max_step;
    bool backtracked;
  };
  auto switch_after = [&](const std::vector<Step>& steps) {
    akvf::SwitchingPreconditioner p("test", std::make_unique<akvf::IdentityPreconditioner>(),
                                    identity_expecting(akvf::SwitchReason::kCurvatureSet), rule);
    const Eigen::VectorXd x = Eigen::VectorXd::Zero(4), g = Eigen::VectorXd::Ones(4);
    p.update({x, g, 1.0, 1});
    int k = 2;
    for (const Step& s : steps) p.update({x, g, 1.0, k++, s.step, s.max_step, s.backtracked});
    return p.switch_iteration();
  };
  // Backtracked to AKVF's isometric step 1/c on a nearly isometric map: never.
  CHECK(switch_after({{0.25, 100, true}, {0.25, 100, true}, {0.5, 100, true}, {0.25, 100, true}}) == 0);
  // Backtracked below sqrt(rho)/c twice in a row: at the next iteration.
  CHECK(switch_after({{0.25, 100, true}, {0.125, 100, true}, {0.0625, 100, true}, {0.25, 100, true}}) == 4);
  // The first trial accepted far inside the bound says nothing: it counts.
  CHECK(switch_after({{0.25, 100, false}, {1.0, 2.5, false}}) == 3);
  // Not consecutive: never.
  CHECK(switch_after({{0.125, 100, true}, {0.25, 100, true}, {0.125, 100, true}, {0.5, 100, true}}) == 0);
  // Short, but the flip-free bound set them (0.125 >= half of 0.2): never.
  CHECK(switch_after({{0.125, 0.2, true}, {0.125, 0.2, true}, {0.125, 0.2, true}}) == 0);
  // Without an isometric step (infinity) every curvature-set step counts.
  rule.isometric_step = std::numeric_limits<double>::infinity();
  CHECK(switch_after({{0.25, 100, true}, {0.25, 100, true}}) == 3);
}

// switching_preconditioner.h: Newton steps whose first trial, below the unit
// step, was set by a flip-free bound closer than the step before's and
// accepted at once send the run back to the first preconditioner after
// `patience` of them; each return doubles the patience of the next switch to
// the second.
TEST_CASE("akvf-newton returns to AKVF after two Newton steps closing in on a collapse") {
  akvf::SwitchRule rule;  // isometric step infinity: every curvature-set step counts
  struct Step {
    double step, max_step;
    bool backtracked;
  };
  int built_second = 0, built_first = 0;
  std::vector<akvf::SwitchReason> reasons;
  akvf::SwitchingPreconditioner p(
      "test", std::make_unique<akvf::IdentityPreconditioner>(),
      [&](akvf::Preconditioner&, akvf::SwitchReason why) {
        ++built_second;
        reasons.push_back(why);
        return std::make_unique<akvf::IdentityPreconditioner>();
      },
      rule,
      [&](akvf::Preconditioner&, akvf::SwitchReason why) {
        ++built_first;
        reasons.push_back(why);
        return std::make_unique<akvf::IdentityPreconditioner>();
      });
  const Eigen::VectorXd x = Eigen::VectorXd::Zero(4), g = Eigen::VectorXd::Ones(4);
  int k = 1;
  auto run = [&](const std::vector<Step>& steps) {
    for (const Step& s : steps) p.update({x, g, 1.0, k++, s.step, s.max_step, s.backtracked});
  };
  const Step curvature{0.25, 100, true}, unit{1.0, 5, false};
  auto bound = [](double max_step) { return Step{0.8 * max_step, max_step, false}; };
  run({{0, 0, false}, curvature, curvature});  // iterations 1-3: switch at 3
  CHECK(p.switches() == std::vector<int>{3});
  CHECK(p.in_second());
  // One bound-set Newton step, then a unit step: the count starts over.
  run({bound(0.5), unit, bound(0.5)});  // iterations 4-6
  CHECK(p.switches() == std::vector<int>{3});
  // Bound-set steps whose bound recedes do not count (MIPS on camelhead).
  run({bound(0.6), bound(1.1), bound(1.2)});  // iterations 7-9
  CHECK(p.switches() == std::vector<int>{3});
  // A backtracked short step is the curvature's, not the bound's.
  run({{0.4, 0.5, true}, bound(0.2), bound(0.04)});  // iterations 10-12: back at 12
  CHECK(p.switches() == std::vector<int>{3, 12});
  CHECK(!p.in_second());
  CHECK(built_second == 1);
  CHECK(built_first == 1);
  CHECK(reasons == std::vector<akvf::SwitchReason>{akvf::SwitchReason::kCurvatureSet, akvf::SwitchReason::kClosingIn});
  // The next switch to Newton needs twice the patience: 4 curvature-set steps.
  run({curvature, curvature, curvature});
  CHECK(p.switches() == std::vector<int>{3, 12});
  run({curvature});
  CHECK(p.switches() == std::vector<int>{3, 12, 16});
  CHECK(p.report().find("from iteration 12 identity") != std::string::npos);
  CHECK(p.report().find("from iteration 16 identity") != std::string::npos);
}

// switching_preconditioner.h: Newton steps held by a bound below far_share
// of the unit step count toward the return whether or not the bound closes
// in (MIPS on hilbert_b: 0.00087, then 0.00097).
TEST_CASE("akvf-newton returns to AKVF after two Newton steps held far short of the unit step") {
  akvf::SwitchRule rule;  // isometric step infinity: every curvature-set step counts
  struct Step {
    double step, max_step;
    bool backtracked;
  };
  auto switches_after = [&](const std::vector<Step>& steps) {
    akvf::SwitchingPreconditioner p("test", std::make_unique<akvf::IdentityPreconditioner>(),
                                    identity_expecting(akvf::SwitchReason::kCurvatureSet), rule,
                                    identity_expecting(akvf::SwitchReason::kClosingIn));
    const Eigen::VectorXd x = Eigen::VectorXd::Zero(4), g = Eigen::VectorXd::Ones(4);
    int k = 1;
    const Step curvature{0.25, 100, true};
    for (const Step& s : std::vector<Step>{{0, 0, false}, curvature, curvature})  // switch at 3
      p.update({x, g, 1.0, k++, s.step, s.max_step, s.backtracked});
    for (const Step& s : steps) p.update({x, g, 1.0, k++, s.step, s.max_step, s.backtracked});
    return p.switches();
  };
  auto bound = [](double max_step) { return Step{0.8 * max_step, max_step, false}; };
  // Receding bounds far below the unit step: back at the second.
  CHECK(switches_after({bound(0.00087), bound(0.00097)}) == std::vector<int>{3, 5});
  // Receding bounds above far_share: they stay.
  CHECK(switches_after({bound(0.02), bound(0.03), bound(0.05)}) == std::vector<int>{3});
  // Far below, but backtracked: the curvature set the step.
  CHECK(switches_after({{0.0004, 0.00097, true}, bound(0.00097), {0.0004, 0.00097, true}}) == std::vector<int>{3});
  // A share of 1 puts every bound-set step far.
  rule.far_share = 1;
  CHECK(switches_after({bound(0.5), bound(0.6)}) == std::vector<int>{3, 5});
  rule.far_share = 0;
  CHECK(switches_after({bound(0.00087), bound(0.00097)}) == std::vector<int>{3});
}

// switching_preconditioner.h: bound-set AKVF steps that each leave more than
// stall_ratio of the gap E - E_lb switch to Newton after `patience` of them;
// a bound that keeps more than half the last is not closing in.
TEST_CASE(
    "akvf-newton switches after two bound-set steps that stall, and does not return on a bound that barely shrinks") {
  akvf::SwitchRule rule;
  rule.isometric_step = 0.25;
  rule.energy_lower_bound = 4;  // symmetric Dirichlet
  struct Step {
    double energy, step, max_step;
    bool backtracked;
  };
  auto switches_after = [&](double start, const std::vector<Step>& steps) {
    akvf::SwitchingPreconditioner p("test", std::make_unique<akvf::IdentityPreconditioner>(),
                                    identity_expecting(akvf::SwitchReason::kStalled), rule,
                                    identity_expecting(akvf::SwitchReason::kClosingIn));
    const Eigen::VectorXd x = Eigen::VectorXd::Zero(4), g = Eigen::VectorXd::Ones(4);
    p.update({x, g, start, 1});
    int k = 2;
    for (const Step& s : steps) p.update({x, g, s.energy, k++, s.step, s.max_step, s.backtracked});
    return p.switches();
  };
  auto bound = [](double energy, double max_step) { return Step{energy, 0.8 * max_step, max_step, false}; };
  // tricera_b subdivided: 144 -> 72 (half the gap), then 72 -> 65 -> 62.5
  // (ratios 0.90, 0.96): the second stalled step switches.
  CHECK(switches_after(144, {bound(72, 4e-5), bound(65, 3e-5), bound(62.5, 1e-5)}) == std::vector<int>{4});
  // horse_b: 1150 -> 385 -> 147 -> 110 -> 100 -> 19: never two in a row.
  CHECK(switches_after(1150, {bound(385, 2e-5), bound(147, 2e-4), bound(110, 2e-4), bound(100, 7e-5), bound(19, 5e-3)})
            .empty());
  // horse_b near its minimum (E* = 4.089): bound-set steps that keep 0.98
  // and 0.99 of E - 4, but the bound (0.26, 0.24) let them reach more than
  // half the model's decrease (t / (1/c) above 1 - 1/sqrt(2)): not stalled.
  CHECK(switches_after(4.1289, {bound(4.0928, 0.26), bound(4.0906, 0.24), bound(4.0899, 0.18)}).empty());
  // A curvature-set step and a stalled one count together; the last names the reason.
  CHECK(switches_after(144, {{140, 1e-3, 1, true}, bound(139, 1e-5), {138, 1e-3, 1, true}}) == std::vector<int>{3});
  // ARAP on jittered horse_b (E_lb = 0, AKVF's isometric step 1): unit steps
  // the curvature set, each followed by one the bound set keeping 0.99 of E.
  rule.isometric_step = 1;
  rule.energy_lower_bound = 0;
  CHECK(switches_after(0.05134, {{0.05130, 1, 2.5, false}, bound(0.05097, 0.2995)}) == std::vector<int>{3});
  // A step the bound set that gains more than 0.15 of the gap breaks the run.
  CHECK(switches_after(0.05134, {{0.05130, 1, 2.5, false}, bound(0.04, 0.2995), {0.0399, 1, 2.5, false}}).empty());
  rule.isometric_step = 0.25;
  // Without a known infimum no step stalls.
  rule.energy_lower_bound = -std::numeric_limits<double>::infinity();
  CHECK(switches_after(144, {bound(143, 1e-5), bound(142, 1e-5), bound(141, 1e-5)}).empty());
  // In Newton's phase, bounds that shrink by less than half (0.713, 0.710,
  // 0.693: Newton's far phase on tricera_b subdivided) do not send it back;
  // one that falls fivefold twice does.
  rule.energy_lower_bound = 4;
  const Step stalled_1 = bound(130, 4e-5), stalled_2 = bound(120, 3e-5);  // ratios 0.90, 0.92
  CHECK(switches_after(144, {stalled_1, stalled_2, bound(50, 0.713), bound(40, 0.710), bound(31, 0.693)}) ==
        std::vector<int>{3});
  CHECK(switches_after(144, {stalled_1, stalled_2, bound(50, 0.7), bound(45, 0.14), bound(44, 0.028)}) ==
        std::vector<int>{3, 6});
}

// switching_preconditioner.h: bound-set Newton steps that keep more than
// stall_ratio of E - E_lb, and more than AKVF's last bound-set step kept,
// while the model promised (g^T P^-1 g / 2; P = I here) more than
// 1 - stall_ratio of it, send the run back to AKVF after `patience` of them.
TEST_CASE("akvf-newton returns to AKVF after two Newton steps held by the bound behind AKVF's pace") {
  akvf::SwitchRule rule;
  rule.isometric_step = 1;      // 2D AKVF's scaled K
  rule.energy_lower_bound = 0;  // ARAP
  struct Step {
    double energy, step, max_step;
  };
  // AKVF's bound-set step to `akvf_energy` from 1 (at 0.8 of the model's
  // minimizer: not stalled, whatever it keeps), two unit steps the
  // curvature set (the switch at 4), then Newton's steps with the gradient
  // g = gradient_scale (1, 1, 1, 1), whose promise is 2 gradient_scale^2.
  auto switches_after = [&](double akvf_energy, double gradient_scale, const std::vector<Step>& newton) {
    const auto any_reason = [](akvf::Preconditioner&, akvf::SwitchReason) {
      return std::make_unique<akvf::IdentityPreconditioner>();
    };
    akvf::SwitchingPreconditioner p("test", std::make_unique<akvf::IdentityPreconditioner>(), any_reason, rule,
                                    any_reason);
    const Eigen::VectorXd x = Eigen::VectorXd::Zero(4);
    Eigen::VectorXd g = Eigen::VectorXd::Ones(4), d;
    std::vector<Step> steps{{akvf_energy, 0.4, 0.5}, {0.95 * akvf_energy, 1, 2.5}, {0.9 * akvf_energy, 1, 2.5}};
    steps.insert(steps.end(), newton.begin(), newton.end());
    p.update({x, g, 1.0, 1});
    p.apply(g, &d);
    int k = 2;
    for (const Step& s : steps) {
      p.update({x, g, s.energy, k++, s.step, s.max_step, false});
      g = Eigen::VectorXd::Constant(4, gradient_scale);
      p.apply(g, &d);
    }
    return p.switches();
  };
  // Bounds that neither close in nor fall below far_share; each step keeps
  // 0.97 of E (jittered hilbert_b's strips: 0.95-0.99).
  const std::vector<Step> slow{{0.97 * 0.54, 0.24, 0.3}, {0.97 * 0.97 * 0.54, 0.2, 0.25}};
  // AKVF's bound-set step kept 0.6 and Newton's model promises 2 * 0.25 = 0.5
  // against E = 0.54: back at the second Newton step.
  CHECK(switches_after(0.6, 0.5, slow) == std::vector<int>{4, 6});
  // The model promises 2e-4 (4e-4 of E): near a minimum above E_lb, Newton stays.
  CHECK(switches_after(0.6, 0.01, slow) == std::vector<int>{4});
  // AKVF's own bound-set step kept 0.99: Newton's 0.97 is ahead of it.
  CHECK(switches_after(0.99, 0.5, {{0.97 * 0.8910, 0.24, 0.3}, {0.97 * 0.97 * 0.8910, 0.2, 0.25}}) ==
        std::vector<int>{4});
  // Steps that each keep 0.8 of E, below stall_ratio: Newton stays.
  CHECK(switches_after(0.6, 0.5, {{0.8 * 0.54, 0.24, 0.3}, {0.64 * 0.54, 0.2, 0.25}}) == std::vector<int>{4});
}

// switching_preconditioner.h: with soft constraints, a bound-set step after
// which the constraints still carry more than half of E - E_lb switches at
// once; once they are met, or when the curvature set the step, it does not.
TEST_CASE("akvf-newton switches at once after a bound-set step that left the soft constraints far") {
  akvf::SwitchRule rule;
  rule.isometric_step = 1;  // 3D AKVF's secant scale
  rule.energy_lower_bound = 6;
  double distortion = 6.37;  // the SLIM cube after its first step
  rule.distortion_energy = [&](const Eigen::VectorXd&) { return distortion; };
  auto switches_after = [&](double energy, double step, double max_step, bool backtracked) {
    akvf::SwitchingPreconditioner p("test", std::make_unique<akvf::IdentityPreconditioner>(),
                                    identity_expecting(akvf::SwitchReason::kConstraintsFar), rule);
    const Eigen::VectorXd x = Eigen::VectorXd::Zero(4), g = Eigen::VectorXd::Ones(4);
    p.update({x, g, 336927, 1});
    p.update({x, g, energy, 2, step, max_step, backtracked});
    return p.switches();
  };
  // The first step 0.8 of its bound 1.03, the constraints 99.9 % of E - E_lb.
  CHECK(switches_after(10408.7, 0.824, 1.03, false) == std::vector<int>{2});
  // The same share after a unit step, or a step the line search shortened.
  CHECK(switches_after(10408.7, 1, 2.85, false).empty());
  CHECK(switches_after(10408.7, 0.4, 1.03, true).empty());
  // A lifted mesh: its first step met the constraints.
  distortion = 6.0476;
  CHECK(switches_after(6.0476001, 0.824, 1.03, false).empty());
  // Without added terms the rule is off.
  rule.distortion_energy = nullptr;
  CHECK(switches_after(10408.7, 0.824, 1.03, false).empty());
}
