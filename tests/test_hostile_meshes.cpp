// Hostile but valid meshes (docs/robustness.md): extreme scales, slivers
// and needles, flaps, a long thin strip, a mesh whose Tutte map is nearly
// degenerate, and 3 and one million triangles. Each run must end with a
// normal status and no inverted triangle at any iterate, or with a clear
// failure status; never a non-finite output.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "akvf/internal/parameterization.h"
#include "tests/test_support.h"

namespace {

struct Outcome {
  akvf::OptimizerResult result;
  Eigen::MatrixXd uv;
  int worst_flips = 0;
};

akvf::ParamConfig hostile_config(const std::string& precond = "akvf") {
  akvf::ParamConfig config;
  config.preconditioner = precond;
  config.optimizer.max_iterations = 300;
  return config;
}

Outcome parameterize(const akvf::TriMesh& mesh, const akvf::ParamConfig& config) {
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

Outcome parameterize(const akvf::TriMesh& mesh, const std::string& precond = "akvf") {
  return parameterize(mesh, hostile_config(precond));
}

// Smallest over mean triangle area of a planar map.
double min_area_ratio(const akvf::TriMesh& mesh, const Eigen::VectorXd& x) {
  Eigen::VectorXd area(mesh.num_faces());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Vector2d a = x.segment<2>(2 * mesh.F(f, 0)), b = x.segment<2>(2 * mesh.F(f, 1)),
                          c = x.segment<2>(2 * mesh.F(f, 2));
    area[f] = 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  }
  return area.minCoeff() / area.mean();
}

// A sock: a cylinder of `rings` rings of `around` vertices, closed at the
// far end by a fan, open at ring 0 (the one boundary loop). Tutte's uniform
// weights shrink the rings geometrically towards the toe.
akvf::TriMesh sock(int around, int rings, double length) {
  akvf::TriMesh mesh;
  const int n = around * rings;
  mesh.V.resize(n + 1, 3);
  for (int r = 0; r < rings; ++r)
    for (int i = 0; i < around; ++i) {
      const double angle = 2 * M_PI * (i + 0.5 * r) / around;
      mesh.V.row(r * around + i) << std::cos(angle), std::sin(angle), -length * r / (rings - 1);
    }
  mesh.V.row(n) << 0, 0, -length - 0.5;
  mesh.F.resize(2 * around * (rings - 1) + around, 3);
  int f = 0;
  for (int r = 0; r + 1 < rings; ++r)
    for (int i = 0; i < around; ++i) {
      const int a = r * around + i, b = r * around + (i + 1) % around, c = a + around, d = b + around;
      mesh.F.row(f++) << a, c, b;
      mesh.F.row(f++) << b, c, d;
    }
  for (int i = 0; i < around; ++i)
    mesh.F.row(f++) << (rings - 1) * around + i, n, (rings - 1) * around + (i + 1) % around;
  return mesh;
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

TEST_CASE("needles: a vertex 1e-6 from its neighbour (angles of about 1e-6 rad)") {
  akvf::TriMesh mesh = akvf::test::grid_disk(8, 8);
  const int v = 3 * 8 + 3;
  mesh.V.row(v) = mesh.V.row(v + 1) + Eigen::RowVector3d(-1e-6 / 7, 0, 0);
  for (const char* method : {"akvf", "newton", "slim"}) {
    CAPTURE(method);
    check_clean(parameterize(mesh, method));
  }
}

TEST_CASE("a flap: a boundary vertex in one triangle folded back over the mesh") {
  // The grid's corner (1, 0) lies in one triangle only; fold it over the
  // square (z up, x back inside): Tutte puts it on the circle, where its
  // triangle is nearly flat.
  akvf::TriMesh mesh = akvf::test::bumpy_disk(9, 9);
  const int corner = 8;
  mesh.V.row(corner) << 0.8, 0.1, 0.4;
  for (const bool flaps : {true, false}) {
    CAPTURE(flaps);
    akvf::ParamConfig config = hostile_config();
    config.conformal = akvf::ConformalStart::kNever;  // the flap is the Tutte map's
    config.boundary_first = akvf::ConformalStart::kNever;
    config.optimize_flaps = flaps;
    const akvf::ParamSetup setup = akvf::prepare_parameterization(mesh, "flap", config);
    if (flaps) CHECK(setup.flaps_moved >= 1);
    const Outcome o = parameterize(mesh, config);
    check_clean(o);
    CHECK(o.result.status == akvf::TerminationStatus::kConverged);
  }
}

TEST_CASE("a nearly degenerate Tutte map (a deep sock: areas below 1e-12 of the mean) converges") {
  const akvf::TriMesh mesh = sock(12, 40, 10);
  akvf::ParamConfig config = hostile_config();
  config.conformal = akvf::ConformalStart::kNever;
  config.boundary_first = akvf::ConformalStart::kNever;
  config.optimizer.max_iterations = 500;
  const akvf::ParamSetup setup = akvf::prepare_parameterization(mesh, "sock", config);
  CHECK(min_area_ratio(setup.disk.mesh, setup.x0) < 1e-12);
  for (const char* method : {"akvf", "newton", "slim"}) {
    CAPTURE(method);
    config.preconditioner = method;
    const Outcome o = parameterize(mesh, config);
    check_clean(o);
    CHECK(o.result.trace.back().energy < 1e-6 * o.result.trace.front().energy);
  }
}

TEST_CASE("SLIM with MIPS on a jittered bumpy disk reaches the default's minimum within 100 iterations") {
  // Vertices moved by up to a fifth of the spacing in 3D: slivers and folds
  // whose conformal maps need large changes of scale, which a SLIM proxy
  // stiff along each element's similarities lets through only slowly.
  akvf::TriMesh mesh = akvf::test::bumpy_disk(30, 30);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.2 / 29, 0.2 / 29);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int c = 0; c < 3; ++c) mesh.V(v, c) += jitter(rng);
  akvf::ParamConfig config = hostile_config("akvf-newton");
  config.energy = "mips";
  config.global_injectivity = false;
  config.optimizer.max_iterations = 100;
  const Outcome best = parameterize(mesh, config);
  REQUIRE(best.result.status == akvf::TerminationStatus::kConverged);
  config.preconditioner = "slim";
  const Outcome slim = parameterize(mesh, config);
  check_clean(slim);
  CHECK(slim.result.status == akvf::TerminationStatus::kConverged);
  CHECK(slim.result.trace.back().energy <= best.result.trace.back().energy * (1 + 1e-6));
}

TEST_CASE("one million triangles: Tutte, then AKVF iterations without a flip") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(709, 709);
  REQUIRE(mesh.num_faces() >= 1000000);
  akvf::ParamConfig config = hostile_config();
  config.optimizer.max_iterations = 3;
  const Outcome o = parameterize(mesh, config);
  check_clean(o);
  CHECK(o.result.trace.size() == 4);
  CHECK(o.result.trace.back().energy < o.result.trace.front().energy);
}
