// Global injectivity (framework/optimization/boundary_contact.h,
// injective_objective.h, framework/mesh/uv_overlap.h): the contact step,
// the barrier's derivatives, the crossing count, the overlap measure, and a
// run whose flip-free optimum overlaps itself kept free of overlap.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>

#include "akvf/akvf.h"
#include "akvf/internal/parameterization.h"
#include "framework/mesh/box_pairs.h"
#include "framework/mesh/uv_overlap.h"
#include "framework/optimization/boundary_contact.h"
#include "framework/optimization/distortion_objective.h"
#include "preconditioners/akvf_preconditioner_2d.h"
#include "preconditioners/contact_curvature.h"
#include "preconditioners/contact_preconditioner.h"
#include "preconditioners/newton_preconditioner.h"
#include "tests/test_support.h"

using namespace akvf;

namespace {

// A loop of the first n points of `rest`, (x, y, 0) in R^3, each corner's
// rest angle that of the polygon (convex corners: pi / 2 for the square).
BoundaryContact loop_at_rest(const Eigen::VectorXd& rest, const Eigen::VectorXd& rest_angle) {
  const int n = static_cast<int>(rest.size() / 2);
  Eigen::MatrixXd positions = Eigen::MatrixXd::Zero(n, 3);
  for (int v = 0; v < n; ++v) positions.row(v).head<2>() = rest.segment<2>(2 * v);
  std::vector<int> loop(n);
  for (int v = 0; v < n; ++v) loop[v] = v;
  return BoundaryContact({loop}, positions, rest_angle, Eigen::MatrixXi(0, 3));
}

Eigen::VectorXd square() {
  Eigen::VectorXd x(8);
  x << 0, 0, 1, 0, 1, 1, 0, 1;
  return x;
}

// The unit square's corners as one loop, at rest as it is.
BoundaryContact square_loop() { return loop_at_rest(square(), Eigen::VectorXd::Constant(4, M_PI / 2)); }

// A strip of a helicoid, radii 1 to 2, `turns` turns, rising `rise` per
// radian: its least-distorted flattening is close to an annulus sector of
// about 2 pi turns radians, which overlaps itself for more than one turn.
TriMesh helicoid_strip(double turns, double rise, int radial = 4, int around = 96) {
  TriMesh mesh;
  mesh.V.resize((radial + 1) * (around + 1), 3);
  for (int j = 0; j <= around; ++j)
    for (int i = 0; i <= radial; ++i) {
      const double theta = 2 * M_PI * turns * j / around, r = 1 + static_cast<double>(i) / radial;
      mesh.V.row(j * (radial + 1) + i) << r * std::cos(theta), r * std::sin(theta), rise * theta;
    }
  mesh.F.resize(2 * radial * around, 3);
  int f = 0;
  for (int j = 0; j < around; ++j)
    for (int i = 0; i < radial; ++i) {
      const int a = j * (radial + 1) + i, b = a + 1, c = a + radial + 1, d = c + 1;
      mesh.F.row(f++) << a, b, d;
      mesh.F.row(f++) << a, d, c;
    }
  return mesh;
}

}  // namespace

TEST_CASE("box pairs: every overlapping pair once, in order (or the grid's), as a brute force finds them") {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> place(0, 10), size(0, 1.5);
  std::vector<Box2> a(200), b(150);
  for (auto* set : {&a, &b})
    for (Box2& box : *set) {
      const double x = place(random), y = place(random);
      box = {x, y, x + size(random), y + size(random)};
    }
  std::vector<std::pair<int, int>> found, expected;
  for_each_overlapping_pair(a, b, [&](int i, int j) { found.push_back({i, j}); });
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 150; ++j)
      if (a[i].overlaps(b[j])) expected.push_back({i, j});
  CHECK(found == expected);
  // The grid's order: the same pairs, i increasing, each once.
  std::vector<std::pair<int, int>> unordered;
  for_each_overlapping_pair(
      a, b,
      [&](int i, int j) {
        unordered.push_back({i, j});
      },
      PairOrder::kGrid);
  CHECK(std::is_sorted(unordered.begin(), unordered.end(),
                       [](const auto& p, const auto& q) { return p.first < q.first; }));
  std::sort(unordered.begin(), unordered.end());
  CHECK(unordered == expected);
}

TEST_CASE("the first contact step: a corner moving onto the opposite edge, and none moving apart") {
  const BoundaryContact loop = square_loop();
  Eigen::VectorXd d = Eigen::VectorXd::Zero(8);
  d[5] = -1;  // vertex 2 (1, 1) moves down: it reaches edge 0 -> 1 (y = 0) at t = 1
  CHECK(loop.first_contact_step(square(), d, 10) == doctest::Approx(1).epsilon(1e-12));
  CHECK(std::isinf(loop.first_contact_step(square(), d, 0.5)));  // beyond the horizon
  // Vertex 2 moving diagonally toward vertex 0 meets it at t = 1 (a corner
  // of edges 3 -> 0 and 0 -> 1: point on segment at an end).
  d.setZero();
  d[4] = -1;
  d[5] = -1;
  CHECK(loop.first_contact_step(square(), d, 10) == doctest::Approx(1).epsilon(1e-12));
  // Scaling the square up never brings a vertex to an edge.
  CHECK(std::isinf(loop.first_contact_step(square(), square(), 10)));
}

TEST_CASE("the first contact step of a long sweep (sliced): a vertex on an edge there, no crossing before") {
  // A circle of 300 vertices, each moved by a random direction far longer
  // than an edge: the sweep is cut into slices, the first contact must be
  // exact all the same.
  const int n = 300;
  Eigen::VectorXd x(2 * n), d(2 * n);
  for (int v = 0; v < n; ++v) x.segment<2>(2 * v) << std::cos(2 * M_PI * v / n), std::sin(2 * M_PI * v / n);
  const BoundaryContact circle = loop_at_rest(x, Eigen::VectorXd::Constant(n, M_PI - 2 * M_PI / n));
  std::mt19937 random(7);
  std::normal_distribution<double> normal(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    CAPTURE(trial);
    for (int i = 0; i < 2 * n; ++i) d[i] = 0.05 * normal(random);
    const double t = circle.first_contact_step(x, d, 100);
    REQUIRE(std::isfinite(t));
    for (const double before : {0.25, 0.5, 0.9, 0.999}) CHECK(circle.count_crossings(x + before * t * d) == 0);
    // At t some vertex lies on an edge it is not an end of.
    const Eigen::VectorXd y = x + t * d;
    double closest = INFINITY;
    for (int v = 0; v < n; ++v)
      for (int e = 0; e < n; ++e) {
        const int a = e, b = (e + 1) % n;
        if (v == a || v == b) continue;
        const Eigen::Vector2d p = y.segment<2>(2 * v), pa = y.segment<2>(2 * a), pb = y.segment<2>(2 * b);
        const double s = std::clamp((p - pa).dot(pb - pa) / (pb - pa).squaredNorm(), 0.0, 1.0);
        closest = std::min(closest, (p - (pa + s * (pb - pa))).norm());
      }
    CHECK(closest < 1e-9);
  }
}

namespace {

// A U at rest (vertex 4 at (0.5, 0.6), its inner angle about 286
// degrees), as a loop, and mapped thinner: vertex 4 at (0.5, 0.12) is near
// edge 0 -> 1 (y = 0), within half of its rest distance 0.6 from it, and
// its inner angle, about 329 degrees, is within the angle term's reach of
// a fold.
Eigen::VectorXd u_at_rest() {
  Eigen::VectorXd rest(12);
  rest << 0, 0, 1, 0, 1, 1, 0.6, 0.9, 0.5, 0.6, 0.2, 0.8;
  return rest;
}
BoundaryContact u_loop() {
  Eigen::VectorXd rest_angle = Eigen::VectorXd::Constant(6, M_PI / 2);
  rest_angle[4] = 3 * M_PI / 2;
  return loop_at_rest(u_at_rest(), rest_angle);
}
Eigen::VectorXd u_thinner() {
  Eigen::VectorXd x = u_at_rest();
  x[9] = 0.12;
  return x;
}

}  // namespace

TEST_CASE("the barrier is zero far from contact and its gradient matches finite differences") {
  const Eigen::VectorXd rest = u_at_rest(), x = u_thinner();
  const BoundaryContact loop = u_loop();
  CHECK(loop.barrier(rest, nullptr) == 0);
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(12);
  const double value = loop.barrier(x, &gradient);
  CHECK(value > 0);
  const double h = 1e-7;
  for (int i = 0; i < 12; ++i) {
    Eigen::VectorXd plus = x, minus = x;
    plus[i] += h;
    minus[i] -= h;
    CHECK(gradient[i] ==
          doctest::Approx((loop.barrier(plus, nullptr) - loop.barrier(minus, nullptr)) / (2 * h)).epsilon(1e-5));
  }
  CHECK(square_loop().barrier(square(), nullptr) == 0);
}

TEST_CASE("each barrier term's Hessian: their sum matches finite differences of the barrier's gradient") {
  // The thinner U: a vertex-edge term (vertex 4 inside edge 0 -> 1) and an
  // angle term (at vertex 4); then vertex 4 beyond vertex 1, where its
  // distance to edge 0 -> 1 is to that end.
  const BoundaryContact loop = u_loop();
  const Eigen::VectorXd inside = u_thinner();
  Eigen::VectorXd beyond = inside;
  beyond.segment<2>(8) << 1.15, -0.05;
  for (const bool at_end : {false, true}) {
    const Eigen::VectorXd& x = at_end ? beyond : inside;
    bool angle = false, inner = false, end = false;
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(12, 12);
    for (const BoundaryContact::ActiveTerm& term : loop.active_terms(x)) {
      angle = angle || term.angle;
      // An edge's end shares none of dq/dx where the closest point is the other end.
      const bool clamped = term.gradient[1].norm() == 0 || term.gradient[2].norm() == 0;
      if (!term.angle) (clamped ? end : inner) = true;
      const Eigen::Matrix<double, 6, 6> H = BoundaryContact::hessian(term, x);
      CHECK(BoundaryContact::argument_at(term, x) == doctest::Approx(term.argument).epsilon(1e-14));
      CHECK(term.argument < term.reach);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          sum.block<2, 2>(2 * term.vertex[a], 2 * term.vertex[b]) += H.block<2, 2>(2 * a, 2 * b);
    }
    CHECK((at_end ? end : angle && inner));
    const double h = 1e-6;
    Eigen::MatrixXd differences(12, 12);
    for (int i = 0; i < 12; ++i) {
      Eigen::VectorXd plus = x, minus = x, g_plus = Eigen::VectorXd::Zero(12), g_minus = Eigen::VectorXd::Zero(12);
      plus[i] += h;
      minus[i] -= h;
      loop.barrier(plus, &g_plus);
      loop.barrier(minus, &g_minus);
      differences.col(i) = (g_plus - g_minus) / (2 * h);
    }
    CHECK((sum - differences).norm() <= 1e-5 * sum.norm());
    // A term's argument with its vertices moved is the one found there.
    Eigen::VectorXd moved = x;
    moved.segment<2>(8) += Eigen::Vector2d(0.01, 0.005);
    const std::vector<BoundaryContact::ActiveTerm> here = loop.active_terms(x), there = loop.active_terms(moved);
    REQUIRE(here.size() == there.size());
    for (std::size_t k = 0; k < here.size(); ++k) {
      REQUIRE(std::equal(here[k].vertex, here[k].vertex + 3, there[k].vertex));
      CHECK(BoundaryContact::argument_at(here[k], moved) == doctest::Approx(there[k].argument).epsilon(1e-14));
      CHECK(BoundaryContact::argument_at(here[k], moved) != doctest::Approx(here[k].argument));
    }
  }
}

TEST_CASE("boundary crossings and the rasterized overlap of a map that lies over itself") {
  // A bow tie: edges 0 -> 1 and 2 -> 3 cross.
  const BoundaryContact loop = square_loop();
  Eigen::VectorXd bow_tie(8);
  bow_tie << 0, 0, 1, 1, 1, 0, 0, 1;
  CHECK(loop.count_crossings(bow_tie) == 1);
  CHECK(loop.count_crossings(square()) == 0);

  // Two triangles of one chart, the second over half of the first.
  Eigen::MatrixXd UV(6, 2);
  UV << 0, 0, 1, 0, 0, 1, 0, 0, 0.5, 0, 0, 0.5;
  Eigen::MatrixXi F(2, 3);
  F << 0, 1, 2, 3, 4, 5;
  const UvOverlap overlap = measure_uv_overlap(UV, F, {});
  CHECK(overlap.fraction() == doctest::Approx(0.25).epsilon(0.02));
  // The same in two charts is no overlap; nor is a grid's map of itself.
  CHECK(measure_uv_overlap(UV, F, {0, 1}).overlapped_samples == 0);
  const TriMesh grid = test::grid_disk(12, 9);
  CHECK(measure_uv_overlap(grid.V.leftCols(2), grid.F, {}).overlapped_samples == 0);
  // The unit square as four triangles around v, placed so that the edge
  // from the corner (0, 0) to v passes through the sample at the centre of
  // cell (503, 414) of the 1024 x 1024 grid, up to rounding: the sample is
  // inside one of the two triangles at most, whatever the rounding.
  Eigen::MatrixXd square(5, 2);
  square << 0, 0, 1, 0, 1, 1, 0, 1, 0.5872209263578807, 0.48342219260246583;
  Eigen::MatrixXi fan(4, 3);
  fan << 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4;
  CHECK(measure_uv_overlap(square, fan, {}).overlapped_samples == 0);
}

TEST_CASE("a helicoid strip of 1.5 turns: flip-free alone overlaps, global injectivity does not") {
  const TriMesh strip = helicoid_strip(1.5, 0.05);
  ParameterizeOptions local;
  local.injectivity = akvf::Injectivity::kLocal;
  const ParameterizeResult overlapping = parameterize(strip.V, strip.F, local);
  REQUIRE(overlapping.trace.back().flips == 0);
  CHECK(overlapping.boundary_crossings > 0);
  CHECK(overlapping.overlap_fraction > 0.05);

  const ParameterizeResult injective = parameterize(strip.V, strip.F);
  CHECK(injective.status == TerminationStatus::kConverged);
  CHECK(injective.boundary_crossings == 0);
  CHECK(injective.overlap_fraction == 0);
  for (const IterationSummary& row : injective.trace) CHECK(row.flips == 0);
  // Held apart, the map is more distorted than the overlapping one.
  CHECK(injective.energy() > overlapping.energy());

  // L-BFGS too: its line search refuses a point past a contact.
  ParameterizeOptions lbfgs;
  lbfgs.preconditioner = "lbfgs";
  lbfgs.max_iters = 300;
  const ParameterizeResult quasi_newton = parameterize(strip.V, strip.F, lbfgs);
  CHECK(quasi_newton.boundary_crossings == 0);
  CHECK(quasi_newton.overlap_fraction == 0);
}

TEST_CASE("MIPS held apart by the barrier converges with AKVF and the default: the barrier stiffens the dilation") {
  // MIPS's K_0 has the dilation in its null space; the barrier, pressing
  // the strip's turns apart, is not scale invariant and stiffens it, so
  // P + C's null space is the rigid motions alone (ComponentMotions::
  // keep_unstiffened_by); projecting the dilation out of (P + C)^-1 g
  // would give directions that climb.
  const TriMesh strip = helicoid_strip(1.5, 0.05);
  for (const char* preconditioner : {"akvf", "akvf-newton"}) {
    CAPTURE(preconditioner);
    ParameterizeOptions options;
    options.energy = "mips";
    options.preconditioner = preconditioner;
    const ParameterizeResult result = parameterize(strip.V, strip.F, options);
    CHECK(result.status == TerminationStatus::kConverged);
    CHECK(result.boundary_crossings == 0);
    for (const IterationSummary& row : result.trace) CHECK(row.flips == 0);
  }
}

TEST_CASE("a globally injective map restarts at the energy it ended with, the boundary barrier included") {
  // The barrier is held at the end (the strip's turns press on each other),
  // so the restart's scale is the best of distortion plus barrier.
  const TriMesh strip = helicoid_strip(1.5, 0.05);
  akvf::Parameterizer solver(strip.V, strip.F);
  const ParameterizeResult first = solver.solve();
  REQUIRE(first.status == TerminationStatus::kConverged);
  REQUIRE(first.energy() > first.distortion_energy * (1 + 1e-6));  // the barrier is active
  const ParameterizeResult again = solver.solve(first.uv / 7.0);   // any scale
  CHECK(std::abs(again.trace.front().energy - first.trace.back().energy) <= 1e-9 * first.trace.back().energy);
}

TEST_CASE(
    "the barrier's curvature in a factored P: the sum of its terms, a pattern that grows and shrinks, P + C solved") {
  // The helicoid strip held off its own overlap: its final map presses the
  // boundary on itself.
  const ParamConfig config;
  const ParamSetup setup = prepare_parameterization(helicoid_strip(1.5, 0.05), "strip", config);
  const ParamRun run = run_parameterization(setup, config, {});
  const Eigen::VectorXd& x = run.result.x;
  const std::vector<BoundaryContact::ActiveTerm> terms = setup.boundary_contact->active_terms(x);
  REQUIRE(!terms.empty());
  const Eigen::Index n = x.size();
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(n, n);
  for (const BoundaryContact::ActiveTerm& term : terms)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        expected.block<2, 2>(2 * term.vertex[a], 2 * term.vertex[b]) +=
            term.curvature * term.gradient[a] * term.gradient[b].transpose();
  const int nv = setup.objective->num_vertices();
  ContactCurvature curvature(setup.boundary_contact, nv);
  const Eigen::MatrixXd upper = Eigen::MatrixXd(curvature.at(x));
  const Eigen::MatrixXd full = upper + upper.transpose() - Eigen::MatrixXd(upper.diagonal().asDiagonal());
  CHECK((full - expected).norm() <= 1e-12 * expected.norm());
  CHECK(curvature.pattern_version() == 1);
  // The pattern also holds the pairs of the terms within twice their reach
  // (those within their reach are the active ones).
  const std::vector<std::array<int, 3>> active = setup.boundary_contact->terms_within(x, 1);
  REQUIRE(active.size() == terms.size());
  for (std::size_t k = 0; k < terms.size(); ++k) CHECK(std::equal(active[k].begin(), active[k].end(), terms[k].vertex));
  const std::vector<std::array<int, 3>> near =
      setup.boundary_contact->terms_within(x, ContactCurvature::kProspectiveReach);
  CHECK(near.size() > terms.size());
  const Eigen::SparseMatrix<double>& pattern = curvature.at(x);
  const auto stored = [&](int row, int column) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(pattern, column); it; ++it)
      if (it.row() == row) return true;
    return false;
  };
  for (const std::array<int, 3>& vertex : near)
    for (int a : vertex)
      for (int b : vertex)
        if (a <= b) CHECK(stored(2 * a, 2 * b + 1));
  // The pattern's vertex pairs: a diagonal pair stores 3 entries (2 on the
  // diagonal), another 4.
  const auto pairs_of = [](const Eigen::SparseMatrix<double>& matrix) {
    Eigen::Index diagonal = 0;
    for (int column = 0; column < matrix.outerSize(); ++column)
      for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, column); it; ++it) diagonal += it.row() == column;
    return diagonal / 2 + (matrix.nonZeros() - 3 * diagonal / 2) / 4;
  };
  // Another map's terms add their pairs (the start map's boundary, pressed
  // on a circle, brings many). Back at x, C is the same; the pattern is
  // rebuilt from the terms within twice their reach, as the first call at x
  // built it, since they couple fewer than a quarter of its pairs (6 a term
  // at most); and it does not change again.
  const Eigen::Index nonzeros = curvature.at(x).nonZeros();
  const int version = curvature.pattern_version();
  const Eigen::Index grown_pairs = pairs_of(curvature.at(setup.x0));
  CHECK(curvature.pattern_version() == version + 1);
  REQUIRE(6 * near.size() * ContactCurvature::kShrinkRatio < static_cast<std::size_t>(grown_pairs));
  const Eigen::SparseMatrix<double>& again = curvature.at(x);
  CHECK(curvature.pattern_version() == version + 2);
  CHECK(again.nonZeros() == nonzeros);
  CHECK((Eigen::MatrixXd(again) - upper).norm() == 0);
  curvature.at(x);
  CHECK(curvature.pattern_version() == version + 2);
  // A pattern whose near terms keep a quarter of its pairs stays: x0's
  // pattern is kept at x0 after x's pairs are added to it.
  curvature.at(setup.x0);
  const int at_start = curvature.pattern_version();
  CHECK((Eigen::MatrixXd(curvature.at(setup.x0)) -
         Eigen::MatrixXd(ContactCurvature(setup.boundary_contact, nv).at(setup.x0)))
            .norm() == 0);
  CHECK(curvature.pattern_version() == at_start);

  // Projected Newton's C: each term's whole Hessian with its negative
  // eigenvalues clamped, positive semi-definite; in Newton's exact tries
  // each term's whole Hessian as it is (some of them indefinite).
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  const auto sum_of_terms = [&](const std::function<Matrix6(const Matrix6&)>& filter) {
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(n, n);
    for (const BoundaryContact::ActiveTerm& term : terms) {
      const Matrix6 H = filter(BoundaryContact::hessian(term, x));
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          sum.block<2, 2>(2 * term.vertex[a], 2 * term.vertex[b]) += H.block<2, 2>(2 * a, 2 * b);
    }
    return sum;
  };
  const auto symmetric = [](const Eigen::SparseMatrix<double>& upper_part) {
    const Eigen::MatrixXd dense(upper_part);
    return Eigen::MatrixXd(dense + dense.transpose() - Eigen::MatrixXd(dense.diagonal().asDiagonal()));
  };
  const Eigen::MatrixXd projected = sum_of_terms([](const Matrix6& H) {
    const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(H);
    return Matrix6(eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
                   eigen.eigenvectors().transpose());
  });
  const Eigen::MatrixXd whole = symmetric(curvature.at(x, ContactModel::kProjectedHessian));
  CHECK((whole - projected).norm() <= 1e-12 * projected.norm());
  CHECK(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(whole).eigenvalues().minCoeff() >= -1e-9 * projected.norm());
  CHECK((whole - full).norm() > 1e-6 * full.norm());  // the curvature of q counts
  const Eigen::MatrixXd exact_sum = sum_of_terms([](const Matrix6& H) { return H; });
  const Eigen::MatrixXd exact = symmetric(curvature.at(x, ContactModel::kHessian));
  CHECK((exact - exact_sum).norm() <= 1e-12 * exact_sum.norm());
  CHECK((exact - whole).norm() > 1e-6 * whole.norm());

  // AKVF with C in its factor gives the direction of AKVF with C added by
  // the Woodbury identity over every term.
  AkvfOptions2D with_contact;
  with_contact.factor.contact_curvature = std::make_shared<ContactCurvature>(setup.boundary_contact, nv);
  with_contact.factor.reuse_tolerance = 0;  // a factorization at every update (below)
  AkvfPreconditioner2D factored(*setup.objective, with_contact);
  ContactPreconditioner woodbury(std::make_unique<AkvfPreconditioner2D>(*setup.objective), setup.boundary_contact,
                                 static_cast<int>(terms.size()));
  Eigen::VectorXd gradient;
  const double energy = setup.objective->value_and_gradient(x, &gradient);
  const OptimizationState state{x, gradient, energy, 0};
  factored.update(state);
  woodbury.update(state);
  Eigen::VectorXd d_factored, d_woodbury;
  factored.apply(gradient, &d_factored);
  woodbury.apply(gradient, &d_woodbury);
  CHECK((d_factored - d_woodbury).norm() <= 1e-6 * d_woodbury.norm());
  // P + C again on the same pattern (its values added where the first
  // update placed them): at another map, the same bits as a preconditioner
  // built there; at x again, the first direction.
  Eigen::VectorXd moved = x + 1e-4 * d_factored, moved_gradient;
  const double moved_energy = setup.objective->value_and_gradient(moved, &moved_gradient);
  const OptimizationState moved_state{moved, moved_gradient, moved_energy, 1};
  REQUIRE(setup.boundary_contact->active_terms(moved).size() == terms.size());
  factored.update(moved_state);
  AkvfOptions2D fresh_options = with_contact;
  fresh_options.factor.contact_curvature = std::make_shared<ContactCurvature>(setup.boundary_contact, nv);
  fresh_options.factor.contact_curvature->at(x);  // the same pattern as factored's
  AkvfPreconditioner2D fresh(*setup.objective, fresh_options);
  fresh.update(moved_state);
  Eigen::VectorXd d_moved, d_fresh, d_again;
  factored.apply(moved_gradient, &d_moved);
  fresh.apply(moved_gradient, &d_fresh);
  CHECK((d_moved - d_fresh).norm() == 0);
  factored.update(state);
  factored.apply(gradient, &d_again);
  CHECK((d_again - d_factored).norm() == 0);
}
