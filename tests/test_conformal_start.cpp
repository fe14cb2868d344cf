// The conformal start: the least-squares conformal map of a disk, and
// init auto taking it where it is flip-free and lower in energy than
// Tutte's map.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include "akvf/internal/demo_mesh.h"
#include "akvf/internal/parameterization.h"
#include "akvf/mesh_io.h"
#include "akvf/parameterize.h"
#include "energies/symmetric_dirichlet.h"
#include "framework/mesh/mesh_validation.h"
#include "framework/mesh/plane_geometry.h"
#include "framework/optimization/conformal_map.h"
#include "framework/optimization/uniform_scale.h"
#include "tests/test_support.h"

namespace {

// Symmetric Dirichlet of the conformal map of `mesh`, at its best uniform scale.
double conformal_energy_at_best_scale(const akvf::TriMesh& mesh) {
  const auto disk = akvf::prepare_disk_mesh(mesh, "m");
  const akvf::RestTriangles rest = akvf::rest_triangles(disk.mesh);
  const Eigen::MatrixXd UV = akvf::conformal_map(disk.mesh, rest, disk.boundary_loops[0]);
  REQUIRE(UV.rows() == disk.mesh.num_vertices());
  CHECK(akvf::count_inverted_triangles(disk.mesh.F, UV) == 0);
  const akvf::DistortionObjective2D objective(disk.mesh.F, rest, std::make_shared<akvf::SymmetricDirichlet2D>(),
                                              disk.mesh.num_vertices());
  const Eigen::VectorXd x = akvf::stack_uv(UV);
  return objective.value(akvf::best_uniform_scale(objective, x) * x);
}

// A strip of n by 3 vertices wound `turns` times along a cone (half-angle
// 45 degrees, each turn lifted by 0.5 off the last): flattened without
// distortion it turns through more than a full circle and lies over itself.
akvf::TriMesh wound_strip(int n, double turns) {
  akvf::TriMesh mesh;
  const int m = 3;
  mesh.V.resize(n * m, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double theta = 2 * std::numbers::pi * turns * i / (n - 1), rho = 4 + 0.3 * j / (m - 1);
      const double r = rho * std::sqrt(0.5);
      mesh.V.row(i * m + j) << r * std::cos(theta), r * std::sin(theta), r + 0.5 * theta / (2 * std::numbers::pi);
    }
  mesh.F.resize(2 * (n - 1) * (m - 1), 3);
  int f = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < m; ++j) {
      const int a = i * m + j, b = a + 1, c = a + m, d = c + 1;
      mesh.F.row(f++) << a, c, d;
      mesh.F.row(f++) << a, d, b;
    }
  return mesh;
}

}  // namespace

TEST_CASE("the conformal map of a developable disk is an isometry, and does not depend on the numbering") {
  // A bar bent in space: its conformal map at the best scale is at
  // symmetric Dirichlet's infimum, 4.
  CHECK(conformal_energy_at_best_scale(akvf::bent_bar(31, 6)) == doctest::Approx(4).epsilon(1e-9));
  // A bumpy disk is not developable; a permuted numbering gives the same map.
  const akvf::TriMesh bumpy = akvf::test::bumpy_disk(11, 9);
  const double energy = conformal_energy_at_best_scale(bumpy);
  CHECK(energy > 4.01);
  std::vector<int> to(bumpy.num_vertices());
  std::iota(to.begin(), to.end(), 0);
  std::shuffle(to.begin(), to.end(), std::mt19937(7));
  akvf::TriMesh permuted = bumpy;
  for (int v = 0; v < bumpy.num_vertices(); ++v) permuted.V.row(to[v]) = bumpy.V.row(v);
  permuted.F = bumpy.F.unaryExpr([&](int v) { return to[v]; }).eval();
  CHECK(conformal_energy_at_best_scale(permuted) == doctest::Approx(energy).epsilon(1e-9));
}

TEST_CASE("init auto starts at the conformal map where it is flip-free and lower than Tutte's, tutte never") {
  const akvf::TriMesh bar = akvf::bent_bar(31, 6);
  for (const bool global : {false, true}) {
    CAPTURE(global);
    akvf::ParamConfig config;
    config.global_injectivity = global;
    config.boundary_first = akvf::ConformalStart::kNever;  // the least-squares map against Tutte's
    const akvf::ParamSetup automatic = akvf::prepare_parameterization(bar, "bar", config);
    CHECK(automatic.initial_map == akvf::InitialMap::kConformal);
    CHECK(automatic.objective->value(automatic.x0) == doctest::Approx(4).epsilon(1e-9));
    CHECK(automatic.flaps_moved == 0);
    config.conformal = akvf::ConformalStart::kNever;
    config.boundary_first = akvf::ConformalStart::kNever;
    const akvf::ParamSetup tutte = akvf::prepare_parameterization(bar, "bar", config);
    CHECK(tutte.initial_map == akvf::InitialMap::kTutte);
    CHECK(tutte.objective->value(tutte.x0) > 4.5);
  }
  // Through the API: the result says which start the run took.
  akvf::ParameterizeOptions options;
  options.max_iters = 0;
  options.init = akvf::InitialMap::kConformal;
  CHECK(akvf::parameterize(bar.V, bar.F, options).initial_map == akvf::InitialMap::kConformal);
  options.init = akvf::InitialMap::kTutte;
  CHECK(akvf::parameterize(bar.V, bar.F, options).initial_map == akvf::InitialMap::kTutte);
}

TEST_CASE("with global injectivity a conformal map that lies over itself is not the start") {
  const akvf::TriMesh strip = wound_strip(240, 1.8);
  akvf::ParamConfig config;
  config.global_injectivity = false;
  config.boundary_first = akvf::ConformalStart::kNever;  // it winds as far
  const akvf::ParamSetup local = akvf::prepare_parameterization(strip, "strip", config);
  REQUIRE(local.initial_map == akvf::InitialMap::kConformal);
  CHECK(local.boundary_contact->count_crossings(local.x0) > 0);
  config.global_injectivity = true;
  const akvf::ParamSetup global = akvf::prepare_parameterization(strip, "strip", config);
  CHECK(global.initial_map == akvf::InitialMap::kTutte);
  CHECK(global.boundary_contact->count_crossings(global.x0) == 0);
  CHECK(global.warnings.empty());
  // Asked for by name, the refusal is a warning.
  config.conformal = akvf::ConformalStart::kAlways;
  const akvf::ParamSetup asked = akvf::prepare_parameterization(strip, "strip", config);
  CHECK(asked.initial_map == akvf::InitialMap::kTutte);
  REQUIRE(asked.warnings.size() == 1);
  CHECK(asked.warnings[0] ==
        "the conformal map is not the start: its boundary crosses itself; starting from the Tutte map");
}

TEST_CASE("charts of a cut mesh start from the Tutte map, and a warning says so when the conformal one was asked for") {
  akvf::ParamConfig config;
  config.cut = true;
  const akvf::TriMesh two = akvf::test::side_by_side(akvf::bent_bar(11, 4), akvf::bent_bar(11, 4), 30);
  const akvf::ParamSetup automatic = akvf::prepare_parameterization(two, "two", config);
  REQUIRE(automatic.disk.boundary_loops.size() == 2);
  CHECK(automatic.initial_map == akvf::InitialMap::kTutte);
  CHECK(automatic.warnings.empty());
  config.conformal = akvf::ConformalStart::kAlways;
  const akvf::ParamSetup asked = akvf::prepare_parameterization(two, "two", config);
  CHECK(asked.initial_map == akvf::InitialMap::kTutte);
  REQUIRE(asked.warnings.size() == 1);
  CHECK(asked.warnings[0] == "a conformal map is the start of one chart; these 2 charts start from the Tutte map");
}

TEST_CASE("a run from a conformal start takes K's analysis prepared beside the Tutte solve") {
  akvf::ParamConfig config;
  config.global_injectivity = false;
  config.optimizer.max_iterations = 2;
  config.preconditioner = "akvf";
  const akvf::ParamSetup setup = akvf::prepare_parameterization(akvf::test::bumpy_disk(15, 12), "bumpy", config);
  REQUIRE(setup.initial_map != akvf::InitialMap::kTutte);  // a conformal map, either
  const akvf::ParamRun run = akvf::run_parameterization(setup, config);
  CHECK(run.result.trace.size() == 3);
  CHECK(run.preconditioner_statistics.symbolic_analyses == 1);
}

TEST_CASE("a conformal map folded at its boundary starts flip-free once its folds are undone") {
  const std::string dir = akvf::test::data_dir();
  if (dir.empty()) return akvf::test::skip("../shared/meshes not found (set AKVF_DATA_DIR)");
  // cow_b's conformal map inverts a boundary triangle; unfolded, it is far
  // below the Tutte map in energy (and its boundary crosses itself).
  const akvf::TriMesh cow = akvf::read_triangle_mesh(dir + "/tri/cow_b.obj");
  akvf::ParamConfig config;
  config.global_injectivity = false;
  config.boundary_first = akvf::ConformalStart::kNever;
  const akvf::ParamSetup local = akvf::prepare_parameterization(cow, "cow_b", config);
  CHECK(local.initial_map == akvf::InitialMap::kConformal);
  CHECK(local.folds_unfolded >= 1);
  CHECK(local.objective->count_inverted(local.x0) == 0);
  config.global_injectivity = true;
  const akvf::ParamSetup global = akvf::prepare_parameterization(cow, "cow_b", config);
  CHECK(global.initial_map == akvf::InitialMap::kTutte);
  CHECK(global.folds_unfolded == 0);
}
