// The algebraic multigrid solve path (--linear-solver amg): hypre's V-cycle as
// a symmetric preconditioner, every factored preconditioner solving with it,
// and whole runs that match the Cholesky path's results.
#include <doctest/doctest.h>

#include <random>

#include "akvf/catalog.h"
#include "akvf/deform.h"
#include "akvf/internal/option_schema.h"
#include "akvf/internal/parameterization.h"
#include "akvf/internal/preconditioner_settings.h"
#include "akvf/motion_bases.h"
#include "akvf/parameterize.h"
#include "framework/optimization/distortion_objective.h"
#include "preconditioners/akvf_preconditioner_2d.h"
#include "solvers/algebraic_multigrid.h"
#include "solvers/symbolic_analysis_cache.h"
#include "tests/test_support.h"

namespace {

// K(x) + eps I of a curved grid at its Tutte map (Eq. (5)), as the AKVF
// preconditioner assembles it: upper triangle, 2 unknowns per vertex.
Eigen::SparseMatrix<double> killing_operator(const akvf::ParamSetup& setup) {
  akvf::AkvfPreconditioner2D akvf(*setup.objective);
  Eigen::VectorXd g;
  const double energy = setup.objective->value_and_gradient(setup.x0, &g);
  akvf.update({setup.x0, g, energy, 0});
  return akvf.matrix().upper();
}

Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = u(rng);
  return v;
}

}  // namespace

TEST_CASE("without hypre the multigrid path says what to install, with it a V-cycle is a symmetric contraction") {
  const akvf::ParamSetup setup = akvf::prepare_parameterization(akvf::test::bumpy_disk(30, 25), "bumpy", {});
  const Eigen::SparseMatrix<double> upper = killing_operator(setup);
  akvf::AlgebraicMultigrid multigrid;
  if (!akvf::AlgebraicMultigrid::available()) {
    CHECK(akvf::test::error_message([&] { multigrid.setup(upper, 2); }).find("install libhypre-dev") !=
          std::string::npos);
    return;
  }
  multigrid.setup(upper, 2);
  REQUIRE(multigrid.ready());
  const auto A = upper.selfadjointView<Eigen::Upper>();
  // Right-hand sides free of K's null space (the rigid motions), as the
  // preconditioners pass them.
  const Eigen::MatrixXd motions = akvf::rigid_motion_basis_2d(setup.x0);
  Eigen::VectorXd u = random_vector(upper.rows(), 1), v = random_vector(upper.rows(), 2);
  u -= motions * (motions.transpose() * u);
  v -= motions * (motions.transpose() * v);
  Eigen::VectorXd Mu, Mv;
  multigrid.apply(u, &Mu);
  multigrid.apply(v, &Mv);
  // Symmetric: v . M u = u . M v, and positive.
  CHECK(v.dot(Mu) == doctest::Approx(u.dot(Mv)).epsilon(1e-10));
  CHECK(u.dot(Mu) > 0);
  // One cycle from zero removes most of the error: |u - A M u| well below |u|.
  const Eigen::VectorXd residual = u - A * Mu;
  CHECK(residual.norm() < 0.5 * u.norm());
  // A second setup replaces the first (no leak, same results).
  multigrid.setup(upper, 2);
  Eigen::VectorXd again;
  multigrid.apply(u, &again);
  CHECK((again - Mu).norm() <= 1e-12 * Mu.norm());
}

TEST_CASE("AKVF with the multigrid solve: a direction within the tolerance of K's solve, rigid motions removed") {
  if (!akvf::AlgebraicMultigrid::available()) {
    const akvf::TriMesh mesh = akvf::test::bumpy_disk(6, 6);
    CHECK_THROWS_AS(akvf::parameterize(mesh.V, mesh.F,
                                       [] {
                                         akvf::ParameterizeOptions o;
                                         o.linear_solver = akvf::LinearSolver::kAmg;
                                         return o;
                                       }()),
                    akvf::OptionsError);
    return;
  }
  // K at the Tutte start of a curved grid, solved both ways.
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(25, 20);
  const akvf::ParamConfig config;
  const akvf::ParamSetup setup = akvf::prepare_parameterization(mesh, "bumpy", config);
  Eigen::VectorXd g;
  const double energy = setup.objective->value_and_gradient(setup.x0, &g);
  akvf::AkvfOptions2D cholmod_options, amg_options;
  cholmod_options.factor.reuse_tolerance = 0;
  amg_options.factor.linear_solver = akvf::LinearSolver::kAmg;
  akvf::AkvfPreconditioner2D exact(*setup.objective, cholmod_options), multigrid(*setup.objective, amg_options);
  Eigen::VectorXd d_exact, d_multigrid;
  exact.update({setup.x0, g, energy, 0});
  exact.apply(g, &d_exact);
  multigrid.update({setup.x0, g, energy, 0});
  multigrid.apply(g, &d_multigrid);
  CHECK(multigrid.statistics().multigrid_setups == 1);
  CHECK(multigrid.statistics().factorizations == 0);
  // The residual of K d = g is what CG controls: at most 1e-2 |g| (the
  // exact direction's own is round-off), so the directions agree in K's norm.
  const auto K = multigrid.matrix().upper().selfadjointView<Eigen::Upper>();
  const Eigen::MatrixXd motions = akvf::rigid_motion_basis_2d(setup.x0);
  Eigen::VectorXd g_free = g - motions * (motions.transpose() * g);
  CHECK((K * d_multigrid - g_free).norm() <= 1.01e-2 * g.norm());
  CHECK((motions.transpose() * d_multigrid).norm() <= 1e-10 * d_multigrid.norm());
  const Eigen::VectorXd difference = d_multigrid - d_exact;
  CHECK(std::sqrt(difference.dot(K * difference)) <= 0.05 * std::sqrt(d_exact.dot(K * d_exact)));
  CHECK(g.dot(d_multigrid) > 0);
  // The next solve on the same matrix reuses the hierarchy.
  multigrid.update({setup.x0, g, energy, 1});
  multigrid.apply(g, &d_multigrid);
  CHECK(multigrid.statistics().multigrid_setups == 1);
  CHECK(multigrid.statistics().reused_solves == 1);
}

TEST_CASE("every preconditioner with --linear-solver amg reaches the Cholesky runs' energy, flip-free throughout") {
  if (!akvf::AlgebraicMultigrid::available()) return;  // the case above checks the message
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(16, 14);
  for (const std::string method : {"akvf", "newton", "akvf-newton", "slim", "laplacian"}) {
    CAPTURE(method);
    akvf::ParameterizeOptions options;
    options.preconditioner = method;
    options.grad_tol = 1e-5;
    options.max_iters = 3000;
    options.linear_solver = akvf::LinearSolver::kCholmod;
    const akvf::ParameterizeResult cholmod = akvf::parameterize(mesh.V, mesh.F, options);
    options.linear_solver = akvf::LinearSolver::kAmg;
    const akvf::ParameterizeResult amg = akvf::parameterize(mesh.V, mesh.F, options);
    CHECK(cholmod.status == akvf::TerminationStatus::kConverged);
    CHECK(amg.status == akvf::TerminationStatus::kConverged);
    CHECK(amg.energy() == doctest::Approx(cholmod.energy()).epsilon(1e-8));
    for (const auto& row : amg.trace) CHECK(row.flips == 0);
    CHECK(amg.statistics.preconditioner.multigrid_setups >= 1);
    CHECK(amg.statistics.preconditioner.factorizations == 0);
    CHECK(amg.preconditioner_report.find("multigrid setups") != std::string::npos);
  }
}

TEST_CASE("3D deformation with --linear-solver amg: the Cholesky runs' energy, no inverted tet") {
  if (!akvf::AlgebraicMultigrid::available()) return;
  const akvf::TetMesh mesh = akvf::test::tet_grid(4);
  akvf::PositionConstraints constraints;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (mesh.V(v, 2) == 0 || mesh.V(v, 2) == 1) constraints.vertices.push_back(v);
  constraints.targets.resize(static_cast<Eigen::Index>(constraints.vertices.size()), 3);
  for (std::size_t c = 0; c < constraints.vertices.size(); ++c) {
    constraints.targets.row(c) = mesh.V.row(constraints.vertices[c]);
    if (mesh.V(constraints.vertices[c], 2) == 1) constraints.targets(c, 2) = 1.3;
  }
  for (const std::string method : {"akvf", "newton", "slim", "laplacian"}) {
    for (const bool hard : {false, true}) {
      CAPTURE(method);
      CAPTURE(hard);
      akvf::DeformOptions options;
      options.preconditioner = method;
      options.hard = hard;
      options.grad_tol = 1e-6;
      options.max_iters = 2000;
      options.linear_solver = akvf::LinearSolver::kCholmod;
      const akvf::DeformResult cholmod = akvf::deform(mesh.V, mesh.T, constraints, options);
      options.linear_solver = akvf::LinearSolver::kAmg;
      const akvf::DeformResult amg = akvf::deform(mesh.V, mesh.T, constraints, options);
      CHECK(akvf::is_normal_termination(amg.status));
      CHECK(amg.energy() == doctest::Approx(cholmod.energy()).epsilon(1e-6));
      for (const auto& row : amg.trace) CHECK(row.flips == 0);
      CHECK(amg.statistics.preconditioner.multigrid_setups >= 1);
    }
  }
}

TEST_CASE("--linear-solver: names checked, auto decides from the factor's size when multigrid is built in") {
  akvf::ParameterizeOptions options;
  CHECK(akvf::test::error_message([&] {
          akvf::set_option_text(akvf::parameterize_option_fields(), "linear_solver", "umfpack", &options);
        }) == "unknown linear solver 'umfpack' (valid: auto, cholmod, amg)");
  akvf::set_option_text(akvf::parameterize_option_fields(), "linear_solver", "amg", &options);
  CHECK(options.linear_solver == akvf::LinearSolver::kAmg);
  CHECK(akvf::available_linear_solver(akvf::LinearSolver::kCholmod) == akvf::LinearSolver::kCholmod);
  CHECK(akvf::available_linear_solver(akvf::LinearSolver::kAmg) == akvf::LinearSolver::kAmg);
  CHECK(akvf::available_linear_solver(akvf::LinearSolver::kAuto) ==
        (akvf::AlgebraicMultigrid::available() ? akvf::LinearSolver::kAuto : akvf::LinearSolver::kCholmod));
}

TEST_CASE("auto: CHOLMOD while the factor fits the limit, multigrid (and no kept analysis) beyond it") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(25, 20);
  const akvf::ParamConfig config;
  const akvf::ParamSetup setup = akvf::prepare_parameterization(mesh, "bumpy", config);
  Eigen::VectorXd g;
  const double energy = setup.objective->value_and_gradient(setup.x0, &g);
  const auto run = [&](double limit, const std::shared_ptr<akvf::SymbolicAnalysisCache>& cache) {
    akvf::AkvfOptions2D options;
    options.factor.linear_solver = akvf::LinearSolver::kAuto;
    options.factor.auto_factor_bytes = limit;
    options.factor.analysis_cache = cache;
    akvf::AkvfPreconditioner2D preconditioner(*setup.objective, options);
    Eigen::VectorXd d;
    preconditioner.update({setup.x0, g, energy, 0});
    preconditioner.apply(g, &d);
    CHECK(g.dot(d) > 0);
    return preconditioner.statistics();
  };
  // The default limit (half the memory) keeps this small mesh on CHOLMOD.
  const akvf::PreconditionerStatistics small = run(0, nullptr);
  CHECK(small.factorizations == 1);
  CHECK(small.multigrid_setups == 0);
  // A limit below the factor's size takes the multigrid path when there is one.
  const auto cache = std::make_shared<akvf::SymbolicAnalysisCache>();
  const akvf::PreconditionerStatistics large = run(1000, cache);
  CHECK(large.factorizations == (akvf::AlgebraicMultigrid::available() ? 0 : 1));
  CHECK(large.multigrid_setups == (akvf::AlgebraicMultigrid::available() ? 1 : 0));
  if (akvf::AlgebraicMultigrid::available()) {
    // The analysis made for the choice was not kept: analyzing again computes it.
    akvf::SparseCholesky cholesky;
    akvf::ElementMatrix2D K(setup.objective->elements(), setup.objective->num_vertices());
    CHECK(cache->analyze(K.upper(), 2, &cholesky));
  }
}
