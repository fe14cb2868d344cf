// Local Newton sweeps (framework/optimization/local_newton_sweep.h): every
// move lowers the energy and inverts nothing, the colour classes are
// independent (the same bits on any number of threads), and the
// parameterization's option turns them on after bound-set steps (the
// interior vertices only with global injectivity).
#include <doctest/doctest.h>

#include <tbb/task_arena.h>

#include "akvf/extend.h"
#include "akvf/internal/options.h"
#include "akvf/internal/parameterization.h"
#include "akvf/rest_geometry.h"
#include "energies/arap.h"
#include "energies/symmetric_dirichlet.h"
#include "framework/mesh/mesh_validation.h"
#include "framework/optimization/distortion_objective.h"
#include "framework/optimization/local_newton_sweep.h"
#include "tests/test_support.h"

namespace {

template <class Density>
akvf::DistortionObjective2D objective_of(const akvf::TriMesh& mesh) {
  return akvf::DistortionObjective2D(mesh.F, akvf::rest_triangles(mesh), std::make_shared<Density>(),
                                     mesh.num_vertices());
}

// A jittered grid's map squeezed along y: every triangle distorted, some much more.
Eigen::VectorXd distorted_map(const akvf::TriMesh& mesh) {
  Eigen::MatrixXd uv = akvf::test::jittered_uv(mesh, 0.25, 3);
  uv.col(1) *= 0.3;
  return akvf::stack_uv(uv);
}

Eigen::VectorXd swept(const akvf::DistortionObjective2D& objective, const Eigen::VectorXd& start, double share,
                      int threads, int* moved = nullptr) {
  Eigen::VectorXd x = start, gradient;
  objective.value_and_gradient(x, &gradient);
  const akvf::LocalNewtonSweep<2> sweep(objective);
  tbb::task_arena arena(threads);
  arena.execute([&] {
    const int n = sweep.sweep(gradient, share, &x);
    if (moved) *moved = n;
  });
  return x;
}

}  // namespace

TEST_CASE("a local Newton sweep lowers the energy and inverts no triangle") {
  const akvf::TriMesh mesh = akvf::test::grid_disk(30, 20);
  const auto sd = objective_of<akvf::SymmetricDirichlet2D>(mesh);
  const auto arap = objective_of<akvf::Arap2D>(mesh);
  const Eigen::VectorXd start = distorted_map(mesh);
  for (const akvf::DistortionObjective2D* objective : {&sd, &arap}) {
    for (double share : {0.0, 1.0, 4.0}) {
      CAPTURE(share);
      int moved = 0;
      const Eigen::VectorXd x = swept(*objective, start, share, 2, &moved);
      CHECK(moved > 0);
      CHECK(objective->count_inverted(x) == 0);
      CHECK(objective->value(x) < objective->value(start));
      // Only the chosen vertices move.
      Eigen::VectorXd gradient;
      objective->value_and_gradient(start, &gradient);
      const double threshold = share * gradient.squaredNorm() / mesh.num_vertices();
      int changed = 0;
      for (int v = 0; v < mesh.num_vertices(); ++v) {
        const bool chosen = gradient.segment<2>(2 * v).squaredNorm() > threshold;
        const bool moved_v = x.segment<2>(2 * v) != start.segment<2>(2 * v);
        CHECK((chosen || !moved_v));
        changed += moved_v;
      }
      CHECK(changed == moved);
    }
  }
}

TEST_CASE("a local Newton sweep has the same bits on 1, 2 and 3 threads") {
  const akvf::TriMesh mesh = akvf::test::grid_disk(40, 30);
  const auto objective = objective_of<akvf::SymmetricDirichlet2D>(mesh);
  const akvf::LocalNewtonSweep<2> sweep(objective);
  CHECK(sweep.colours() >= 3);  // a triangle's three vertices differ
  CHECK(sweep.colours() <= 8);
  const Eigen::VectorXd start = distorted_map(mesh);
  const Eigen::VectorXd one = swept(objective, start, 1.0, 1);
  CHECK(swept(objective, start, 1.0, 2) == one);
  CHECK(swept(objective, start, 1.0, 3) == one);
}

TEST_CASE("a local Newton sweep leaves the minimum where it is") {
  // The rest shape is every vertex's minimum: its gradient is rounding, and
  // so is each vertex's Newton step.
  const akvf::TriMesh mesh = akvf::test::grid_disk(10, 8);
  const auto objective = objective_of<akvf::SymmetricDirichlet2D>(mesh);
  const Eigen::VectorXd rest = akvf::stack_uv(mesh.V.leftCols(2));
  CHECK((swept(objective, rest, 0.0, 2) - rest).lpNorm<Eigen::Infinity>() < 1e-12);
}

TEST_CASE("local_sweep runs the sweeps after bound-set steps, with local injectivity only") {
  const akvf::TriMesh mesh = akvf::test::grid_disk(30, 20, 0.3, 5);
  akvf::ParamConfig config;
  config.global_injectivity = false;
  config.conformal = akvf::ConformalStart::kNever;  // the flat grid's conformal map is the minimum
  config.boundary_first = akvf::ConformalStart::kNever;
  const auto setup = akvf::prepare_parameterization(mesh, "test", config);
  const akvf::ParamRun plain = akvf::run_parameterization(setup, config);
  config.local_sweep = 4;
  const akvf::ParamRun local = akvf::run_parameterization(setup, config);
  CHECK(local.result.status == akvf::TerminationStatus::kConverged);
  for (const akvf::IterationSummary& row : local.result.trace) CHECK(row.flips == 0);
  CHECK(local.result.trace.back().energy == doctest::Approx(plain.result.trace.back().energy).epsilon(1e-8));
  // The first step from the Tutte map is bound-set: the sweep moves vertices.
  REQUIRE(local.result.trace.size() > 1);
  REQUIRE(plain.result.trace[1].bound_cut_initial_step);
  CHECK(local.result.trace[1].energy < plain.result.trace[1].energy);

  // With global injectivity the sweeps move the interior vertices only,
  // which the boundary barrier does not involve: still no crossing.
  akvf::ParamConfig global = config;
  global.global_injectivity = true;
  const auto global_setup = akvf::prepare_parameterization(mesh, "test", global);
  const akvf::ParamRun injective = akvf::run_parameterization(global_setup, global);
  CHECK(injective.result.status == akvf::TerminationStatus::kConverged);
  CHECK(injective.boundary_crossings == 0);
  for (const akvf::IterationSummary& row : injective.result.trace) CHECK(row.flips == 0);
}

TEST_CASE("local_sweep auto sweeps with the default method on barrier energies only, a number with any method") {
  akvf::ParameterizeOptions options;
  for (const char* barrier : {"symmetric-dirichlet", "mips", "amips", "exp-symmetric-dirichlet"}) {
    options.energy = barrier;
    CHECK(akvf::param_config(options).local_sweep == 4);
  }
  // ARAP's barrier acts only below 1e-3 of the rest area.
  options.energy = "arap";
  CHECK(akvf::param_config(options).local_sweep == 0);
  options.local_sweep = 4;
  CHECK(akvf::param_config(options).local_sweep == 4);
  options.local_sweep.reset();
  options.energy = "symmetric-dirichlet";
  for (const char* published : {"akvf", "newton", "slim", "laplacian", "identity"}) {
    options.preconditioner = published;
    CHECK(akvf::param_config(options).local_sweep == 0);
  }
  options.local_sweep = 2;
  CHECK(akvf::param_config(options).local_sweep == 2);
  options.preconditioner = "akvf-newton";
  options.local_sweep = 0;
  CHECK(akvf::param_config(options).local_sweep == 0);
}

namespace {
// |J|^2 + |J^-1|^2: symmetric Dirichlet, infinite at a collapse.
struct AutodiffSymmetricDirichlet {
  template <class T>
  T operator()(const Eigen::Matrix<T, 2, 2>& J) const {
    return J.squaredNorm() + J.inverse().squaredNorm();
  }
};
}  // namespace

TEST_CASE("a user energy registered with the collapse-barrier tag is swept by default, one without is not") {
  akvf::register_autodiff_energy<2>("test-swept-sd", "tagged", 4.0, AutodiffSymmetricDirichlet{},
                                    {akvf::kCollapseBarrier});
  akvf::register_autodiff_energy<2>("test-unswept-sd", "untagged", 4.0, AutodiffSymmetricDirichlet{});
  CHECK(akvf::energies_2d().has_tag("test-swept-sd", akvf::kCollapseBarrier));
  akvf::ParameterizeOptions options;
  options.energy = "test-swept-sd";
  CHECK(akvf::param_config(options).local_sweep == 4);
  options.energy = "test-unswept-sd";
  CHECK(akvf::param_config(options).local_sweep == 0);
}

TEST_CASE("a local Newton sweep leaves its fixed vertices where they are") {
  const akvf::TriMesh mesh = akvf::test::grid_disk(30, 20);
  const auto objective = objective_of<akvf::SymmetricDirichlet2D>(mesh);
  const akvf::DiskMesh disk = akvf::prepare_disk_mesh(mesh, "grid");
  const std::vector<int>& boundary = disk.boundary_loops.at(0);
  Eigen::VectorXd x = distorted_map(mesh), gradient;
  const Eigen::VectorXd start = x;
  objective.value_and_gradient(x, &gradient);
  const akvf::LocalNewtonSweep<2> sweep(objective, boundary);
  CHECK(sweep.sweep(gradient, 0.0, &x) > 0);
  for (int v : boundary) CHECK(x.segment<2>(2 * v) == start.segment<2>(2 * v));
  CHECK(objective.value(x) < objective.value(start));
}

TEST_CASE("a local Newton sweep of a tet mesh lowers the energy and inverts no tet") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(4);
  const akvf::DistortionObjective3D objective(mesh.T, akvf::rest_tets(mesh),
                                              std::make_shared<akvf::SymmetricDirichlet3D>(), mesh.num_vertices());
  const Eigen::VectorXd start = akvf::test::distorted_tet_positions(mesh, 7);
  Eigen::VectorXd x = start, gradient;
  objective.value_and_gradient(x, &gradient);
  const akvf::LocalNewtonSweep<3> sweep(objective);
  CHECK(sweep.colours() >= 4);
  CHECK(sweep.sweep(gradient, 1.0, &x) > 0);
  CHECK(objective.count_inverted(x) == 0);
  CHECK(objective.value(x) < objective.value(start));
}
