// The distortion objective on tets (D = 3): assembled gradient, flip-free
// step bound, inverted count.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <sstream>

#include "akvf/constrained_objective.h"
#include "akvf/internal/deformation.h"
#include "energies/symmetric_dirichlet.h"
#include "framework/optimization/distortion_objective.h"
#include "io/constraints_io.h"
#include "preconditioners/akvf_preconditioner_3d.h"
#include "solvers/lbfgs_solver.h"
#include "tests/test_support.h"

namespace {

akvf::DistortionObjective3D cube_objective(const akvf::TetMesh& mesh) {
  return akvf::DistortionObjective3D(mesh.T, akvf::rest_tets(mesh), std::make_shared<akvf::SymmetricDirichlet3D>(),
                                     mesh.num_vertices());
}

}  // namespace

TEST_CASE("tet objective: rest state is the lower bound, the gradient matches finite differences") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(2);
  const akvf::DistortionObjective3D objective = cube_objective(mesh);
  Eigen::VectorXd g;
  CHECK(objective.value_and_gradient(akvf::stack_rows(mesh.V), &g) == doctest::Approx(6.0).epsilon(1e-12));
  CHECK(g.norm() <= 1e-10);
  const Eigen::VectorXd x = akvf::test::distorted_tet_positions(mesh, 1);
  const double energy = objective.value_and_gradient(x, &g);
  CHECK(energy > 6.0);
  CHECK(objective.value(x) == energy);
  const double h = 1e-7;
  for (int i = 0; i < x.size(); i += 5) {
    Eigen::VectorXd plus = x, minus = x;
    plus[i] += h;
    minus[i] -= h;
    CHECK(g[i] == doctest::Approx((objective.value(plus) - objective.value(minus)) / (2 * h)).epsilon(1e-5).scale(1.0));
  }
}

TEST_CASE("tet objective: the flip-free bound is tight and no step below it inverts a tet") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(2);
  const akvf::DistortionObjective3D objective = cube_objective(mesh);
  std::mt19937 rng(3);
  std::normal_distribution<double> n;
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::VectorXd x = akvf::test::distorted_tet_positions(mesh, trial + 10);
    REQUIRE(objective.count_inverted(x) == 0);
    const Eigen::VectorXd d = Eigen::VectorXd::NullaryExpr(x.size(), [&](Eigen::Index) { return n(rng); });
    const double t = objective.max_feasible_step(x, d);
    REQUIRE(std::isfinite(t));
    for (double fraction : {0.5, 0.9, 0.999999}) CHECK(objective.count_inverted(x + fraction * t * d) == 0);
    CHECK(objective.count_inverted(x + 1.000001 * t * d) > 0);
  }
}

TEST_CASE("3D AKVF preconditioner: K + c I gives a descent direction, with rigid projection, none of it rigid") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(2);
  const akvf::DistortionObjective3D objective = cube_objective(mesh);
  const Eigen::VectorXd x = akvf::test::distorted_tet_positions(mesh, 5);
  Eigen::VectorXd g, d;
  objective.value_and_gradient(x, &g);
  for (bool project : {false, true}) {
    CAPTURE(project);
    akvf::AkvfOptions3D options;
    options.project_rigid = project;
    akvf::AkvfPreconditioner3D preconditioner(objective, options);
    preconditioner.update({x, g, 0.0, 1});
    preconditioner.apply(g, &d);
    CHECK(d.allFinite());
    CHECK(g.dot(d) > 0);
    // P d = g: the matrix factored is K + c I (+ the tiny relative shift).
    const Eigen::MatrixXd P(preconditioner.matrix().full());
    if (!project) CHECK((P * d - g).norm() <= 1e-8 * g.norm());
    if (project) CHECK((akvf::rigid_motion_basis_3d(x).transpose() * d).norm() <= 1e-10 * d.norm());
  }
}

TEST_CASE("soft positional constraints add w |x_i - p_i|^2 with its gradient, bad constraints are rejected") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(1);
  const akvf::DistortionObjective3D base = cube_objective(mesh);
  akvf::PositionConstraints constraints;
  constraints.vertices = {0, 7};
  constraints.targets.resize(2, 3);
  constraints.targets << 0.1, 0, 0, 1, 1, 1.2;
  const akvf::SoftConstrainedObjective objective(base, 3, constraints, 1e5);
  const Eigen::VectorXd x = akvf::stack_rows(mesh.V);
  CHECK(objective.value(x) == doctest::Approx(6.0 + 1e5 * (0.01 + 0.04)));
  Eigen::VectorXd g;
  objective.value_and_gradient(x, &g);
  CHECK(g[0] == doctest::Approx(2e5 * -0.1));
  CHECK(g[3 * 7 + 2] == doctest::Approx(2e5 * -0.2));
  CHECK(objective.max_feasible_step(x, g) == base.max_feasible_step(x, g));
  CHECK(objective.constraint_distance(x) == doctest::Approx(0.2));  // vertex 7's target is 0.2 above it
  CHECK(std::isnan(base.constraint_distance(x)));                   // no constraints
  // Both optimizers' traces record it (minimize's is checked through the
  // command line, tests/test_cli.cpp): L-BFGS draws vertex 7 toward its target.
  akvf::OptimizerOptions options;
  options.max_iterations = 5;
  const akvf::OptimizerResult lbfgs = akvf::minimize_lbfgs(objective, x, options);
  REQUIRE(lbfgs.trace.size() > 1);
  CHECK(lbfgs.trace.front().constraint_distance == doctest::Approx(0.2));
  CHECK(lbfgs.trace.back().constraint_distance < 0.2);
  constraints.vertices = {0, 99};
  CHECK(akvf::test::error_message([&] { akvf::SoftConstrainedObjective bad(base, 3, constraints, 1e5); }) ==
        "constrained vertex 99 out of range (8 vertices)");
}

TEST_CASE("constraints files: rows, comments, and each malformed line named") {
  const auto parse = [](const std::string& text) {
    std::istringstream in(text);
    return akvf::read_constraints(in, "c.txt", 8);
  };
  const auto constraints = parse("# pinned corners\n0 0 0 0\n\n7 1 1 1.5  # pulled up\n");
  REQUIRE(constraints.vertices == std::vector<int>{0, 7});
  CHECK(constraints.targets(1, 2) == 1.5);
  CHECK(akvf::test::error_message([&] { parse("8 0 0 0\n"); }) ==
        "line 1 of c.txt: vertex index 8 out of range (8 vertices, 0-based)");
  CHECK(akvf::test::error_message([&] { parse("1 0 0\n"); }) ==
        "line 1 of c.txt: expected 4 columns `vertex_index x y z`, found 3");
  CHECK(akvf::test::error_message([&] { parse("1 0 0 0 5\n"); }) ==
        "line 1 of c.txt: expected 4 columns `vertex_index x y z`, found 5");
  CHECK(akvf::test::error_message([&] { parse("1 0 a 0\n"); }) ==
        "line 1 of c.txt: target coordinate 'a' is not a finite number");
  CHECK(akvf::test::error_message([&] { parse("1 0 0 0\n1 1 1 1\n"); }) ==
        "line 2 of c.txt: vertex 1 is already constrained on line 1");
  CHECK(akvf::test::error_message([&] { parse("# nothing\n"); }) == "c.txt: no constraints");
}

TEST_CASE("3D AKVF with conjugate gradients solves (K + c I) d = g to the tolerance without factoring") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(2);
  const akvf::DistortionObjective3D objective = cube_objective(mesh);
  const Eigen::VectorXd x = akvf::test::distorted_tet_positions(mesh, 6);
  Eigen::VectorXd g, d;
  objective.value_and_gradient(x, &g);
  akvf::AkvfOptions3D options;
  options.factor.cg_tolerance = 0.01;
  akvf::AkvfPreconditioner3D preconditioner(objective, options);
  preconditioner.update({x, g, 0.0, 1});
  preconditioner.apply(g, &d);
  const Eigen::MatrixXd P(preconditioner.matrix().full());
  CHECK((P * d - g).norm() <= 0.0101 * g.norm());
  CHECK(g.dot(d) > 0);
  CHECK(preconditioner.statistics().factorizations == 0);
  CHECK(preconditioner.statistics().cg_solves == 1);
}
