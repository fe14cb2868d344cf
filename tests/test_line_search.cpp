// The flip-free step bound (§5.3) and the backtracking line search.
#include <doctest/doctest.h>

#include <limits>
#include <random>

#include "akvf/backtracking_line_search.h"
#include "energies/symmetric_dirichlet.h"
#include "framework/optimization/distortion_objective.h"
#include "framework/optimization/flip_free_step.h"
#include "solvers/wolfe_bisection_line_search.h"
#include "tests/test_support.h"

using akvf::smallest_positive_root;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

akvf::DistortionObjective2D make_objective(const akvf::TriMesh& mesh) {
  return akvf::DistortionObjective2D(mesh.F, akvf::rest_triangles(mesh), std::make_shared<akvf::SymmetricDirichlet2D>(),
                                     mesh.num_vertices());
}
}  // namespace

TEST_CASE("smallest positive root: quadratic, linear and constant cases are exact") {
  CHECK(smallest_positive_root(1, -3, 2) == doctest::Approx(1.0));  // (t - 1)(t - 2)
  CHECK(smallest_positive_root(0, -2, 3) == 1.5);                   // linear: exact -c / b
  CHECK(smallest_positive_root(0, 2, 3) == kInf);                   // linear, root at t < 0
  CHECK(smallest_positive_root(0, 0, 3) == kInf);                   // constant det
  CHECK(smallest_positive_root(1, 0, 1) == kInf);                   // no real root
  CHECK(smallest_positive_root(-1, 0, 4) == doctest::Approx(2.0));  // roots +-2
  CHECK(smallest_positive_root(1, 3, 2) == kInf);                   // roots -1, -2
}

TEST_CASE("smallest positive root stays accurate when the quadratic term is tiny") {
  // det(t) = 1e-12 t^2 - 2 t + 1: the small root is 0.5 to first order; the
  // textbook formula loses it to cancellation.
  const double t = smallest_positive_root(1e-12, -2, 1);
  CHECK(t == doctest::Approx(0.5).epsilon(1e-12));
  CHECK(std::abs(1e-12 * t * t - 2 * t + 1) <= 1e-15);
}

TEST_CASE("no step below the bound inverts a triangle (random directions on random meshes)") {
  std::mt19937 rng(17);
  std::normal_distribution<double> n;
  int tested = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const akvf::TriMesh mesh = akvf::test::grid_disk(8, 8, 0.3, trial + 1);
    const auto objective = make_objective(mesh);
    const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(akvf::test::grid_disk(8, 8), 0.2, trial + 100));
    if (objective.count_inverted(x) > 0) continue;  // the random start must be a valid map
    ++tested;
    const Eigen::VectorXd d = Eigen::VectorXd::NullaryExpr(x.size(), [&](Eigen::Index) { return n(rng); });
    const double t_max = objective.max_feasible_step(x, d);
    REQUIRE(std::isfinite(t_max));
    for (double fraction : {0.1, 0.5, 0.8, 0.99, 0.999999})
      CHECK(objective.count_inverted(x + fraction * t_max * d) == 0);
    CHECK(objective.count_inverted(x + 1.000001 * t_max * d) > 0);  // the bound is tight
  }
  CHECK(tested >= 15);
}

TEST_CASE("neither line search ever returns a step that inverts a triangle") {
  const akvf::BacktrackingLineSearch backtracking;
  const akvf::WolfeBisectionLineSearch wolfe;
  for (const akvf::LineSearch* line_search : std::initializer_list<const akvf::LineSearch*>{&backtracking, &wolfe}) {
    CAPTURE(line_search->name());
    const akvf::LineSearch& search = *line_search;
    std::mt19937 rng(23);
    std::normal_distribution<double> n;
    int tested = 0, handed_over = 0;
    for (int trial = 0; trial < 20; ++trial) {
      const akvf::TriMesh mesh = akvf::test::grid_disk(8, 8, 0.3, trial + 1);
      const auto objective = make_objective(mesh);
      const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(akvf::test::grid_disk(8, 8), 0.2, trial + 7));
      if (objective.count_inverted(x) > 0) continue;
      ++tested;
      Eigen::VectorXd g;
      const double energy = objective.value_and_gradient(x, &g);
      // A random descent direction, scaled to reach far beyond the flip bound.
      Eigen::VectorXd d = Eigen::VectorXd::NullaryExpr(x.size(), [&](Eigen::Index) { return n(rng); });
      if (d.dot(g) > 0) d = -d;
      d *= 100 / d.norm();
      const auto summary = search.search(objective, x, energy, g, d);
      REQUIRE(summary.success);
      CHECK(summary.step <= 0.8 * summary.max_feasible_step);
      CHECK(objective.count_inverted(akvf::accepted_point(x, d, summary)) == 0);
      CHECK(summary.energy < energy);
      CHECK(summary.energy <= energy + 1e-5 * summary.step * g.dot(d));  // Armijo
      // The gradient handed to the optimizer is the accepted point's, to the
      // bit, here and after a short step along -g, whose first trial (the
      // unit step) is accepted.
      const Eigen::VectorXd short_d = (-1e-4 / g.norm()) * g;
      const auto short_summary = search.search(objective, x, energy, g, short_d);
      REQUIRE(short_summary.success);
      if (line_search == &backtracking) CHECK(short_summary.evaluations == 1);
      CHECK(short_summary.gradient.size() == x.size());
      const auto check_handed_over = [&](const Eigen::VectorXd& direction, const akvf::LineSearchSummary& result) {
        if (result.gradient.size() == 0) return;
        Eigen::VectorXd at_point;
        CHECK(objective.value_and_gradient(akvf::accepted_point(x, direction, result), &at_point) == result.energy);
        CHECK(at_point == result.gradient);
        ++handed_over;
      };
      check_handed_over(d, summary);
      check_handed_over(short_d, short_summary);
    }
    CHECK(tested >= 15);
    CHECK(handed_over > 0);
  }
}

TEST_CASE("the line search reports failure for an ascent direction and keeps x") {
  const akvf::TriMesh mesh = akvf::test::grid_disk(4, 4);
  const auto objective = make_objective(mesh);
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(mesh, 0.1, 3));
  REQUIRE(objective.count_inverted(x) == 0);
  Eigen::VectorXd g;
  const double energy = objective.value_and_gradient(x, &g);
  const auto summary = akvf::BacktrackingLineSearch().search(objective, x, energy, g, g);
  CHECK_FALSE(summary.success);
  CHECK(summary.step == 0);
  CHECK(summary.energy == energy);
  CHECK(summary.message.find("search direction is not a descent direction") == 0);
}

TEST_CASE("line search settings are validated") {
  akvf::LineSearchSettings settings;
  settings.rho = 1.5;
  std::string error;
  CHECK_FALSE(settings.is_valid(&error));
  CHECK(error == "line search rho must be in (0, 1)");
  CHECK(akvf::test::error_message([&] { akvf::BacktrackingLineSearch bad(settings); }) ==
        "line search rho must be in (0, 1)");
}

TEST_CASE("Wolfe bisection satisfies the curvature condition on a smooth problem") {
  const akvf::TriMesh mesh = akvf::test::grid_disk(6, 6);
  const auto objective = make_objective(mesh);
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(akvf::test::grid_disk(6, 6), 0.15, 2));
  REQUIRE(objective.count_inverted(x) == 0);
  Eigen::VectorXd g, g_new;
  const double energy = objective.value_and_gradient(x, &g);
  const Eigen::VectorXd d = -1e-3 * g;  // short: the minimum along d lies well inside the flip-free bound
  const auto summary = akvf::WolfeBisectionLineSearch().search(objective, x, energy, g, d);
  REQUIRE(summary.success);
  objective.value_and_gradient(x + summary.step * d, &g_new);
  CHECK(g_new.dot(d) >= 0.9 * g.dot(d));
  CHECK(summary.step > 1.0);  // it extended beyond the initial step to satisfy curvature
}

TEST_CASE("cubic flip-free step: exact degenerate cases and known roots") {
  // (1 - t)(2 - t)(3 - t) = -t^3 + 6 t^2 - 11 t + 6: smallest root 1.
  CHECK(akvf::smallest_positive_root_cubic(-1, 6, -11, 6) == doctest::Approx(1.0).epsilon(1e-15));
  // (t + 1)(t + 2)(t + 3) > 0 for t > 0: no root.
  CHECK(akvf::smallest_positive_root_cubic(1, 6, 11, 6) == kInf);
  // A cubic term of 0 falls back to the quadratic and linear cases exactly.
  CHECK(akvf::smallest_positive_root_cubic(0, 0, -2, 3) == 1.5);
  CHECK(akvf::smallest_positive_root_cubic(0, 1, -3, 2) == doctest::Approx(1.0));
  // A tiny cubic term: the root near 0.5 of -2 t + 1 survives.
  CHECK(akvf::smallest_positive_root_cubic(1e-14, 0, -2, 1) == doctest::Approx(0.5).epsilon(1e-12));
  // Double root at 1 touching zero from above, then a root at 4: (t - 1)^2 (4 - t).
  const double t = akvf::smallest_positive_root_cubic(-1, 6, -9, 4);
  CHECK(t == doctest::Approx(1.0).epsilon(1e-6));
}

TEST_CASE("tet step bound: no step below it inverts a tet, a step just above does") {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> u(-1, 1);
  int bounded = 0;
  for (int trial = 0; trial < 500; ++trial) {
    Eigen::Matrix3d Ds = Eigen::Matrix3d::NullaryExpr([&](Eigen::Index, Eigen::Index) { return u(rng); });
    if (Ds.determinant() < 0) Ds.col(0) *= -1;
    if (Ds.determinant() < 1e-3) continue;
    const Eigen::Matrix3d Dd = Eigen::Matrix3d::NullaryExpr([&](Eigen::Index, Eigen::Index) { return u(rng); });
    const double t = akvf::tet_flip_step(Ds, Dd);
    for (double s : {0.1, 0.5, 0.9, 0.999999}) CHECK((Ds + s * std::min(t, 1e6) * Dd).determinant() > 0);
    if (std::isfinite(t)) {
      ++bounded;
      CHECK((Ds + 1.000001 * t * Dd).determinant() <= 1e-9);
    }
  }
  CHECK(bounded > 100);
}

TEST_CASE("backtracking tries the parabola's minimizer after a step that overshot, and keeps the lower point") {
  const akvf::TriMesh mesh = akvf::test::grid_disk(6, 6);
  const auto objective = make_objective(mesh);
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(mesh, 0.15, 2));
  REQUIRE(objective.count_inverted(x) == 0);
  Eigen::VectorXd g;
  const double energy = objective.value_and_gradient(x, &g);
  akvf::LineSearchSettings plain_settings;
  plain_settings.fit_parabola = false;
  int untouched = 0, shorter_taken = 0;
  for (const double length : {1e-3, 1e-2, 0.1, 0.3, 1.0, 3.0, 10.0}) {
    CAPTURE(length);
    const Eigen::VectorXd d = -length * g;
    const auto plain = akvf::BacktrackingLineSearch(plain_settings).search(objective, x, energy, g, d);
    const auto fitted = akvf::BacktrackingLineSearch().search(objective, x, energy, g, d);
    REQUIRE(plain.success);
    REQUIRE(fitted.success);
    // The share of the linear prediction the plain step gained.
    const double r = (energy - plain.energy) / (plain.step * -g.dot(d));
    if (!(r < 0.25)) {
      CHECK(fitted.step == plain.step);
      CHECK(fitted.evaluations == plain.evaluations);
      ++untouched;
      continue;
    }
    CHECK(fitted.evaluations == plain.evaluations + 1);
    const double shorter = plain.step / (2 * (1 - r));
    const double at_shorter = objective.value(x + shorter * d);
    CHECK(fitted.energy == std::min(plain.energy, at_shorter));
    CHECK(fitted.step == (at_shorter < plain.energy ? shorter : plain.step));
    if (at_shorter < plain.energy) ++shorter_taken;
  }
  // Both cases occur along these directions: short ones gain more than a
  // quarter of their prediction, long ones are cut by the flip-free bound.
  CHECK(untouched > 0);
  CHECK(shorter_taken > 0);
}

TEST_CASE("at the energy's rounding floor, backtracking takes the secant step that passes approximate Wolfe") {
  const akvf::TriMesh mesh = akvf::test::grid_disk(6, 6);
  const auto objective = make_objective(mesh);
  // The rest map is an isometry, the minimum; 1e-8 away from it E moves by
  // about 1e-14, below its round-off (1e-13 relative), so values cannot
  // order the points.
  const Eigen::VectorXd rest = akvf::stack_uv(mesh.V.leftCols(2));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  Eigen::VectorXd offset(rest.size());
  for (Eigen::Index i = 0; i < offset.size(); ++i) offset[i] = 1e-8 * unit(rng);
  const Eigen::VectorXd x = rest + offset;
  Eigen::VectorXd g;
  const double energy = objective.value_and_gradient(x, &g);
  for (const double length : {3.0, 10.0, 30.0}) {
    CAPTURE(length);
    // Toward the minimum, overshooting it length times: E rises at alpha = 1.
    const Eigen::VectorXd d = -length * offset;
    const auto result = akvf::BacktrackingLineSearch().search(objective, x, energy, g, d);
    REQUIRE(result.success);
    CHECK(result.evaluations == 2);
    Eigen::VectorXd g1;
    objective.value_and_gradient(x + d, &g1);
    const double descent = -g.dot(d);
    CHECK(result.step == descent / (g1.dot(d) + descent));
    CHECK(result.step == doctest::Approx(1 / length).epsilon(0.05));
    REQUIRE(result.gradient.size() == g.size());
    CHECK(result.gradient.dot(d) <= (1 - 2 * akvf::LineSearchSettings().c1) * descent);
    CHECK(result.gradient.norm() < 0.1 * g.norm());
  }
}
