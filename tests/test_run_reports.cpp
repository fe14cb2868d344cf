// What a run reports: a warm start with its own limit, time and trace rows;
// traces that never hold NaN; the reason of a stalled run; manifests that
// cannot read outside the data folder unless they say so.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "akvf/internal/parameterization.h"
#include "cli/akvf_cli.h"
#include "cli/exit_codes.h"
#include "cli/run_reporting.h"
#include "experiments/report/trace_csv.h"
#include "experiments/runner/manifest.h"
#include "framework/optimization/iteration_limit.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

namespace fs = std::filesystem;
using akvf::ParamConfig;
using akvf::TerminationStatus;

namespace {

fs::path scratch(const std::string& name) { return akvf::test::scratch_dir("run_reports_" + name); }

std::string trace_text(const akvf::OptimizerResult& result) {
  std::ostringstream out;
  akvf::write_trace_csv(out, result);
  return out.str();
}

// 101 rows, iterations 0-100, whose gradient norm halves every 10
// iterations, from 1 to 2^-10.
std::vector<akvf::IterationSummary> halving_gradient_trace() {
  std::vector<akvf::IterationSummary> trace(101);
  for (int k = 0; k <= 100; ++k) {
    trace[static_cast<std::size_t>(k)].iteration = k;
    trace[static_cast<std::size_t>(k)].grad_norm = std::pow(0.5, k / 10.0);
  }
  return trace;
}

}  // namespace

TEST_CASE("the exponential energies' warm start has its own limit, counts its time and opens the trace") {
  ParamConfig config;
  config.energy = "exp-symmetric-dirichlet";
  config.energy_settings.exponent = 60;  // exp(60 D) overflows at the Tutte map's worst triangles
  config.optimizer.max_iterations = 2;   // the run's limit does not cap the warm start
  config.warm_start_max_iterations = 1000;
  config.conformal = akvf::ConformalStart::kNever;  // from the Tutte map
  config.boundary_first = akvf::ConformalStart::kNever;
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(9, 9);
  akvf::ParamSetup setup = akvf::prepare_parameterization(mesh, "b.obj", config);
  REQUIRE(setup.warm_start.trace.size() >= 2);
  CHECK(setup.warm_start.status == TerminationStatus::kConverged);
  REQUIRE(setup.warnings.size() == 1);
  CHECK(setup.warnings[0].find("starting from the symmetric Dirichlet minimizer instead (warm start: ") !=
        std::string::npos);
  const akvf::OptimizerResult result = akvf::run_parameterization(setup, config).result;
  const std::size_t warm_rows = setup.warm_start.trace.size();
  REQUIRE(result.trace.size() == warm_rows + 3);  // the run's rows 0, 1, 2
  for (std::size_t i = 0; i < warm_rows; ++i) CHECK(result.trace[i].warm_start);
  CHECK(result.trace[warm_rows].iteration == 0);
  CHECK(result.trace[warm_rows].seconds >= setup.warm_start.trace.back().seconds);
  const std::string csv = trace_text(result);
  CHECK(csv.find(",warm-start\n") != std::string::npos);
  CHECK(csv.find(",max-iterations\n") != std::string::npos);

  // A warm start stopped by its own limit is not called a minimizer.
  config.warm_start_max_iterations = 1;
  setup = akvf::prepare_parameterization(mesh, "b.obj", config);
  REQUIRE(setup.warnings.size() == 1);
  CHECK(setup.warnings[0].find("the symmetric Dirichlet map reached") != std::string::npos);
  CHECK(setup.warnings[0].find("minimizer") == std::string::npos);
  CHECK(setup.warm_start.trace.back().iteration == 1);
}

TEST_CASE("an exponential energy that overflows at the symmetric Dirichlet minimizer is reached by halving k") {
  // A spike the flat map cannot follow: the symmetric Dirichlet minimizer
  // leaves its triangles stretched, where exp(10 f) overflows and exp(5 f)
  // does not.
  akvf::TriMesh mesh = akvf::test::grid_disk(9, 9);
  mesh.V(40, 2) = 2;
  ParamConfig config;
  config.energy = "exp-symmetric-dirichlet";
  config.energy_settings.exponent = 10;
  config.optimizer.max_iterations = 3;
  akvf::ParamSetup setup = akvf::prepare_parameterization(mesh, "spike.obj", config);
  REQUIRE(setup.warnings.size() == 1);
  CHECK(setup.warnings[0].find("starting from the symmetric Dirichlet minimizer minimized further with the exponent 5 "
                               "instead (warm start: ") != std::string::npos);
  const akvf::OptimizerResult result = akvf::run_parameterization(setup, config).result;
  const std::size_t warm_rows = setup.warm_start.trace.size();
  REQUIRE(result.trace.size() > warm_rows);
  for (std::size_t i = 1; i < warm_rows; ++i) CHECK(result.trace[i].iteration == result.trace[i - 1].iteration + 1);
  // The run starts at a finite energy (its own steps then meet E's
  // round-off: the spike keeps it near 1e143).
  for (std::size_t i = warm_rows; i < result.trace.size(); ++i) {
    CHECK(std::isfinite(result.trace[i].energy));
    if (i > warm_rows) CHECK(result.trace[i].energy <= result.trace[i - 1].energy);
  }

  // At k = 20 every stage ends short of a finite energy: the run stops at
  // once and says so.
  config.energy_settings.exponent = 20;
  setup = akvf::prepare_parameterization(mesh, "spike.obj", config);
  REQUIRE(setup.warnings.size() == 1);
  CHECK(setup.warnings[0].find("minimized further with the exponent 5") != std::string::npos);
  CHECK(setup.warnings[0].find("the run will stop at once (a smaller exponent may keep the energy finite)") !=
        std::string::npos);
}

TEST_CASE(
    "after a warm start the default starts in its Newton phase only where the energy is within e of its infimum") {
  // exp(k D) overflows at the Tutte map's worst triangles for both meshes;
  // the flat grid's symmetric Dirichlet minimizer is an isometry (E = E_lb),
  // the bumpy disk's leaves k (D - 4) well above 1 on average.
  struct Case {
    akvf::TriMesh mesh;
    const char* report_start;
  };
  for (const Case& c :
       {Case{akvf::test::grid_disk(9, 9), "from the start newton: "}, Case{akvf::test::bumpy_disk(9, 9), "akvf: "}}) {
    ParamConfig config;
    config.energy = "exp-symmetric-dirichlet";
    config.energy_settings.exponent = 60;
    config.conformal = akvf::ConformalStart::kNever;  // the Tutte map, where the energy overflows
    config.boundary_first = akvf::ConformalStart::kNever;
    const akvf::ParamSetup setup = akvf::prepare_parameterization(c.mesh, "b.obj", config);
    REQUIRE(setup.warm_start.trace.size() >= 2);
    const double ratio = setup.objective->value(setup.x0) / setup.objective->lower_bound();
    CAPTURE(ratio);
    CHECK((ratio < std::exp(1.0)) == (std::string(c.report_start) != "akvf: "));
    const akvf::ParamRun run = akvf::run_parameterization(setup, config);
    CHECK(run.preconditioner_name == "akvf-newton");
    CHECK(run.preconditioner_report.rfind(c.report_start, 0) == 0);
    CHECK(akvf::is_normal_termination(run.result.status));
  }
}

TEST_CASE("a trace never holds NaN: overflowing energies end as numerical-failure naming an element") {
  for (const char* energy : {"amips", "exp-symmetric-dirichlet"})
    for (const char* method : {"akvf", "newton", "lbfgs"}) {
      CAPTURE(energy);
      CAPTURE(method);
      ParamConfig config;
      config.energy = energy;
      config.preconditioner = method;
      config.energy_settings.exponent = 1000;
      config.optimizer.max_iterations = 20;
      const akvf::ParamSetup setup = akvf::prepare_parameterization(akvf::test::bumpy_disk(7, 7), "b.obj", config);
      const akvf::OptimizerResult result = akvf::run_parameterization(setup, config).result;
      const std::string csv = trace_text(result);
      CHECK(csv.find("nan") == std::string::npos);
      if (!akvf::is_normal_termination(result.status)) {
        CHECK(result.status == TerminationStatus::kNumericalFailure);
        CHECK(result.message.find("first bad element: triangle ") != std::string::npos);
      }
    }
}

TEST_CASE("a stalled run says why in the status line and the trace") {
  akvf::OptimizerResult result;
  result.trace.resize(1);
  result.status = TerminationStatus::kStalled;
  result.message = "Ceres: Parameter tolerance reached. Relative step_norm: 0, epsilon: 0";
  CHECK(akvf::summary_line(result).find(
            "status stalled (Ceres: Parameter tolerance reached. Relative step_norm: 0, epsilon: 0) after 0 "
            "iterations") == 0);
  const std::string csv = trace_text(result);
  CHECK(csv.find(",stalled (Ceres: Parameter tolerance reached. Relative step_norm: 0; epsilon: 0)\n") !=
        std::string::npos);
  result.status = TerminationStatus::kConverged;
  CHECK(akvf::summary_line(result).find("status converged after") == 0);
}

TEST_CASE("a run at its iteration limit says how fast it was converging") {
  // The gradient norm halves every 10 iterations, from 1 at iteration 0 to
  // 2^-10 at 100; the blocks 81-90 and 91-100 (a tenth each) have their
  // least values a half apart, and 1e-6 needs log2(1024e-6) / (1/10) more,
  // 99.3.
  akvf::OptimizerResult result;
  result.trace = halving_gradient_trace();
  result.status = TerminationStatus::kMaxIterations;
  result.message = akvf::iteration_limit_message(result.trace, 1e-6, 100);
  CHECK(result.message ==
        "reached 100 iterations; the least gradient norm of iterations 81-90 was 0.00195312, of 91-100 0.000976562 "
        "(tolerance 1e-06): about 100 more iterations at that rate");
  CHECK(akvf::summary_line(result).find("\nnot converged: reached 100 iterations; the least gradient norm") !=
        std::string::npos);
  // An oscillating gradient (the line search alternating between step
  // lengths) is compared at its least values: here every third iteration
  // ten times the others, the last among them, which alone would read as a
  // rise from iteration 90.
  for (akvf::IterationSummary& row : result.trace)
    if (row.iteration % 3 == 1) row.grad_norm *= 10;
  CHECK(akvf::iteration_limit_message(result.trace, 1e-6, 100).find("was 0.00195312, of 91-100 0.00104665") !=
        std::string::npos);
  for (akvf::IterationSummary& row : result.trace) row.grad_norm = 1;
  CHECK(akvf::iteration_limit_message(result.trace, 1e-6, 100) ==
        "reached 100 iterations; the least gradient norm of iterations 81-90 was 1, of 91-100 1 (tolerance 1e-06): it "
        "did not fall");
  CHECK(akvf::iteration_limit_message({}, 1e-6, 0) == "reached 0 iterations");
  // With no gradient target (--grad-tol 0, a fixed budget) there is no
  // estimate to give.
  for (akvf::IterationSummary& row : result.trace) row.grad_norm = std::pow(0.5, row.iteration / 10.0);
  CHECK(akvf::iteration_limit_message(result.trace, 0, 100) ==
        "reached 100 iterations; the least gradient norm of iterations 81-90 was 0.00195312, of 91-100 0.000976562 "
        "(tolerance 0)");
}

TEST_CASE("a run at its iteration limit says what held its steps") {
  // 100 iterations; the last tenth (91-100) decides.
  akvf::OptimizerResult result;
  result.trace = halving_gradient_trace();
  const std::string rate =
      "reached 100 iterations; the least gradient norm of iterations 81-90 was 0.00195312, of 91-100 0.000976562 "
      "(tolerance 1e-06): about 100 more iterations at that rate";
  auto set_last_tenth = [&](auto&& set) {
    for (int k = 91; k <= 100; ++k) set(k, &result.trace[static_cast<std::size_t>(k)]);
  };
  // The search took a quarter of its unit first trial (or less, once).
  set_last_tenth([](int k, akvf::IterationSummary* row) {
    row->initial_step = 1;
    row->step = k == 95 ? 0.125 : 0.25;
  });
  CHECK(akvf::iteration_limit_message(result.trace, 1e-6, 100) ==
        rate +
            "; the line search shortened 10 of the last 10 first trials (to a median 0.25 of them): the "
            "preconditioner's model is softer than the energy along its directions");
  // The bound set the first trial, and it was taken.
  set_last_tenth([](int k, akvf::IterationSummary* row) {
    row->initial_step = row->step = 0.001 * k;
    row->bound_cut_initial_step = true;
  });
  CHECK(akvf::iteration_limit_message(result.trace, 1e-6, 100) ==
        rate +
            "; the flip-free bound cut 10 of the last 10 first trials (to a median step of 0.096): elements near "
            "collapse hold the steps");
  // The direction's own step, taken at once.
  set_last_tenth([](int, akvf::IterationSummary* row) {
    row->initial_step = row->step = 1;
    row->bound_cut_initial_step = false;
  });
  CHECK(akvf::iteration_limit_message(result.trace, 1e-6, 100) ==
        rate +
            "; 10 of the last 10 steps were the direction's own, accepted at once: the preconditioner's model is "
            "stiffer than the energy in some directions, where the steps fall short");
  // A Wolfe search took more than its first trial.
  set_last_tenth([](int, akvf::IterationSummary* row) { row->step = 2; });
  CHECK(akvf::iteration_limit_message(result.trace, 1e-6, 100) ==
        rate +
            "; the line search lengthened 10 of the last 10 first trials: the preconditioner's model is stiffer than "
            "the energy along its directions");
  // No kind makes up more than half: the counts.
  set_last_tenth([](int k, akvf::IterationSummary* row) {
    row->initial_step = k <= 97 ? 1 : 0.5;
    row->bound_cut_initial_step = k > 97;
    row->step = k <= 94 ? 0.5 : row->initial_step;
  });
  CHECK(akvf::iteration_limit_message(result.trace, 1e-6, 100) ==
        rate +
            "; of the last 10 steps the line search shortened 4, the flip-free bound cut 3, 3 were the "
            "direction's own");
  // A solver whose rows do not say what the first trial was (L-BFGS): no clause.
  set_last_tenth([](int, akvf::IterationSummary* row) { row->initial_step = 0; });
  CHECK(akvf::iteration_limit_message(result.trace, 1e-6, 100) == rate);

  // A run fills the rows in: plain gradient descent on a bumpy disk.
  ParamConfig config;
  config.preconditioner = "identity";
  config.optimizer.max_iterations = 20;
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(9, 9);
  const akvf::OptimizerResult run =
      akvf::run_parameterization(akvf::prepare_parameterization(mesh, "b.obj", config), config).result;
  REQUIRE(run.status == TerminationStatus::kMaxIterations);
  for (std::size_t i = 1; i < run.trace.size(); ++i) {
    CHECK(run.trace[i].initial_step > 0);
    CHECK(run.trace[i].initial_step <= 1);
    CHECK(run.trace[i].bound_cut_initial_step == (run.trace[i].initial_step < 1));
  }
  const bool diagnosed = run.message.find("first trials") != std::string::npos ||
                         run.message.find("were the direction's own") != std::string::npos ||
                         run.message.find("of the last 10 steps") != std::string::npos;
  CHECK_MESSAGE(diagnosed, run.message);
}

TEST_CASE("a manifest cannot read outside --data-dir unless it says so") {
  auto error_of = [](const std::string& text) {
    return akvf::test::error_message([&] { akvf::parse_manifest(text, "m.json"); });
  };
  const std::string methods = R"("methods": [{"label": "X"}])";
  CHECK(error_of(R"({"meshes": [{"label": "A", "file": "../../x.obj"}], )" + methods + "}") ==
        "m.json: meshes[0].file: \"../../x.obj\" leaves the data folder (absolute, or \"..\" past its top); give a "
        "path inside --data-dir, or set \"allow_outside_data_dir\": true in the manifest");
  CHECK(error_of(R"({"meshes": [{"label": "A", "file": "/etc/x.obj"}], )" + methods + "}")
            .find("m.json: meshes[0].file: \"/etc/x.obj\" leaves the data folder") == 0);
  CHECK(error_of(R"({"meshes": [{"label": "A", "file": "tet/a.mesh"}], "methods": [{"label": "X", "problem": )"
                 R"("deform", "constraints": "../c.txt"}]})")
            .find("m.json: methods[0].constraints: \"../c.txt\" leaves the data folder") == 0);
  CHECK(error_of(R"({"meshes": [{"label": "A", "file": "a/../b.obj"}], )" + methods + "}").empty());
  CHECK(error_of(R"({"allow_outside_data_dir": true, "meshes": [{"label": "A", "file": "../x.obj"}], )" + methods + "}")
            .empty());

  // A link inside the data folder that leads out of it is refused when the case runs.
  const fs::path dir = scratch("outside");
  fs::create_directories(dir / "data");
  std::ofstream(dir / "secret.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  fs::create_symlink(dir / "secret.obj", dir / "data" / "link.obj");
  std::ofstream(dir / "m.json") << R"({"meshes": [{"label": "A", "file": "link.obj"}], )" + methods + "}";
  std::ostringstream out, err;
  const int code = akvf::run_akvf({"experiment", (dir / "m.json").string(), "--data-dir", (dir / "data").string(),
                                   "--out-dir", (dir / "r").string()},
                                  out, err);
  CHECK(code == akvf::kExitOptimizerFailure);
  CHECK(err.str().find("meshes[0].file: ") != std::string::npos);
  CHECK(err.str().find("outside the data folder") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("a growing trace holds every row as the run goes and becomes the final trace at the end") {
  const fs::path dir = scratch("growing");
  const std::string path = (dir / "t.csv").string();
  akvf::GrowingTraceCsv trace(path);
  REQUIRE(trace.partial_path() == fs::weakly_canonical(dir / "t.csv").string() + ".partial");
  std::vector<std::string> seen;  // the partial file after each row
  const akvf::IterationCallback record = trace.callback();
  const akvf::IterationCallback look = [&](const akvf::IterationSummary&, const Eigen::VectorXd&) {
    std::ifstream in(trace.partial_path());
    seen.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return akvf::CallbackAction::kContinue;
  };
  ParamConfig config;
  config.optimizer.max_iterations = 3;
  config.conformal = akvf::ConformalStart::kNever;  // a start farther than 3 iterations from the minimum
  config.boundary_first = akvf::ConformalStart::kNever;
  const akvf::ParamSetup setup = akvf::prepare_parameterization(akvf::test::bumpy_disk(7, 7), "b.obj", config);
  const akvf::OptimizerResult result = akvf::run_parameterization(setup, config, {record, look}).result;
  REQUIRE(seen.size() == 4);  // rows 0..3
  const std::string final_text = trace_text(result);
  for (std::size_t k = 0; k < seen.size(); ++k) {
    CAPTURE(k);
    CHECK(std::count(seen[k].begin(), seen[k].end(), '\n') == static_cast<long>(k + 2));  // header + rows 0..k
    // Every row so far, as the final trace has it but with an empty status.
    const std::string header_and_rows = seen[k];
    CHECK(final_text.rfind(header_and_rows.substr(0, header_and_rows.size() - 1), 0) == 0);
  }
  CHECK(!fs::exists(path));  // nothing at PATH before finish()
  trace.finish(result);
  CHECK(!fs::exists(trace.partial_path()));
  std::ifstream in(path);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(written == final_text);
  CHECK(written.find(",max-iterations\n") != std::string::npos);
}

TEST_CASE("a growing trace leaves special outputs and whatever is not a regular file at PATH.partial alone") {
  CHECK(akvf::GrowingTraceCsv("/dev/null").partial_path().empty());
  CHECK(akvf::GrowingTraceCsv("").partial_path().empty());
  const fs::path dir = scratch("growing_folder");
  fs::create_directories(dir / "t.csv.partial");  // a folder where the partial file would go
  akvf::GrowingTraceCsv trace((dir / "t.csv").string());
  ParamConfig config;
  config.optimizer.max_iterations = 2;
  const akvf::ParamSetup setup = akvf::prepare_parameterization(akvf::test::bumpy_disk(7, 7), "b.obj", config);
  const akvf::OptimizerResult result = akvf::run_parameterization(setup, config, {trace.callback()}).result;
  trace.finish(result);
  CHECK(fs::is_directory(dir / "t.csv.partial"));
  CHECK(fs::is_empty(dir / "t.csv.partial"));
  std::ifstream in(dir / "t.csv");
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(written == trace_text(result));
}
