// The rotation-following path of the backtracking line search
// (MeshObjective::rotation_following_term).
#include <doctest/doctest.h>

#include <cmath>

#include "akvf/backtracking_line_search.h"
#include "energies/arap.h"
#include "framework/optimization/distortion_objective.h"
#include "tests/test_support.h"

namespace {

akvf::DistortionObjective2D arap_objective(const akvf::TriMesh& mesh) {
  return akvf::DistortionObjective2D(mesh.F, akvf::rest_triangles(mesh), std::make_shared<akvf::Arap2D>(),
                                     mesh.num_vertices());
}

// x rotated by the angle t about the origin.
Eigen::VectorXd rotated(const Eigen::VectorXd& x, double t) {
  Eigen::VectorXd y(x.size());
  for (Eigen::Index v = 0; v < x.size() / 2; ++v)
    y.segment<2>(2 * v) = Eigen::Rotation2Dd(t).toRotationMatrix() * x.segment<2>(2 * v);
  return y;
}

}  // namespace

TEST_CASE("along a rigid turn the path follows the circle to third order, the straight step to second") {
  const akvf::TriMesh mesh = akvf::test::grid_disk(6, 5);
  const auto objective = arap_objective(mesh);
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(mesh, 0.2, 5));
  REQUIRE(objective.count_inverted(x) == 0);
  const Eigen::VectorXd d = rotated(x, M_PI / 2);  // W x, W the quarter turn
  Eigen::VectorXd a;
  REQUIRE(objective.rotation_following_term(x, d, &a));
  CHECK((a + x).norm() <= 1e-12 * x.norm());  // W W x = -x
  for (double t : {0.2, 0.1}) {
    const Eigen::VectorXd circle = rotated(x, t);
    const double straight = (x + t * d - circle).norm();
    const double curved = (x + t * d + 0.5 * t * t * a - circle).norm();
    CAPTURE(t);
    CHECK(straight == doctest::Approx(0.5 * t * t * x.norm()).epsilon(0.02));
    CHECK(curved == doctest::Approx(t * t * t / 6 * x.norm()).epsilon(0.02));
  }
}

TEST_CASE("the rotation-following term of a tet mesh is W d for a rigid turn about an axis") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(3);
  const akvf::DistortionObjective3D objective(mesh.T, akvf::rest_tets(mesh), std::make_shared<akvf::Arap3D>(),
                                              mesh.num_vertices());
  const Eigen::VectorXd x = akvf::stack_rows(mesh.V);
  const Eigen::Vector3d omega(0.3, -0.5, 0.8);
  Eigen::VectorXd d(x.size());
  for (int v = 0; v < mesh.num_vertices(); ++v) d.segment<3>(3 * v) = omega.cross(x.segment<3>(3 * v));
  Eigen::VectorXd a;
  REQUIRE(objective.rotation_following_term(x, d, &a));
  for (int v = 0; v < mesh.num_vertices(); ++v)
    CHECK((a.segment<3>(3 * v) - omega.cross(d.segment<3>(3 * v))).norm() <= 1e-12);
}

TEST_CASE("where the straight unit step fails along a turn, the line search takes the turn") {
  // A compressed copy of the rest shape, and a direction that restores its
  // size while turning it by 0.7 radian per unit step: the straight unit
  // step stretches every triangle by sqrt(1 + 0.63^2) and raises ARAP from
  // 0.02 to 0.066; along the turn it ends near 0.001.
  const akvf::TriMesh mesh = akvf::test::grid_disk(40, 30);
  const auto objective = arap_objective(mesh);
  const Eigen::VectorXd rest = akvf::stack_uv(mesh.V.leftCols(2));
  const Eigen::VectorXd x = 0.9 * rest;
  const Eigen::VectorXd d = 0.1 * rest + 0.7 * rotated(x, M_PI / 2);
  Eigen::VectorXd g;
  const double energy = objective.value_and_gradient(x, &g);
  REQUIRE(energy == doctest::Approx(0.02));
  REQUIRE(g.dot(d) < 0);
  REQUIRE(objective.value(x + d) > energy);  // the straight unit step fails
  const akvf::BacktrackingLineSearch search;

  const akvf::LineSearchSummary summary = search.search(objective, x, energy, g, d);
  REQUIRE(summary.success);
  CHECK(summary.step == 1);
  REQUIRE(summary.turn.size() == x.size());
  const Eigen::VectorXd next = akvf::accepted_point(x, d, summary);
  CHECK(objective.count_inverted(next) == 0);
  CHECK(objective.value(next) == summary.energy);
  CHECK(summary.energy < 0.1 * energy);
}

TEST_CASE("where the flip-free bound cut the first trial, the line search keeps to the straight line") {
  // The turning square of the case above, beside a small square (1 % of the
  // area) that the direction flattens (y -> y (1 - t / 1.1)): the bound is
  // 1.1, the first trial 0.88, where the straight step fails and the turn
  // would not.
  akvf::TriMesh small = akvf::test::grid_disk(3, 3);
  small.V *= 0.1;
  const akvf::TriMesh square = akvf::test::grid_disk(16, 12);
  const akvf::TriMesh mesh = akvf::test::side_by_side(square, small, 2);
  const auto objective = arap_objective(mesh);
  const Eigen::VectorXd x = 0.9 * akvf::stack_uv(mesh.V.leftCols(2));
  Eigen::VectorXd d = 0.1 / 0.9 * x + 0.7 * rotated(x, M_PI / 2);
  for (int v = square.num_vertices(); v < mesh.num_vertices(); ++v) d.segment<2>(2 * v) << 0, -x[2 * v + 1] / 1.1;
  Eigen::VectorXd g;
  const double energy = objective.value_and_gradient(x, &g);
  REQUIRE(g.dot(d) < 0);
  REQUIRE(objective.max_feasible_step(x, d) == doctest::Approx(1.1));

  const auto summary = akvf::BacktrackingLineSearch().search(objective, x, energy, g, d);
  const double first = summary.initial_step;
  REQUIRE(first == doctest::Approx(0.88));
  REQUIRE(objective.value(x + first * d) > energy);  // the straight first trial fails
  Eigen::VectorXd a;
  REQUIRE(objective.rotation_following_term(x, d, &a));
  CHECK(objective.value(x + first * d + 0.5 * first * first * a) < energy);  // the turn would not
  REQUIRE(summary.success);
  CHECK(summary.step < first);
  CHECK(summary.turn.size() == 0);
}
