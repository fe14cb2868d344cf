// The 3D preconditioners (projected Newton, Laplacian, SLIM, AKVF's scale),
// soft and hard constraints, and every 3D energy with every 3D method.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <random>

#include "akvf/backtracking_line_search.h"
#include "akvf/catalog.h"
#include "akvf/constrained_objective.h"
#include "akvf/internal/deformation.h"
#include "akvf/internal/preconditioner_settings.h"
#include "akvf/threads.h"
#include "energies/amips.h"
#include "energies/arap.h"
#include "energies/exp_symmetric_dirichlet.h"
#include "energies/invariant_density_3d.h"
#include "energies/mips.h"
#include "energies/symmetric_dirichlet.h"
#include "framework/optimization/distortion_objective.h"
#include "preconditioners/akvf_preconditioner_3d.h"
#include "preconditioners/energy_scale.h"
#include "preconditioners/laplacian_preconditioner.h"
#include "preconditioners/newton_preconditioner.h"
#include "preconditioners/slim_preconditioner.h"
#include "tests/density_checks.h"
#include "tests/test_support.h"

namespace {

// The relative Tikhonov shift every factored P carries (factored_preconditioner.h).
const double kShift = akvf::FactorOptions{}.tikhonov;

akvf::DistortionObjective3D grid_objective(const akvf::TetMesh& mesh,
                                           std::shared_ptr<const akvf::DistortionDensity<3>> density) {
  return akvf::DistortionObjective3D(mesh.T, akvf::rest_tets(mesh), std::move(density), mesh.num_vertices());
}

// The grid's bottom face fixed and its top face turned by `angle` about the vertical axis.
akvf::PositionConstraints twisted_top(const akvf::TetMesh& mesh, double angle) {
  akvf::PositionConstraints constraints;
  std::vector<Eigen::RowVector3d> targets;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Eigen::RowVector3d p = mesh.V.row(v);
    if (p.z() != 0 && p.z() != 1) continue;
    const Eigen::Vector3d centred(p.x() - 0.5, p.y() - 0.5, 0);
    const double turn = p.z() == 1 ? angle : 0.0;
    constraints.vertices.push_back(v);
    targets.push_back((Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()) * centred).transpose() +
                      Eigen::RowVector3d(0.5, 0.5, p.z()));
  }
  constraints.targets.resize(static_cast<Eigen::Index>(targets.size()), 3);
  for (std::size_t c = 0; c < targets.size(); ++c) constraints.targets.row(c) = targets[c];
  return constraints;
}

}  // namespace

TEST_CASE("3D Newton, Laplacian and SLIM: symmetric PSD, the expected null spaces, descent directions") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(2);
  const akvf::DistortionObjective3D objective = grid_objective(mesh, std::make_shared<akvf::SymmetricDirichlet3D>());
  const Eigen::VectorXd x = akvf::test::distorted_tet_positions(mesh, 3);
  Eigen::VectorXd g, d;
  objective.value_and_gradient(x, &g);
  akvf::NewtonPreconditioner3D newton(objective);
  akvf::LaplacianPreconditioner3D laplacian(objective);
  akvf::SlimPreconditioner3D slim(objective);
  const Eigen::MatrixXd translations = akvf::translation_basis(3, mesh.num_vertices());
  for (akvf::FactoredPreconditioner3D* p :
       std::initializer_list<akvf::FactoredPreconditioner3D*>{&newton, &laplacian, &slim}) {
    CAPTURE(p->name());
    p->update({x, g, 0.0, 1});
    p->apply(g, &d);
    CHECK(d.allFinite());
    CHECK(g.dot(d) > 0);
    // The factored matrix is P + eps I with eps = tikhonov * mean(diag P): remove the shift to test P.
    Eigen::MatrixXd P(p->matrix().full());
    P.diagonal().array() -= kShift * P.diagonal().mean() / (1 + kShift);
    CHECK((P - P.transpose()).norm() <= 1e-12 * P.norm());
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(P);
    CHECK(eig.eigenvalues().minCoeff() >= -1e-9 * eig.eigenvalues().maxCoeff());
    CHECK((P * translations).norm() <= 1e-8 * P.norm());
  }
}

TEST_CASE_TEMPLATE("3D Newton assembled from the density's eigensystem is the filtered element Hessians' sum", Density,
                   akvf::SymmetricDirichlet3D, akvf::Arap3D) {
  const akvf::TetMesh mesh = akvf::test::tet_grid(2);
  const akvf::DistortionObjective3D with_modes = grid_objective(mesh, std::make_shared<Density>());
  const akvf::DistortionObjective3D hessians_only =
      grid_objective(mesh, std::make_shared<akvf::test::HessiansOnly<3, Density>>());
  const Eigen::VectorXd x = akvf::test::distorted_tet_positions(mesh, 3);
  Eigen::VectorXd g;
  const double energy = with_modes.value_and_gradient(x, &g);
  for (const akvf::EigenvalueFilter filter : {akvf::EigenvalueFilter::kClamp, akvf::EigenvalueFilter::kAbsolute}) {
    CAPTURE(static_cast<int>(filter));
    akvf::NewtonPreconditioner3D from_modes(with_modes, {}, akvf::default_newton_projection(3), filter);
    akvf::NewtonPreconditioner3D from_hessians(hessians_only, {}, akvf::default_newton_projection(3), filter);
    for (akvf::NewtonPreconditioner3D* p : {&from_modes, &from_hessians}) p->update({x, g, energy, 1});
    const Eigen::SparseMatrix<double>& expected = from_hessians.matrix().upper();
    CHECK((from_modes.matrix().upper() - expected).norm() <= 1e-12 * expected.norm());
  }
}

TEST_CASE("3D Newton's model of ARAP adds the log-area damping g_hat (d det J / det J)^2 of each tet") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(2);
  const akvf::DistortionObjective3D damped =
      grid_objective(mesh, std::make_shared<akvf::test::HessiansOnly<3, akvf::Arap3D>>());
  const akvf::DistortionObjective3D undamped =
      grid_objective(mesh, std::make_shared<akvf::test::HessiansOnlyWithoutOnset<3, akvf::Arap3D>>());
  const Eigen::VectorXd x = akvf::test::distorted_tet_positions(mesh, 3);
  Eigen::VectorXd v;
  const double difference = akvf::test::newton_matrix_difference<3>(damped, undamped, x, 5, &v);
  double expected = 0;  // J is linear in the positions: jacobian(v, e) is J's change along v
  for (int e = 0; e < damped.weights().size(); ++e) {
    const Eigen::Matrix3d J = damped.jacobian(x, e);
    const double along = (akvf::cofactor_3d(J).array() * damped.jacobian(v, e).array()).sum();
    expected += damped.weights()[e] * akvf::Arap3D::collapse_volume_ratio() * along * along /
                (J.determinant() * J.determinant());
  }
  CHECK(expected > 0);
  CHECK(difference == doctest::Approx(expected).epsilon(1e-9));
}

TEST_CASE("the 3D SLIM proxy's gradient equals the energy's gradient for the isometric energies") {
  // (For AMIPS and the 3D MIPS w_i^2 can be negative and is clamped: see
  // slim_preconditioner.h.)
  const akvf::SymmetricDirichlet3D sd;
  const akvf::ExpSymmetricDirichlet3D exp_sd(0.2);
  const akvf::Arap3D arap;
  std::mt19937 rng(5);
  for (const akvf::DistortionDensity<3>* density :
       std::initializer_list<const akvf::DistortionDensity<3>*>{&sd, &exp_sd, &arap}) {
    CAPTURE(density->name());
    const auto& sigma_derivative = dynamic_cast<const akvf::SingularValueDerivative<3>&>(*density);
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::Matrix3d J = akvf::test::random_jacobian<3>(rng, 0.4, 2.5);
      Eigen::Matrix3d WtW, R, dD;
      akvf::SlimPreconditioner3D::proxy_weights(sigma_derivative, J, &WtW, &R);
      density->value_and_gradient(J, &dD);
      CHECK((2 * WtW * (J - R) - dD).norm() <= 1e-9 * std::max(1.0, dD.norm()));
      CHECK(R.determinant() == doctest::Approx(1.0));
    }
  }
}

TEST_CASE("3D AKVF scales K to the energy: rest shear curvature first, then the secant of the last step") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(2);
  const auto density = std::make_shared<akvf::ExpSymmetricDirichlet3D>(0.5);
  const akvf::DistortionObjective3D objective = grid_objective(mesh, density);
  const Eigen::VectorXd x1 = akvf::test::distorted_tet_positions(mesh, 11),
                        x2 = akvf::test::distorted_tet_positions(mesh, 12);
  Eigen::VectorXd g1, g2;
  objective.value_and_gradient(x1, &g1);
  objective.value_and_gradient(x2, &g2);
  akvf::AkvfOptions3D options;
  options.factor.absolute_shift = 0;  // test s K alone (plus the 1e-8 relative shift)
  akvf::AkvfPreconditioner3D preconditioner(objective, options);
  preconditioner.update({x1, g1, 0.0, 1});
  akvf::ElementMatrix3D K(mesh.T, mesh.num_vertices());
  akvf::assemble_killing_operator_3d(mesh.T, x1, &K);
  const double first_scale = akvf::rest_shear_curvature(*density) / (4 * objective.rest().total_volume);
  CHECK(preconditioner.matrix().upper().coeff(0, 0) ==
        doctest::Approx(first_scale * K.upper().coeff(0, 0) * (1 + 1e-8)));
  preconditioner.update({x2, g2, 0.0, 2});
  const Eigen::VectorXd dx = x2 - x1;
  const Eigen::MatrixXd P(preconditioner.matrix().full());
  CHECK(dx.dot(P * dx) == doctest::Approx(dx.dot(g2 - g1)).epsilon(1e-6));
}

TEST_CASE("a stretched cube relaxes to symmetric Dirichlet 6 (a rigid motion of the rest shape) with 3D AKVF") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(3);
  const akvf::DistortionObjective3D objective = grid_objective(mesh, std::make_shared<akvf::SymmetricDirichlet3D>());
  const Eigen::VectorXd stretched = akvf::stack_rows(mesh.V * Eigen::Vector3d(1.4, 0.8, 1.1).asDiagonal());
  akvf::AkvfOptions3D options;
  options.project_rigid = true;  // no constraints: the energy is rigid-invariant
  akvf::AkvfPreconditioner3D preconditioner(objective, options);
  const akvf::BacktrackingLineSearch line_search(akvf::LineSearchSettings{});
  akvf::OptimizerOptions stop;
  stop.gradient_tolerance = 1e-9;
  stop.max_iterations = 300;
  const akvf::OptimizerResult result = akvf::minimize(objective, preconditioner, line_search, stretched, stop);
  CHECK(result.status == akvf::TerminationStatus::kConverged);
  CHECK(result.trace.front().energy > 6.5);
  CHECK(result.trace.back().energy == doctest::Approx(6.0).epsilon(1e-10));
  for (const auto& row : result.trace) CHECK(row.flips == 0);
}

TEST_CASE("every 3D energy with every 3D method under soft constraints: no flip, the energy never rises") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(3);
  const akvf::PositionConstraints constraints = twisted_top(mesh, 0.5);
  for (const auto& energy_entry : akvf::energies_3d().entries())
    for (const auto& method_entry : akvf::preconditioners_3d().entries()) {
      // Named copies: clang 14 cannot capture structured bindings in CAPTURE's lambda.
      const std::string& energy = energy_entry.first;
      const std::string& method = method_entry.first;
      CAPTURE(energy);
      CAPTURE(method);
      akvf::DeformConfig config;
      config.energy = energy;
      config.energy_settings.exponent = 0.1;
      config.preconditioner = method;
      config.optimizer.max_iterations = 30;
      const auto run = akvf::run_deformation(mesh, "grid", constraints, config);
      CHECK(akvf::is_normal_termination(run.result.status));
      for (std::size_t i = 1; i < run.result.trace.size(); ++i) {
        CHECK(run.result.trace[i].flips == 0);
        CHECK(run.result.trace[i].energy <= run.result.trace[i - 1].energy);
      }
      CHECK(run.result.trace.back().energy < run.result.trace.front().energy);
    }
}

TEST_CASE("AKVF as written in Sec. 6.2 (K + c I alone) also runs without flips, and more slowly") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(3);
  const akvf::PositionConstraints constraints = twisted_top(mesh, 0.5);
  akvf::DeformConfig config;
  config.preconditioner = "akvf";  // the paper's method, not the default (which switches to Newton)
  config.optimizer.max_iterations = 20;
  const auto scaled = akvf::run_deformation(mesh, "grid", constraints, config);
  config.akvf_as_written = true;
  const auto as_written = akvf::run_deformation(mesh, "grid", constraints, config);
  for (const auto& row : as_written.result.trace) CHECK(row.flips == 0);
  CHECK(as_written.result.trace.back().energy < as_written.result.trace.front().energy);
  CHECK(scaled.result.trace.back().energy < as_written.result.trace.back().energy);
}

TEST_CASE("hard constraints: the constrained vertices sit at their targets at every iterate") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(3);
  const akvf::PositionConstraints constraints = twisted_top(mesh, 0.15);
  for (const auto& entry : akvf::preconditioners_3d().entries()) {
    const std::string& method = entry.first;  // clang 14 cannot capture a structured binding
    CAPTURE(method);
    akvf::DeformConfig config;
    config.preconditioner = method;
    config.hard_constraints = true;
    config.optimizer.max_iterations = 20;
    int checked = 0;
    const akvf::IterationCallback at_targets = [&](const akvf::IterationSummary& row, const Eigen::VectorXd& x) {
      for (std::size_t c = 0; c < constraints.vertices.size(); ++c)
        checked += x.segment<3>(3 * constraints.vertices[c]) == constraints.targets.row(c).transpose();
      CHECK(row.flips == 0);
      return akvf::CallbackAction::kContinue;
    };
    const auto run = akvf::run_deformation(mesh, "grid", constraints, config, {at_targets});
    CHECK(akvf::is_normal_termination(run.result.status));
    CHECK(checked == static_cast<int>(constraints.vertices.size() * run.result.trace.size()));
    CHECK(run.result.trace.back().energy < run.result.trace.front().energy);
  }
}

TEST_CASE("hard constraints that would invert a tet at the start are refused with a message") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(3);
  akvf::DeformConfig config;
  config.hard_constraints = true;
  const std::string message =
      akvf::test::error_message([&] { akvf::run_deformation(mesh, "grid.mesh", twisted_top(mesh, 2.5), config); });
  CHECK(message.find("grid.mesh: placing the") == 0);
  CHECK(message.find("use soft constraints") != std::string::npos);
}

TEST_CASE("3D deformation is bitwise deterministic for 1 and 2 threads") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(3);
  const akvf::PositionConstraints constraints = twisted_top(mesh, 0.5);
  for (const char* method : {"akvf", "slim"}) {
    CAPTURE(method);
    akvf::DeformConfig config;
    config.preconditioner = method;
    config.optimizer.max_iterations = 15;
    std::vector<akvf::OptimizerResult> results;
    for (int threads : {1, 2, 2}) {
      const akvf::ThreadLimit limit(threads);
      results.push_back(akvf::run_deformation(mesh, "grid", constraints, config).result);
    }
    for (std::size_t r = 1; r < results.size(); ++r) {
      REQUIRE(results[r].trace.size() == results[0].trace.size());
      for (std::size_t i = 0; i < results[0].trace.size(); ++i) {
        CHECK(results[r].trace[i].energy == results[0].trace[i].energy);
        CHECK(results[r].trace[i].grad_norm == results[0].trace[i].grad_norm);
      }
      CHECK(results[r].x == results[0].x);
    }
  }
}
