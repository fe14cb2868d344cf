// Hostile but valid meshes (the robustness issue, first part): extreme
// scales, a sliver, flaps, a long thin strip and a three-triangle fan. Each
// run must end with a normal status and no inverted triangle at any
// iterate, or with a clear failure status; never a non-finite output.
#include <doctest/doctest.h>

#include <cmath>

#include "experiments/parameterization.h"
#include "tests/test_support.h"

namespace {

struct Outcome {
  akvf::OptimizerResult result;
  Eigen::MatrixXd uv;
  int worst_flips = 0;
};

Outcome parameterize(const akvf::TriMesh& mesh, const std::string& precond = "akvf") {
  akvf::ParamConfig config;
  config.preconditioner = precond;
  config.optimizer.max_iterations = 300;
  const akvf::ParamSetup setup = akvf::prepare_parameterization(mesh, "hostile", config);
  Outcome out;
  const akvf::IterationCallback flips = [&](const akvf::IterationSummary& row, const Eigen::VectorXd&) {
    out.worst_flips = std::max(out.worst_flips, row.flips);
    return akvf::CallbackAction::kContinue;
  };
  out.result = akvf::run_parameterization(setup, config, {flips}).result;
  out.uv = akvf::output_uv(setup, out.result.x);
  return out;
}

void check_clean(const Outcome& o) {
  CHECK(o.worst_flips == 0);
  CHECK(o.uv.allFinite());
  for (const auto& row : o.result.trace) CHECK(std::isfinite(row.energy));
  CHECK(akvf::is_normal_termination(o.result.status));
}

}  // namespace

TEST_CASE("1e-12 and 1e+12 coordinate scales give the scale-free answer") {
  const akvf::TriMesh base = akvf::test::bumpy_disk(9, 9);
  const Outcome reference = parameterize(base);
  check_clean(reference);
  for (const double scale : {1e-12, 1e12}) {
    CAPTURE(scale);
    akvf::TriMesh scaled = base;
    scaled.V *= scale;
    const Outcome o = parameterize(scaled);
    check_clean(o);
    CHECK(o.result.trace.back().energy == doctest::Approx(reference.result.trace.back().energy).epsilon(1e-8));
    // The UVs come back at the input's scale.
    CHECK(o.uv.norm() == doctest::Approx(scale * reference.uv.norm()).epsilon(1e-6));
  }
}

TEST_CASE("a sliver with angles of about 1e-6 rad still parameterizes without flips") {
  akvf::TriMesh mesh = akvf::test::grid_disk(8, 8);
  // Move an interior vertex almost onto the diagonal of its neighbouring cell: angles down to ~1e-6 rad.
  const int v = 3 * 8 + 3;
  const Eigen::RowVector3d a = mesh.V.row(v - 1), b = mesh.V.row(v + 8);
  mesh.V.row(v) = 0.5 * (a + b) + Eigen::RowVector3d(1e-7, -1e-7, 0);  // towards its old place
  for (const char* method : {"akvf", "newton", "slim"}) {
    CAPTURE(method);
    check_clean(parameterize(mesh, method));
  }
}

TEST_CASE("a long thin strip (1000:1) and a three-triangle fan") {
  akvf::TriMesh strip = akvf::test::grid_disk(201, 3);
  strip.V.col(1) *= 0.2 / 1000;  // 1 long, 0.0002 wide
  strip.V.col(2) = 0.05 * (strip.V.col(0).array() * 20).sin().matrix();
  check_clean(parameterize(strip));

  akvf::TriMesh fan;
  fan.V.resize(5, 3);
  fan.V << 0, 0, 0.3, 1, 0, 0, 0.3, 1, 0, -0.8, 0.6, 0, -0.7, -0.7, 0;
  fan.F.resize(3, 3);
  fan.F << 0, 1, 2, 0, 2, 3, 0, 3, 4;
  const Outcome o = parameterize(fan);
  check_clean(o);
  CHECK(o.result.status == akvf::TerminationStatus::kConverged);
}
