// The planar Killing operator K(x) of Eq. (5) and the AKVF preconditioner.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <memory>
#include <random>
#include <type_traits>

#include "energies/amips.h"
#include "energies/arap.h"
#include "energies/exp_symmetric_dirichlet.h"
#include "energies/invariant_density_2d.h"
#include "energies/mips.h"
#include "energies/symmetric_dirichlet.h"
#include "framework/optimization/distortion_objective.h"
#include "framework/optimization/element_derivatives.h"
#include "framework/optimization/flip_free_step.h"
#include "preconditioners/akvf_preconditioner_2d.h"
#include "preconditioners/energy_scale.h"
#include "preconditioners/killing_operator_2d.h"
#include "preconditioners/laplacian_preconditioner.h"
#include "preconditioners/newton_preconditioner.h"
#include "preconditioners/slim_preconditioner.h"
#include "tests/density_checks.h"
#include "tests/test_support.h"

namespace {

// The relative Tikhonov shift every factored P carries (factored_preconditioner.h).
const double kShift = akvf::FactorOptions{}.tikhonov;

Eigen::MatrixXd dense_killing(const Eigen::MatrixXi& F, const Eigen::VectorXd& x, const Eigen::VectorXd& rest_area,
                              bool area_scaling) {
  akvf::ElementMatrix2D K(F, static_cast<int>(x.size() / 2));
  akvf::assemble_killing_operator_2d(F, x, rest_area, area_scaling, &K);
  return Eigen::MatrixXd(K.full());
}

// Eq. (6)-(7): per element A_f [grad phi_j grad phi_i^T + (grad phi_i . grad phi_j) I],
// assembled independently of killing_operator_2d.cpp.
Eigen::MatrixXd fem_killing(const Eigen::MatrixXi& F, const Eigen::VectorXd& x) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(x.size(), x.size());
  for (int f = 0; f < F.rows(); ++f) {
    Eigen::Matrix2d Ds;
    Ds.col(0) = x.segment<2>(2 * F(f, 1)) - x.segment<2>(2 * F(f, 0));
    Ds.col(1) = x.segment<2>(2 * F(f, 2)) - x.segment<2>(2 * F(f, 0));
    const double area = 0.5 * Ds.determinant();
    // Hat-function gradients: rows of Ds^-1 for corners 1, 2; corner 0 is minus their sum.
    const Eigen::Matrix2d inv = Ds.inverse();
    Eigen::Vector2d grad[3] = {-(inv.row(0) + inv.row(1)).transpose(), inv.row(0).transpose(), inv.row(1).transpose()};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        K.block<2, 2>(2 * F(f, i), 2 * F(f, j)) +=
            area * (grad[j] * grad[i].transpose() + grad[i].dot(grad[j]) * Eigen::Matrix2d::Identity());
  }
  return K;
}

// Eq. (4): 1/2 sum_f w_f |J_d + J_d^T|^2 with w_f = A_f (or A_hat_f when area-scaled).
double killing_energy(const Eigen::MatrixXi& F, const Eigen::VectorXd& x, const Eigen::VectorXd& d,
                      const Eigen::VectorXd& weight) {
  double energy = 0;
  for (int f = 0; f < F.rows(); ++f) {
    Eigen::Matrix2d Ds, Dd;
    Ds << x.segment<2>(2 * F(f, 1)) - x.segment<2>(2 * F(f, 0)), x.segment<2>(2 * F(f, 2)) - x.segment<2>(2 * F(f, 0));
    Dd << d.segment<2>(2 * F(f, 1)) - d.segment<2>(2 * F(f, 0)), d.segment<2>(2 * F(f, 2)) - d.segment<2>(2 * F(f, 0));
    const Eigen::Matrix2d Jd = Dd * Ds.inverse();
    energy += 0.5 * weight[f] * (Jd + Jd.transpose()).squaredNorm();
  }
  return energy;
}

// Symmetric Dirichlet on the mesh scaled to area 1 (the mesh is returned too,
// for building UV maps of matching size).
akvf::DistortionObjective2D unit_area_objective(akvf::TriMesh* mesh) {
  akvf::normalize_to_unit_area(mesh);
  return akvf::DistortionObjective2D(mesh->F, akvf::rest_triangles(*mesh),
                                     std::make_shared<akvf::SymmetricDirichlet2D>(), mesh->num_vertices());
}

struct PlanarMesh {
  Eigen::MatrixXi F;
  Eigen::VectorXd x;
  Eigen::VectorXd uv_area;
};

PlanarMesh jittered_grid(int n, unsigned seed) {
  const akvf::TriMesh mesh = akvf::test::grid_disk(n, n);
  PlanarMesh p{mesh.F, akvf::stack_uv(akvf::test::jittered_uv(mesh, 0.25, seed)), {}};
  p.uv_area.resize(p.F.rows());
  for (int f = 0; f < p.F.rows(); ++f) {
    Eigen::Matrix2d Ds;
    Ds << p.x.segment<2>(2 * p.F(f, 1)) - p.x.segment<2>(2 * p.F(f, 0)),
        p.x.segment<2>(2 * p.F(f, 2)) - p.x.segment<2>(2 * p.F(f, 0));
    p.uv_area[f] = 0.5 * Ds.determinant();
  }
  return p;
}

}  // namespace

TEST_CASE("Eq. (5) equals the FEM form Eq. (6) on random triangles") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXi F(1, 3);
  F << 0, 1, 2;
  for (int trial = 0; trial < 100; ++trial) {
    Eigen::VectorXd x(6);
    for (int i = 0; i < 6; ++i) x[i] = u(rng);
    Eigen::Matrix2d Ds;
    Ds << x.segment<2>(2) - x.segment<2>(0), x.segment<2>(4) - x.segment<2>(0);
    if (Ds.determinant() < 0) x.segment<2>(2).swap(x.segment<2>(4));  // counter-clockwise
    if (std::abs(Ds.determinant()) < 1e-3) continue;
    const Eigen::MatrixXd eq5 = dense_killing(F, x, Eigen::VectorXd::Ones(1), false);
    const Eigen::MatrixXd eq6 = fem_killing(F, x);
    CHECK((eq5 - eq6).norm() <= 1e-10 * eq6.norm());
  }
}

TEST_CASE("the quadratic form of K is the Killing energy Eq. (4), with and without area scaling") {
  const PlanarMesh p = jittered_grid(6, 5);
  std::mt19937 rng(9);
  std::normal_distribution<double> n;
  const Eigen::VectorXd rest_area =
      Eigen::VectorXd::NullaryExpr(p.F.rows(), [&](Eigen::Index) { return 0.01 + 0.001 * std::abs(n(rng)); });
  const Eigen::MatrixXd K = dense_killing(p.F, p.x, rest_area, false);
  const Eigen::MatrixXd K_scaled = dense_killing(p.F, p.x, rest_area, true);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::VectorXd d = Eigen::VectorXd::NullaryExpr(p.x.size(), [&](Eigen::Index) { return n(rng); });
    CHECK(d.dot(K * d) == doctest::Approx(killing_energy(p.F, p.x, d, p.uv_area)).epsilon(1e-10));
    // §4.2.1: scaling by A_hat_f / A_f integrates over the 3D triangles instead.
    CHECK(d.dot(K_scaled * d) == doctest::Approx(killing_energy(p.F, p.x, d, rest_area)).epsilon(1e-10));
  }
}

TEST_CASE("K is symmetric PSD with exactly the rigid motions as null space (rank 2|V| - 3)") {
  const PlanarMesh p = jittered_grid(7, 2);
  const Eigen::MatrixXd K = dense_killing(p.F, p.x, p.uv_area * 1.7, true);
  CHECK((K - K.transpose()).norm() <= 1e-12 * K.norm());
  bool psd = false;
  double gap = 0;
  CHECK(akvf::test::null_space_dimension(K, &psd, &gap) == 3);
  CHECK(psd);
  CHECK(gap > 1e3);  // a clear gap above the null space: rank exactly 2|V| - 3
  const Eigen::MatrixXd rigid = akvf::rigid_motion_basis_2d(p.x);
  CHECK((K * rigid).norm() <= 1e-10 * K.norm());
  CHECK((rigid.transpose() * rigid - Eigen::Matrix3d::Identity()).norm() <= 1e-12);
}

TEST_CASE("the AKVF direction is K^+ grad E, a descent direction free of rigid motion") {
  akvf::TriMesh normalized = akvf::test::bumpy_disk(6, 6);
  const akvf::DistortionObjective2D objective = unit_area_objective(&normalized);
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(normalized, 0.2, 4) * 0.9);
  Eigen::VectorXd g, d;
  objective.value_and_gradient(x, &g);
  akvf::AkvfPreconditioner2D preconditioner(objective);
  preconditioner.update({x, g, 0.0, 1});
  preconditioner.apply(g, &d);
  const Eigen::MatrixXd K = dense_killing(objective.elements(), x, objective.rest().area, true);
  const Eigen::MatrixXd pseudo_inverse = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(K).pseudoInverse();
  const Eigen::VectorXd reference = pseudo_inverse * g;
  CHECK((d - reference).norm() <= 1e-5 * reference.norm());
  CHECK(g.dot(d) > 0);  // -d is a descent direction
  CHECK((akvf::rigid_motion_basis_2d(x).transpose() * d).norm() <= 1e-12 * d.norm());
}

TEST_CASE("on a long thin strip the AKVF direction is K^+ grad E in the softest bending modes too") {
  // A 300 x 1 strip of square cells: its in-plane bending modes have
  // eigenvalues of K far below mean(diag K), where a Tikhonov shift of 1e-8
  // of the mean diagonal would damp them by tens of percent
  // (factored_preconditioner.h).
  akvf::TriMesh strip = akvf::test::grid_disk(301, 2);
  strip.V.col(1) /= 300;
  const akvf::DistortionObjective2D objective = unit_area_objective(&strip);
  const Eigen::VectorXd x = akvf::stack_uv(strip.V.leftCols<2>());
  const Eigen::MatrixXd K = dense_killing(objective.elements(), x, objective.rest().area, true);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K);
  const double softest = eig.eigenvalues()[3];  // above the three rigid motions
  CHECK(softest < 1e-8 * K.diagonal().mean());
  // A gradient with equal weight in every non-rigid eigen-direction.
  const Eigen::Index n = K.rows();
  const Eigen::VectorXd g = eig.eigenvectors().rightCols(n - 3) * Eigen::VectorXd::Ones(n - 3);
  const Eigen::VectorXd reference = eig.eigenvectors().rightCols(n - 3) * eig.eigenvalues().tail(n - 3).cwiseInverse();
  akvf::AkvfPreconditioner2D preconditioner(objective);
  Eigen::VectorXd d;
  preconditioner.update({x, g, 0.0, 1});
  preconditioner.apply(g, &d);
  // The shifted solve's error is eps / lambda in each mode: 1.3e-4 here
  // (0.56 with a shift of 1e-8).
  CHECK((d - reference).norm() <= 1e-3 * reference.norm());
}

namespace {

// The uniform graph Laplacian per coordinate minus s I / 3 per triangle: its
// lowest eigenvalue lies between -s times the mean and the largest number of
// triangles at a vertex (the translations' Rayleigh quotient is minus the
// mean of the subtracted diagonal).
class ShiftedGraphLaplacian final : public akvf::FactoredPreconditioner2D {
 public:
  ShiftedGraphLaplacian(const akvf::MeshObjective2D& objective, akvf::FactorOptions options, double s)
      : akvf::FactoredPreconditioner2D(objective, std::move(options)), s_(s) {}
  std::string name() const override { return "shifted-graph-laplacian"; }

 private:
  void assemble(const akvf::OptimizationState&, Matrix* matrix) override {
    matrix->assemble([this](int, Matrix::Local* local) {
      *local = -s_ / 3 * Matrix::Local::Identity();
      for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
          for (int c = 0; c < 2; ++c) {
            (*local)(2 * i + c, 2 * i + c) += 0.5;
            (*local)(2 * j + c, 2 * j + c) += 0.5;
            (*local)(2 * i + c, 2 * j + c) -= 0.5;
          }
    });
  }
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override {
    return akvf::motion_basis(2, akvf::MotionProjection::kTranslations, x);
  }
  double s_;
};

// A graph Laplacian whose element weights, 10^-2 to 10^2, change from one
// iteration to the next: the factor of one iteration's matrix is a poor
// preconditioner for the next one's (their ratio spans 10^8).
class ReweightedLaplacian final : public akvf::FactoredPreconditioner2D {
 public:
  ReweightedLaplacian(const akvf::MeshObjective2D& objective, akvf::FactorOptions options)
      : akvf::FactoredPreconditioner2D(objective, std::move(options)) {}
  std::string name() const override { return "reweighted-laplacian"; }

 private:
  void assemble(const akvf::OptimizationState& state, Matrix* matrix) override {
    matrix->assemble([&state](int e, Matrix::Local* local) {
      const double w = std::pow(10.0, 2 * std::sin(1.7 * e + 2.3 * state.iteration));
      local->setZero();
      for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
          for (int c = 0; c < 2; ++c) {
            (*local)(2 * i + c, 2 * i + c) += w;
            (*local)(2 * j + c, 2 * j + c) += w;
            (*local)(2 * i + c, 2 * j + c) -= w;
            (*local)(2 * j + c, 2 * i + c) -= w;
          }
    });
  }
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override {
    return akvf::motion_basis(2, akvf::MotionProjection::kTranslations, x);
  }
};

}  // namespace

TEST_CASE("a matrix rounding or a slight indefiniteness keeps from factoring is retried with a 100x larger shift") {
  akvf::TriMesh grid = akvf::test::grid_disk(8, 8);
  const akvf::DistortionObjective2D objective = unit_area_objective(&grid);
  const Eigen::VectorXd x = akvf::stack_uv(grid.V.leftCols<2>());
  // Triangles per vertex: 1 to 6, so the mean diagonal is at most 3 (6
  // triangles, each adding 1 per corner and coordinate) and the lowest
  // eigenvalue is at most -s: s = 3e-9 puts it below -1e-9 times the mean
  // diagonal and above -1e-8 times it (the subtracted diagonal is at most
  // 2 s and the diagonal at least 1 for 8 x 8).
  const double s = 3e-9;
  Eigen::VectorXd g = Eigen::VectorXd::LinSpaced(x.size(), -1, 1).array().sin();
  const Eigen::MatrixXd T = akvf::translation_basis_2d(objective.num_vertices());
  g -= T * (T.transpose() * g);
  ShiftedGraphLaplacian retried(objective, {}, s);
  Eigen::VectorXd d;
  retried.update({x, g, 0.0, 1});
  retried.apply(g, &d);
  CHECK(retried.report().find("2 retried with a 100x larger shift") != std::string::npos);
  CHECK(g.dot(d) > 0);
  akvf::FactorOptions capped;
  capped.max_tikhonov = 1e-9;
  ShiftedGraphLaplacian refused(objective, capped, s);
  CHECK_THROWS_AS(refused.update({x, g, 0.0, 1}), akvf::NotPositiveDefinite);
}

namespace {

// The preconditioner updated and applied at x1, then at x2: g and d at x2.
void direction_after(const akvf::DistortionObjective2D& objective, const Eigen::VectorXd& x1, const Eigen::VectorXd& x2,
                     akvf::Preconditioner* preconditioner, Eigen::VectorXd* g, Eigen::VectorXd* d) {
  objective.value_and_gradient(x1, g);
  preconditioner->update({x1, *g, 0.0, 1});
  preconditioner->apply(*g, d);
  objective.value_and_gradient(x2, g);
  preconditioner->update({x2, *g, 0.0, 2});
  preconditioner->apply(*g, d);
}

}  // namespace

TEST_CASE("a face whose thinnest height the map stretched beyond sliver_stretch carries the energy's curvature") {
  // The unit square fanned around vertex 4, which the rest shape puts 1e-4
  // above the bottom edge (face 0 a sliver) and the map at the centre: face
  // 0's height grows 5000-fold, the others' at most 2-fold.
  akvf::TriMesh mesh;
  mesh.V.resize(5, 3);
  mesh.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 1e-4, 0;
  mesh.F.resize(4, 3);
  mesh.F << 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4;
  const akvf::DistortionObjective2D objective = unit_area_objective(&mesh);
  Eigen::MatrixXd uv = mesh.V.leftCols<2>();
  uv.row(4) = 0.5 * (uv.row(0) + uv.row(2));
  const Eigen::VectorXd x = akvf::stack_uv(uv);
  Eigen::VectorXd g;
  const double energy = objective.value_and_gradient(x, &g);
  struct Assembled {
    Eigen::MatrixXd P;
    Eigen::VectorXd d;
    std::string report;
  };
  const auto assemble = [&](std::optional<double> sliver_stretch) {
    akvf::AkvfOptions2D options;
    options.sliver_stretch = sliver_stretch;
    akvf::AkvfPreconditioner2D preconditioner(objective, options);
    preconditioner.update({x, g, energy, 1});
    Assembled a{Eigen::MatrixXd(preconditioner.matrix().full()), {}, preconditioner.report()};
    preconditioner.apply(g, &a.d);
    return a;
  };
  const Assembled K = assemble(std::nullopt), P = assemble(100), P_far = assemble(1e4);
  // Below the limit K is untouched, to the bit.
  CHECK(P_far.P == K.P);
  CHECK(P_far.d == K.d);
  CHECK(P_far.report.find("sliver") == std::string::npos);
  // Above it face 0 adds projected Newton's block w G^T [H]_+ G.
  const auto G = akvf::jacobian_map<2>(objective.rest().Dm_inv[0]);
  const Eigen::Matrix<double, 6, 6> block =
      objective.weights()[0] * G.transpose() * objective.density().projected_hessian(objective.jacobian(x, 0)) * G;
  Eigen::MatrixXd expected = K.P;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      expected.block<2, 2>(2 * mesh.F(0, a), 2 * mesh.F(0, b)) += block.block<2, 2>(2 * a, 2 * b);
  CHECK((P.P - expected).norm() <= 1e-10 * expected.norm());
  CHECK(P.report.find("the energy's own curvature at 1 stretched sliver") != std::string::npos);
  // K alone closes the sliver within a tiny step along its direction; with
  // the sliver's curvature the step may be long.
  const auto sliver_flip_step = [&](const Eigen::VectorXd& d) {
    const auto edges = [&](const Eigen::VectorXd& v) {
      Eigen::Matrix2d E;
      E << v.segment<2>(2 * mesh.F(0, 1)) - v.segment<2>(2 * mesh.F(0, 0)),
          v.segment<2>(2 * mesh.F(0, 2)) - v.segment<2>(2 * mesh.F(0, 0));
      return E;
    };
    const Eigen::Matrix2d Ds = edges(x), Dd = edges(-d);
    return akvf::triangle_flip_step(Ds.data(), Dd.data());
  };
  MESSAGE("sliver flip step: K ", sliver_flip_step(K.d), ", with its curvature ", sliver_flip_step(P.d));
  CHECK(sliver_flip_step(P.d) > 100 * sliver_flip_step(K.d));
}

TEST_CASE("with factorization reuse the direction solves K(x) d = g to the tolerance") {
  akvf::TriMesh normalized = akvf::test::bumpy_disk(8, 8);
  const akvf::DistortionObjective2D objective = unit_area_objective(&normalized);
  const Eigen::VectorXd x1 = akvf::stack_uv(akvf::test::jittered_uv(normalized, 0.2, 4) * 0.9);
  const Eigen::VectorXd x2 = x1 + 1e-3 * akvf::stack_uv(akvf::test::jittered_uv(normalized, 0.2, 5));
  akvf::AkvfOptions2D options;
  options.factor.reuse_tolerance = 0.01;
  akvf::AkvfPreconditioner2D preconditioner(objective, options);
  Eigen::VectorXd g, d;
  direction_after(objective, x1, x2, &preconditioner, &g, &d);
  CHECK(preconditioner.statistics().factorizations == 1);
  CHECK(preconditioner.statistics().reused_solves == 1);
  const Eigen::MatrixXd K = dense_killing(objective.elements(), x2, objective.rest().area, true);
  CHECK((K * d - g).norm() <= 0.011 * g.norm());
  CHECK(g.dot(d) > 0);
  CHECK((akvf::rigid_motion_basis_2d(x2).transpose() * d).norm() <= 1e-10 * d.norm());
}

TEST_CASE("a reuse takes at most the CG iterations its factor's flops per entry pay for") {
  akvf::TriMesh normalized = akvf::test::bumpy_disk(8, 8);
  const akvf::DistortionObjective2D objective = unit_area_objective(&normalized);
  const Eigen::VectorXd x1 = akvf::stack_uv(akvf::test::jittered_uv(normalized, 0.2, 4) * 0.9);
  const Eigen::VectorXd x2 = x1 + 1e-3 * akvf::stack_uv(akvf::test::jittered_uv(normalized, 0.2, 5));
  const auto run = [&](double cg_flops_per_entry, double tolerance, int max_cg) {
    akvf::AkvfOptions2D options;
    options.factor.reuse_tolerance = tolerance;
    options.factor.reuse_max_cg = max_cg;
    options.factor.reuse_cg_flops_per_entry = cg_flops_per_entry;
    auto preconditioner = std::make_unique<akvf::AkvfPreconditioner2D>(objective, options);
    Eigen::VectorXd g, d;
    direction_after(objective, x1, x2, preconditioner.get(), &g, &d);
    const Eigen::MatrixXd K = dense_killing(objective.elements(), x2, objective.rest().area, true);
    CHECK((K * d - g).norm() <= std::max(1.1 * tolerance, 1e-8) * g.norm());
    return preconditioner;
  };
  // Without a cost: reuse_max_cg; one iteration costing a flop per entry:
  // the factor's flops per entry (this small disk's are far below 1e6).
  CHECK(run(0, 0.01, 8)->reuse_budget() == 8);
  // Without a cost even a one-iteration budget is tried.
  CHECK(run(0, 0.01, 1)->statistics().cg_iterations == 1);
  const int flops_per_entry = run(1, 0.01, 1 << 30)->reuse_budget();
  REQUIRE(flops_per_entry >= 8);
  REQUIRE(flops_per_entry < 1e6);
  SUBCASE("a budget below two CG iterations: no reuse is tried") {
    const auto skipped = run(1e6, 0.01, 8);
    CHECK(skipped->reuse_budget() == 0);
    CHECK(skipped->statistics().factorizations == 2);
    CHECK(skipped->statistics().cg_iterations == 0);
  }
  SUBCASE("a reuse that needs more than the budget stops there and factors") {
    // A budget of two; a tolerance two CG iterations do not reach.
    const auto capped = run(flops_per_entry / 2.5, 1e-12, 8);
    CHECK(capped->reuse_budget() == 2);
    CHECK(capped->statistics().factorizations == 2);
    CHECK(capped->statistics().reused_solves == 0);
    CHECK(capped->statistics().cg_iterations >= 1);
    CHECK(capped->statistics().cg_iterations <= 2);
    // The same tolerance with reuse_max_cg's eight: more iterations tried.
    CHECK(run(0, 1e-12, 8)->statistics().cg_iterations > 2);
  }
  SUBCASE("within the budget the reuse serves") {
    const auto reused = run(flops_per_entry / 8.5, 0.01, 8);
    CHECK(reused->reuse_budget() == 8);
    CHECK(reused->statistics().reused_solves == 1);
  }
  akvf::FactorOptions invalid;
  invalid.reuse_cg_flops_per_entry = -1;
  CHECK_THROWS_AS(ReweightedLaplacian(objective, invalid), akvf::OptionsError);
}

TEST_CASE("a reuse whose first CG iteration barely contracts is given up there when checked from the first") {
  akvf::TriMesh grid = akvf::test::grid_disk(12, 12);
  const akvf::DistortionObjective2D objective = unit_area_objective(&grid);
  const Eigen::VectorXd x = akvf::stack_uv(grid.V.leftCols<2>());
  Eigen::VectorXd g = Eigen::VectorXd::LinSpaced(x.size(), -1, 1).array().sin();
  const Eigen::MatrixXd T = akvf::translation_basis_2d(objective.num_vertices());
  g -= T * (T.transpose() * g);
  Eigen::VectorXd directions[2];
  int cg_iterations[2] = {0, 0};
  for (const int check_from : {1, 2}) {
    CAPTURE(check_from);
    akvf::FactorOptions options;
    options.reuse_tolerance = 0.03;
    options.reuse_check_from = check_from;
    ReweightedLaplacian preconditioner(objective, options);
    Eigen::VectorXd d;
    preconditioner.update({x, g, 0.0, 1});
    preconditioner.apply(g, &d);
    preconditioner.update({x, g, 0.0, 2});
    preconditioner.apply(g, &directions[check_from - 1]);
    CHECK(preconditioner.statistics().factorizations == 2);  // the reuse failed: factored anew
    CHECK(preconditioner.statistics().reused_solves == 0);
    cg_iterations[check_from - 1] = preconditioner.statistics().cg_iterations;
  }
  CHECK(cg_iterations[0] == 1);
  CHECK(cg_iterations[1] >= 2);
  CHECK(directions[0] == directions[1]);  // both from the new factor
  akvf::FactorOptions invalid;
  invalid.reuse_check_from = 0;
  CHECK_THROWS_AS(ReweightedLaplacian(objective, invalid), akvf::OptionsError);
}

TEST_CASE("Newton, Laplacian and SLIM matrices are symmetric PSD with the expected null spaces, directions descend") {
  akvf::TriMesh normalized = akvf::test::bumpy_disk(7, 7);
  const akvf::DistortionObjective2D objective = unit_area_objective(&normalized);
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(normalized, 0.2, 8) * 0.8);
  Eigen::VectorXd g, d;
  objective.value_and_gradient(x, &g);
  akvf::NewtonPreconditioner2D newton(objective);
  akvf::LaplacianPreconditioner2D laplacian(objective);
  akvf::SlimPreconditioner2D slim(objective);
  for (akvf::FactoredPreconditioner2D* p :
       std::initializer_list<akvf::FactoredPreconditioner2D*>{&newton, &laplacian, &slim}) {
    CAPTURE(p->name());
    p->update({x, g, 0.0, 1});
    p->apply(g, &d);
    CHECK(g.dot(d) > 0);
    CHECK(d.allFinite());
    // The factored matrix is P + eps I with eps = tikhonov * mean(diag P): remove the shift to test P.
    Eigen::MatrixXd P(p->matrix().full());
    P.diagonal().array() -= kShift * P.diagonal().mean() / (1 + kShift);
    CHECK((P - P.transpose()).norm() <= 1e-12 * P.norm());
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(P);
    CHECK(eig.eigenvalues().minCoeff() >= -1e-9 * eig.eigenvalues().maxCoeff());
    const Eigen::MatrixXd T = akvf::translation_basis_2d(objective.num_vertices());
    CHECK((P * T).norm() <= 1e-8 * P.norm());
  }
}

TEST_CASE_TEMPLATE(
    "Newton assembled from the density's eigensystem is the filtered element Hessians' sum, for every "
    "filter",
    Density, akvf::SymmetricDirichlet2D, akvf::Arap2D) {
  akvf::TriMesh normalized = akvf::test::bumpy_disk(7, 7);
  akvf::normalize_to_unit_area(&normalized);
  const akvf::DistortionObjective2D with_modes(normalized.F, akvf::rest_triangles(normalized),
                                               std::make_shared<Density>(), normalized.num_vertices());
  const akvf::DistortionObjective2D hessians_only(normalized.F, akvf::rest_triangles(normalized),
                                                  std::make_shared<akvf::test::HessiansOnly<2, Density>>(),
                                                  normalized.num_vertices());
  // Shrunk and jittered: many elements have a negative eigenvalue.
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(normalized, 0.2, 8) * 0.6);
  Eigen::VectorXd g;
  const double energy = with_modes.value_and_gradient(x, &g);
  for (const akvf::EigenvalueFilter filter :
       {akvf::EigenvalueFilter::kClamp, akvf::EigenvalueFilter::kAbsolute, akvf::EigenvalueFilter::kExact}) {
    CAPTURE(static_cast<int>(filter));
    akvf::NewtonPreconditioner2D from_modes(with_modes, {}, akvf::default_newton_projection(2), filter);
    akvf::NewtonPreconditioner2D from_hessians(hessians_only, {}, akvf::default_newton_projection(2), filter);
    // The exact filter is tried after a unit step accepted at once.
    for (akvf::NewtonPreconditioner2D* p : {&from_modes, &from_hessians}) p->update({x, g, energy, 1, 1.0, 1.25});
    CHECK(from_modes.last_filter() == from_hessians.last_filter());
    const Eigen::SparseMatrix<double>& expected = from_hessians.matrix().upper();
    CHECK((from_modes.matrix().upper() - expected).norm() <= 1e-12 * expected.norm());
  }
}

TEST_CASE("Newton's model of ARAP adds the log-area damping g_hat (d det J / det J)^2 of each element") {
  akvf::TriMesh normalized = akvf::test::bumpy_disk(7, 7);
  akvf::normalize_to_unit_area(&normalized);
  const akvf::DistortionObjective2D damped(normalized.F, akvf::rest_triangles(normalized),
                                           std::make_shared<akvf::test::HessiansOnly<2, akvf::Arap2D>>(),
                                           normalized.num_vertices());
  const akvf::DistortionObjective2D undamped(normalized.F, akvf::rest_triangles(normalized),
                                             std::make_shared<akvf::test::HessiansOnlyWithoutOnset<2, akvf::Arap2D>>(),
                                             normalized.num_vertices());
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(normalized, 0.2, 8) * 0.6);
  Eigen::VectorXd v;
  const double difference = akvf::test::newton_matrix_difference<2>(damped, undamped, x, 3, &v);
  double expected = 0;  // J is linear in the positions: jacobian(v, e) is J's change along v
  for (int e = 0; e < damped.weights().size(); ++e) {
    const Eigen::Matrix2d J = damped.jacobian(x, e), dJ = damped.jacobian(v, e);
    const double along = akvf::cofactor_2d(J).dot(Eigen::Map<const Eigen::Vector4d>(dJ.data()));
    expected +=
        damped.weights()[e] * akvf::Arap2D::collapse_area_ratio() * along * along / (J.determinant() * J.determinant());
  }
  CHECK(expected > 0);
  CHECK(difference == doctest::Approx(expected).epsilon(1e-9));
}

TEST_CASE("Newton's exact model of ARAP clamps the elements within the collapse barrier's range") {
  akvf::TriMesh grid = akvf::test::grid_disk(7, 6, 0.2, 3);
  akvf::normalize_to_unit_area(&grid);
  const akvf::DistortionObjective2D objective(grid.F, akvf::rest_triangles(grid), std::make_shared<akvf::Arap2D>(),
                                              grid.num_vertices());
  // Compressed planar (det J 0.98, a negative twist eigenvalue in every
  // triangle; the exact Hessian factors), and flattened as well to a
  // ten-thousandth of its height (det J below 1e-3 everywhere).
  const Eigen::MatrixXd compressed = grid.V.leftCols<2>() * 0.99;
  const Eigen::MatrixXd flattened = compressed * Eigen::Vector2d(1, 1e-4).asDiagonal();
  for (const Eigen::MatrixXd* map : {&compressed, &flattened}) {
    const bool in_range = map == &flattened;
    CAPTURE(in_range);
    const Eigen::VectorXd x = akvf::stack_uv(*map);
    for (int e = 0; e < objective.weights().size(); ++e) {
      const double det = objective.jacobian(x, e).determinant();
      CHECK(det > 0);
      CHECK((det < akvf::Arap2D::collapse_area_ratio()) == in_range);
    }
    Eigen::VectorXd g;
    const double energy = objective.value_and_gradient(x, &g);
    akvf::NewtonPreconditioner2D exact(objective, {}, akvf::default_newton_projection(2),
                                       akvf::EigenvalueFilter::kExact);
    akvf::NewtonPreconditioner2D clamped(objective, {}, akvf::default_newton_projection(2),
                                         akvf::EigenvalueFilter::kClamp);
    // The exact Hessian is tried after a unit step accepted at once.
    for (akvf::NewtonPreconditioner2D* p : {&exact, &clamped}) p->update({x, g, energy, 1, 1.0, 1.25});
    REQUIRE(exact.last_filter() == akvf::EigenvalueFilter::kExact);
    // Off the diagonal (where the rotation shift and the Tikhonov shift
    // land) the two differ by the negative eigenvalues the clamp drops.
    Eigen::SparseMatrix<double> difference = exact.matrix().upper() - clamped.matrix().upper();
    difference.prune([](Eigen::Index row, Eigen::Index column, double) { return row != column; });
    if (in_range)
      CHECK(difference.norm() == 0);
    else
      CHECK(difference.norm() > 1e-3 * clamped.matrix().upper().norm());
  }
}

TEST_CASE("an exact try keeps a settled collapse range exact, and clamps it again where that does not factor") {
  akvf::TriMesh grid = akvf::test::grid_disk(7, 6, 0.2, 3);
  akvf::normalize_to_unit_area(&grid);
  const akvf::DistortionObjective2D objective(grid.F, akvf::rest_triangles(grid), std::make_shared<akvf::Arap2D>(),
                                              grid.num_vertices());
  // Flattened to a ten-thousandth of its height: every triangle within the
  // range, where the exact Hessian does not factor (the test above).
  const Eigen::MatrixXd flattened = grid.V.leftCols<2>() * Eigen::Vector2d(0.99, 0.99e-4).asDiagonal();
  const Eigen::VectorXd x = akvf::stack_uv(flattened);
  Eigen::VectorXd g;
  const double energy = objective.value_and_gradient(x, &g);
  akvf::NewtonPreconditioner2D exact(objective, {}, akvf::default_newton_projection(2), akvf::EigenvalueFilter::kExact);
  akvf::NewtonPreconditioner2D clamped(objective, {}, akvf::default_newton_projection(2),
                                       akvf::EigenvalueFilter::kClamp);
  clamped.update({x, g, energy, 1, 1.0, 1.25});
  const auto off_diagonal_difference = [&] {
    Eigen::SparseMatrix<double> difference = exact.matrix().upper() - clamped.matrix().upper();
    difference.prune([](Eigen::Index row, Eigen::Index column, double) { return row != column; });
    return difference.norm();
  };
  // Each update after a unit step accepted at once, at the same x: the
  // range has not moved since the last assembly from the second on. The
  // first keeps the range clamped (nothing to compare with); the second
  // keeps it exact, fails to factor, and is made again with it clamped; the
  // third waits; the fourth tries again.
  const int expected_tries[] = {0, 1, 1, 2};
  for (int k = 1; k <= 4; ++k) {
    CAPTURE(k);
    exact.update({x, g, energy, k, 1.0, 1.25});
    REQUIRE(exact.last_filter() == akvf::EigenvalueFilter::kExact);
    CHECK(exact.range_exact_tries() == expected_tries[k - 1]);
    CHECK(exact.range_exact_fallbacks() == exact.range_exact_tries());
    CHECK(off_diagonal_difference() == 0);
  }
}

TEST_CASE("Newton on AKVF's shared assembly pattern assembles and solves bitwise as Newton on its own") {
  akvf::TriMesh normalized = akvf::test::bumpy_disk(7, 7);
  const akvf::DistortionObjective2D objective = unit_area_objective(&normalized);
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(normalized, 0.2, 8) * 0.8);
  Eigen::VectorXd g;
  objective.value_and_gradient(x, &g);
  akvf::AkvfPreconditioner2D akvf(objective);
  akvf.update({x, g, 0.0, 1});  // AKVF's K holds values; the shared matrix must not take them
  akvf::NewtonPreconditioner2D alone(objective);
  akvf::NewtonPreconditioner2D shared(objective, akvf.matrix(), {}, akvf::default_newton_projection(2),
                                      akvf::EigenvalueFilter::kClamp);
  Eigen::VectorXd d_alone, d_shared;
  for (akvf::NewtonPreconditioner2D* p : {&alone, &shared}) p->update({x, g, 0.0, 1});
  alone.apply(g, &d_alone);
  shared.apply(g, &d_shared);
  const Eigen::SparseMatrix<double> difference = alone.matrix().upper() - shared.matrix().upper();
  CHECK(difference.norm() == 0);
  CHECK(shared.matrix().upper().nonZeros() == alone.matrix().upper().nonZeros());
  CHECK(d_shared == d_alone);
  // AKVF's own matrix is untouched by the Newton assembly on its pattern.
  CHECK((akvf.matrix().upper() - shared.matrix().upper()).norm() > 0);
}

TEST_CASE("the SLIM proxy's gradient equals the energy's gradient at the current iterate") {
  // Per face: d/dJ |W (J - R)|^2 = 2 W^T W (J - R) must be dD/dJ.
  const akvf::SymmetricDirichlet2D sd;
  const akvf::Arap2D arap;
  const akvf::ExpSymmetricDirichlet2D exp_sd(0.3);
  const akvf::Mips2D mips;  // pulled towards the nearest similarity, not rotation
  std::mt19937 rng(31);
  for (const akvf::InvariantDensity2D* density :
       std::initializer_list<const akvf::InvariantDensity2D*>{&sd, &arap, &exp_sd, &mips}) {
    CAPTURE(density->name());
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::Matrix2d J = akvf::test::random_jacobian<2>(rng, 0.3, 3.0);
      Eigen::Matrix2d WtW, R, dD;
      akvf::SlimPreconditioner2D::proxy_weights(*density, J, &WtW, &R);
      density->value_and_gradient(J, &dD);
      CHECK((2 * WtW * (J - R) - dD).norm() <= 1e-9 * std::max(1.0, dD.norm()));
      CHECK(R.determinant() == doctest::Approx(density == &mips ? J.determinant() : 1.0));
    }
  }
}

TEST_CASE("where no positive SLIM weight gives the gradient, the proxy takes the energy's curvature along sigma") {
  // D = (sigma_1 - 2)^2 + (sigma_2 - 2)^2 pulled towards a rotation: at
  // sigma = (3, 1.5) the first weight is (dD/dsigma_1) / (2 (sigma_1 - 1)) =
  // 0.5, the second's ratio is -1 / 1: there half of D's second derivative, 1.
  struct ShiftedArap final : akvf::SingularValueDerivative<2> {
    Vector singular_value_gradient(const Vector& sigma) const override { return 2 * (sigma.array() - 2).matrix(); }
  };
  const Eigen::Matrix2d rotation = Eigen::Rotation2Dd(0.4).toRotationMatrix();
  const Eigen::Matrix2d J = rotation * Eigen::Vector2d(3, 1.5).asDiagonal();
  Eigen::Matrix2d WtW, R;
  akvf::SlimPreconditioner2D::proxy_weights(ShiftedArap{}, J, &WtW, &R);
  const Eigen::Matrix2d expected = rotation * Eigen::Vector2d(0.5, 1).asDiagonal() * rotation.transpose();
  CHECK((WtW - expected).norm() <= 1e-6);
  CHECK((R - rotation).norm() <= 1e-12);
}

TEST_CASE_TEMPLATE(
    "a scale-invariant density's SLIM proxy keeps a millionth of its curvature along J's similarity orbit", Dim,
    std::integral_constant<int, 2>, std::integral_constant<int, 3>) {
  // MIPS is constant on J's orbit s Q J, whose tangents are (s I + Omega) J;
  // the softened proxy Hessian is the original on the complement of those
  // directions, a share kInvariantShare of it along them, and still
  // positive definite.
  constexpr int D = Dim::value;
  using Square = Eigen::Matrix<double, D, D>;
  using Vector = Eigen::Matrix<double, D * D, 1>;
  using Hessian = Eigen::Matrix<double, D * D, D * D>;
  std::mt19937 rng(7);
  for (int trial = 0; trial < 10; ++trial) {
    const Square J = akvf::test::random_jacobian<D>(rng, 0.3, 3.0);
    Square WtW, R;
    akvf::SlimPreconditioner<D>::proxy_weights(std::conditional_t<D == 2, akvf::Mips2D, akvf::Mips3D>{}, J, &WtW, &R);
    Hessian proxy = Hessian::Zero();
    for (int c = 0; c < D; ++c) proxy.template block<D, D>(D * c, D * c) = 2 * WtW;
    Hessian softened = proxy;
    akvf::SlimPreconditioner<D>::soften_invariant_directions(J, &softened);
    Square turn = Square::Zero();
    turn(0, 1) = -1;
    turn(1, 0) = 1;
    const Square turned = turn * J;
    const double share = akvf::SlimPreconditioner<D>::kInvariantShare;
    for (const Square* direction : {&J, &turned}) {
      const Vector v = Eigen::Map<const Vector>(direction->data());
      CHECK(v.dot(softened * v) == doctest::Approx(share * v.dot(proxy * v)).epsilon(1e-9));
    }
    // A direction orthogonal to the orbit: U diag(sigma_2, -sigma_1, 0) V^T,
    // a stretch along the first two singular directions that keeps |J|.
    const Eigen::JacobiSVD<Square> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Square stretch = Square::Zero();
    stretch(0, 0) = svd.singularValues()[1];
    stretch(1, 1) = -svd.singularValues()[0];
    const Square across = svd.matrixU() * stretch * svd.matrixV().transpose();
    const Vector u = Eigen::Map<const Vector>(across.data());
    CHECK(std::abs(u.dot(Eigen::Map<const Vector>(J.data()))) <= 1e-12 * J.squaredNorm());
    CHECK(std::abs(u.dot(Eigen::Map<const Vector>(turned.data()))) <= 1e-12 * J.squaredNorm());
    CHECK(u.dot(softened * u) == doctest::Approx(u.dot(proxy * u)).epsilon(1e-9));
    const Eigen::SelfAdjointEigenSolver<Hessian> eig(softened);
    CHECK(eig.eigenvalues().minCoeff() > 0);
  }
}

TEST_CASE("SLIM refuses an energy without a singular-value derivative") {
  struct Plain final : akvf::DistortionDensity2D {
    std::string name() const override { return "plain"; }
    double lower_bound() const override { return 0; }
    double value(const Matrix& J) const override { return J.squaredNorm(); }
    double value_and_gradient(const Matrix& J, Matrix* g) const override {
      *g = 2 * J;
      return J.squaredNorm();
    }
    Hessian hessian(const Matrix&) const override { return 2 * Hessian::Identity(); }
  };
  akvf::TriMesh mesh = akvf::test::grid_disk(3, 3);
  const akvf::DistortionObjective2D objective(mesh.F, akvf::rest_triangles(mesh), std::make_shared<Plain>(),
                                              mesh.num_vertices());
  CHECK(akvf::test::error_message([&] { akvf::SlimPreconditioner2D slim(objective); }) ==
        "the slim preconditioner needs an energy with a singular-value derivative; 'plain' has none");
}

// The reason AKVF is kept on nearly isometric maps (switching_preconditioner.h,
// energy_scale.h): at an isometry the Hessian of symmetric Dirichlet, ARAP
// and exponential symmetric Dirichlet is c K(x), c = 1 / isometric_newton_step;
// MIPS's is not (it is flat along conformal maps, not only rigid ones).
TEST_CASE(
    "at a similarity map the Hessian is c K_beta(x), beta the energy's: at a rotation for every energy, at any "
    "scale for MIPS") {
  akvf::TriMesh mesh = akvf::test::grid_disk(6, 5, 0.2, 3);  // planar, jittered: every UV rotation is isometric
  akvf::normalize_to_unit_area(&mesh);
  const Eigen::Matrix2d rotation = Eigen::Rotation2Dd(0.7).toRotationMatrix();
  auto unshifted = [](const akvf::FactoredPreconditioner2D& p) {
    Eigen::MatrixXd P(p.matrix().full());
    P.diagonal().array() -= kShift * P.diagonal().mean() / (1 + kShift);
    return P;
  };
  for (const auto& density : std::vector<std::shared_ptr<akvf::DistortionDensity2D>>{
           std::make_shared<akvf::SymmetricDirichlet2D>(), std::make_shared<akvf::Arap2D>(),
           std::make_shared<akvf::ExpSymmetricDirichlet2D>(0.5), std::make_shared<akvf::Amips2D>(1.5),
           std::make_shared<akvf::Mips2D>()}) {
    const bool conformal = density->name() == "mips";
    const double beta = akvf::rest_divergence_weight(*density);
    // Exact: K_beta is K itself unless the energy ignores dilations.
    CHECK(beta == (conformal ? 0.0 : 1.0));
    // MIPS is scale invariant: its Hessian is c K_0 at every similarity.
    for (const double scale : conformal ? std::vector<double>{1.0, 1.7} : std::vector<double>{1.0}) {
      CAPTURE(density->name());
      CAPTURE(scale);
      const Eigen::VectorXd x = akvf::stack_uv(scale * mesh.V.leftCols<2>() * rotation.transpose());
      const akvf::DistortionObjective2D objective(mesh.F, akvf::rest_triangles(mesh), density, mesh.num_vertices());
      Eigen::VectorXd g;
      objective.value_and_gradient(x, &g);
      // The Hessian: projected Newton's matrix (PSD at an isometry), without
      // the log-area damping its model adds for ARAP (newton_preconditioner.h).
      std::shared_ptr<akvf::DistortionDensity2D> undamped = density;
      if (density->collapse_barrier_onset() > 0)  // ARAP's, the one density with an onset
        undamped = std::make_shared<akvf::test::HessiansOnlyWithoutOnset<2, akvf::Arap2D>>();
      const akvf::DistortionObjective2D hessian_objective(mesh.F, akvf::rest_triangles(mesh), undamped,
                                                          mesh.num_vertices());
      akvf::NewtonPreconditioner2D newton(hessian_objective);
      akvf::AkvfOptions2D options;
      options.divergence_weight = beta;
      akvf::AkvfPreconditioner2D akvf_k(objective, options);
      options.energy_scaling = true;  // the default method's AKVF phase
      akvf::AkvfPreconditioner2D scaled_k(objective, options);
      akvf::AkvfOptions2D as_written;
      as_written.divergence_weight = 1;
      akvf::AkvfPreconditioner2D killing(objective, as_written);
      newton.update({x, g, 0.0, 1});
      akvf_k.update({x, g, 0.0, 1});
      scaled_k.update({x, g, 0.0, 1});
      killing.update({x, g, 0.0, 1});
      const double c = 1 / akvf::isometric_newton_step(*density, objective.rest().total_area);
      const Eigen::MatrixXd H = unshifted(newton);
      CHECK((H - c * unshifted(akvf_k)).norm() <= 1e-8 * H.norm());
      CHECK((H - unshifted(scaled_k)).norm() <= 1e-8 * H.norm());
      if (conformal) CHECK((H - c * unshifted(killing)).norm() > 0.1 * H.norm());
    }
  }
  CHECK(akvf::isometric_newton_step(akvf::SymmetricDirichlet2D(), 1.0) == doctest::Approx(0.25).epsilon(1e-12));
  CHECK(akvf::isometric_newton_step(akvf::Arap2D(), 1.0) == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE("K_0 is PSD with exactly the similarities as null space, and K_beta = K - (1 - beta) (div)^2") {
  const PlanarMesh p = jittered_grid(7, 2);
  akvf::ElementMatrix2D K0(p.F, static_cast<int>(p.x.size() / 2)), K(p.F, static_cast<int>(p.x.size() / 2));
  const Eigen::VectorXd rest_area = p.uv_area * 1.7;
  akvf::assemble_killing_operator_2d(p.F, p.x, rest_area, true, &K0, 0.0);
  akvf::assemble_killing_operator_2d(p.F, p.x, rest_area, true, &K);
  const Eigen::MatrixXd dense0(K0.full()), dense(K.full());
  bool psd = false;
  double gap = 0;
  CHECK(akvf::test::null_space_dimension(dense0, &psd, &gap) == 4);
  CHECK(psd);
  CHECK(gap > 1e3);
  const Eigen::MatrixXd similarities = akvf::similarity_motion_basis_2d(p.x);
  CHECK((dense0 * similarities).norm() <= 1e-10 * dense0.norm());
  CHECK((similarities.transpose() * similarities - Eigen::Matrix4d::Identity()).norm() <= 1e-12);
  // A dilation's divergence is 2 on every face: K's form along it is
  // (1/2)|2I|^2 = 4 per unit of the (area-scaled) measure, K_0's 0.
  const Eigen::VectorXd dilation = p.x;
  CHECK(dilation.dot(dense * dilation) == doctest::Approx(4 * rest_area.sum()).epsilon(1e-10));
  CHECK(std::abs(dilation.dot(dense0 * dilation)) <= 1e-10 * rest_area.sum());
}

// Chen et al. 2024's adaptive filter (newton_preconditioner.h): mirror at the
// first iteration and after a step the exact quadratic model mispredicted,
// clamp after one it predicted to 1 %.
TEST_CASE("the adaptive eigenvalue filter clamps only after a step the quadratic model predicted") {
  akvf::TriMesh normalized = akvf::test::bumpy_disk(7, 7);
  const akvf::DistortionObjective2D objective = unit_area_objective(&normalized);
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(normalized, 0.2, 8) * 0.8);
  akvf::NewtonPreconditioner2D newton(objective, {}, akvf::default_newton_projection(2),
                                      akvf::EigenvalueFilter::kAdaptive);
  auto visit = [&](const Eigen::VectorXd& at, int iteration) {
    Eigen::VectorXd g;
    const double energy = objective.value_and_gradient(at, &g);
    newton.update({at, g, energy, iteration});
    return g;
  };
  const Eigen::VectorXd g = visit(x, 1);
  CHECK(newton.last_filter() == akvf::EigenvalueFilter::kAbsolute);  // no step yet
  Eigen::VectorXd d;
  newton.apply(g, &d);
  const Eigen::VectorXd near = x - 1e-4 * d;
  visit(near, 2);  // a short step: the quadratic model is exact to O(step^3)
  CHECK(newton.last_filter() == akvf::EigenvalueFilter::kClamp);
  // A gradient step to 0.9 of the flip-free bound: an element nearly
  // collapses and the energy rises, which no quadratic model predicts.
  const Eigen::VectorXd far = near - 0.9 * objective.max_feasible_step(near, -g) * g;
  CHECK(objective.count_inverted(far) == 0);
  CHECK(objective.value(far) > objective.value(near));
  visit(far, 3);
  CHECK(newton.last_filter() == akvf::EigenvalueFilter::kAbsolute);
  CHECK(newton.mirrored_assemblies() == 2);
}

TEST_CASE("the exact filter factors the unfiltered Hessian where it is positive definite, else the clamped one") {
  // After a step `step` (1: Newton's unit step, accepted at once; below 1:
  // a step the flip-free bound set).
  const auto direction_and_matrix = [](const akvf::DistortionObjective2D& objective, const Eigen::VectorXd& x,
                                       akvf::NewtonPreconditioner2D* newton, Eigen::MatrixXd* P, double step = 1) {
    Eigen::VectorXd g, d;
    const double energy = objective.value_and_gradient(x, &g);
    newton->update({x, g, energy, 1, step, step / 0.8});
    newton->apply(g, &d);
    *P = Eigen::MatrixXd(newton->matrix().full());
    CHECK(g.dot(d) > 0);
    return d;
  };
  // H v by central differences of the gradient.
  const auto hessian_times = [](const akvf::DistortionObjective2D& objective, const Eigen::VectorXd& x,
                                const Eigen::VectorXd& v) {
    Eigen::VectorXd g_plus, g_minus;
    const double h = 1e-6;
    objective.value_and_gradient(x + h * v, &g_plus);
    objective.value_and_gradient(x - h * v, &g_minus);
    return Eigen::VectorXd((g_plus - g_minus) / (2 * h));
  };
  // A bumpy disk's jittered map, shrunk: the smaller `scale`, the more
  // compressed elements and the more indefinite the Hessian.
  akvf::TriMesh bumpy = akvf::test::bumpy_disk(7, 7);
  const akvf::DistortionObjective2D bumpy_objective = unit_area_objective(&bumpy);
  const auto shrunk_map = [&](double jitter, double scale) {
    return Eigen::VectorXd(akvf::stack_uv(akvf::test::jittered_uv(bumpy, jitter, 8) * scale));
  };
  SUBCASE("compressed planar charts: elements indefinite, their sum definite but along each chart's rotation") {
    for (const int charts : {1, 2}) {
      CAPTURE(charts);
      // One jittered grid, or two side by side (a cut mesh's charts),
      // compressed by 0.99 and 0.97 and turned.
      const akvf::TriMesh grid = akvf::test::grid_disk(7, 6, 0.2, 3);
      const Eigen::Index n = grid.V.rows();
      akvf::TriMesh mesh;
      mesh.V.resize(charts * n, 3);
      mesh.F.resize(charts * grid.F.rows(), 3);
      for (int c = 0; c < charts; ++c) {
        mesh.V.middleRows(c * n, n) = grid.V;
        mesh.V.middleRows(c * n, n).col(0).array() += 2.0 * c;
        mesh.F.middleRows(c * grid.F.rows(), grid.F.rows()) = grid.F.array() + static_cast<int>(c * n);
      }
      const akvf::DistortionObjective2D objective = unit_area_objective(&mesh);
      const Eigen::Matrix2d rotation = Eigen::Rotation2Dd(0.4).toRotationMatrix();
      Eigen::MatrixXd uv = mesh.V.leftCols<2>() * rotation.transpose();
      for (int c = 0; c < charts; ++c) uv.middleRows(c * n, n) *= c == 0 ? 0.99 : 0.97;
      const Eigen::VectorXd x = akvf::stack_uv(uv);
      akvf::NewtonPreconditioner2D exact(objective, {}, akvf::default_newton_projection(2),
                                         akvf::EigenvalueFilter::kExact);
      akvf::NewtonPreconditioner2D clamped(objective);
      Eigen::MatrixXd P_exact, P_clamped;
      direction_and_matrix(objective, x, &exact, &P_exact);
      direction_and_matrix(objective, x, &clamped, &P_clamped);
      CHECK(exact.last_filter() == akvf::EigenvalueFilter::kExact);
      CHECK(exact.report().find("exact Hessian at 1 of 1 tries") != std::string::npos);
      // P less its shifts is the Hessian (central differences of the
      // gradient). Compressed, a chart's energy falls as it expands, so the
      // Hessian's curvature along its rotation, grad E . (x - c) / |x - c|^2
      // over the chart, is negative, and P carries twice its magnitude on
      // the chart's coordinates (newton_preconditioner.h).
      Eigen::VectorXd g;
      objective.value_and_gradient(x, &g);
      for (int c = 0; c < charts; ++c) {
        Eigen::MatrixXd centered = uv.middleRows(c * n, n);
        centered.rowwise() -= centered.colwise().mean();
        const double curvature = g.segment(2 * c * n, 2 * n).dot(akvf::stack_uv(centered)) / centered.squaredNorm();
        CHECK(curvature < 0);
        P_exact.diagonal().segment(2 * c * n, 2 * n).array() += 2 * curvature;
      }
      P_exact.diagonal().array() -= kShift * P_exact.diagonal().mean() / (1 + kShift);
      std::mt19937 rng(3);
      std::normal_distribution<double> normal;
      Eigen::VectorXd v(x.size());
      for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = normal(rng);
      const Eigen::VectorXd Hv = hessian_times(objective, x, v);
      CHECK((P_exact * v - Hv).norm() <= 1e-6 * Hv.norm());
      // The clamp stiffens the compressed elements' twist: another matrix.
      CHECK((P_clamped * v - Hv).norm() > 1e-3 * Hv.norm());
    }
  }
  SUBCASE("started on the fallback (akvf-newton's switch): the exact Hessian is tried from the second assembly") {
    akvf::TriMesh grid = akvf::test::grid_disk(7, 6, 0.2, 3);
    const akvf::DistortionObjective2D objective = unit_area_objective(&grid);
    // Compressed planar: the exact Hessian (with its rotation shift) factors.
    const Eigen::VectorXd x = akvf::stack_uv(grid.V.leftCols<2>() * 0.99);
    akvf::NewtonPreconditioner2D exact(objective, {}, akvf::default_newton_projection(2),
                                       akvf::EigenvalueFilter::kExact);
    exact.start_on_fallback();
    Eigen::MatrixXd P;
    direction_and_matrix(objective, x, &exact, &P);
    CHECK(exact.last_filter() == akvf::EigenvalueFilter::kClamp);
    CHECK(exact.last_partly_filtered());
    CHECK(exact.exact_assemblies() == 0);
    direction_and_matrix(objective, x, &exact, &P);
    CHECK(exact.last_filter() == akvf::EigenvalueFilter::kExact);
    CHECK(exact.report().find("exact Hessian at 1 of 1 tries") != std::string::npos);
  }
  SUBCASE(
      "a distorted map: the Hessian is indefinite, so is H + 1/4 of its negative part: the clamped one is factored") {
    const akvf::DistortionObjective2D& objective = bumpy_objective;
    const Eigen::VectorXd x = shrunk_map(0.2, 0.8);
    akvf::NewtonPreconditioner2D exact(objective, {}, akvf::default_newton_projection(2),
                                       akvf::EigenvalueFilter::kExact);
    akvf::NewtonPreconditioner2D clamped(objective);
    Eigen::MatrixXd P_exact, P_clamped;
    const Eigen::VectorXd d_exact = direction_and_matrix(objective, x, &exact, &P_exact);
    const Eigen::VectorXd d_clamped = direction_and_matrix(objective, x, &clamped, &P_clamped);
    CHECK(
        exact.report().find("exact Hessian at 0 of 1 tries, its partly filtered fallback not positive definite at 2") !=
        std::string::npos);
    CHECK(exact.last_filter() == akvf::EigenvalueFilter::kClamp);
    CHECK(exact.negative_share() == 1);
    CHECK(P_exact == P_clamped);
    CHECK(d_exact == d_clamped);
    // One iteration on the fallback, then the exact Hessian again.
    direction_and_matrix(objective, x, &exact, &P_exact);
    CHECK(exact.last_filter() == akvf::EigenvalueFilter::kClamp);
    direction_and_matrix(objective, x, &exact, &P_exact);
    CHECK(exact.report().find("exact Hessian at 0 of 2 tries") != std::string::npos);
  }
  SUBCASE("started at the clamp (akvf-newton with the constraints far): no partial try fails, then it relaxes") {
    const akvf::DistortionObjective2D& objective = bumpy_objective;
    const Eigen::VectorXd x = shrunk_map(0.2, 0.8);
    akvf::NewtonPreconditioner2D exact(objective, {}, akvf::default_newton_projection(2),
                                       akvf::EigenvalueFilter::kExact);
    exact.start_fallback_at_clamp();
    akvf::NewtonPreconditioner2D clamped(objective);
    Eigen::MatrixXd P_exact, P_clamped;
    direction_and_matrix(objective, x, &exact, &P_exact);
    direction_and_matrix(objective, x, &clamped, &P_clamped);
    CHECK(exact.report().find("exact Hessian at 0 of 1 tries") != std::string::npos);
    CHECK(exact.partial_fallbacks() == 0);
    CHECK(exact.negative_share() == 1);
    CHECK(P_exact == P_clamped);
    // While the exact Hessian waits, the clamp serves again, at once; so
    // the fallback after the exact Hessian's next failure keeps a quarter
    // of the negative part, which does not factor here (the subcase above)
    // and is quadrupled back to the clamp.
    direction_and_matrix(objective, x, &exact, &P_exact);
    CHECK(exact.partial_fallbacks() == 0);
    CHECK(P_exact == P_clamped);
    direction_and_matrix(objective, x, &exact, &P_exact);
    CHECK(exact.report().find("exact Hessian at 0 of 2 tries") != std::string::npos);
    CHECK(exact.partial_fallbacks() == 1);
    CHECK(exact.negative_share() == 1);
    CHECK(P_exact == P_clamped);
  }
  SUBCASE("a milder distortion: the fallback keeps part of the negative curvature, the least share that factors") {
    const akvf::DistortionObjective2D& objective = bumpy_objective;
    // The first of these maps, from milder to stronger, where the exact
    // Hessian does not factor but H + mu N with mu < 1 does (which one is
    // decided by the rounding of a near-singular pivot, so the compilers
    // may differ).
    Eigen::VectorXd x;
    std::unique_ptr<akvf::NewtonPreconditioner2D> found;
    Eigen::MatrixXd P;
    for (const double scale : {0.95, 0.9, 0.85, 0.8}) {
      x = shrunk_map(0.05, scale);
      found = std::make_unique<akvf::NewtonPreconditioner2D>(
          objective, akvf::FactorOptions{}, akvf::default_newton_projection(2), akvf::EigenvalueFilter::kExact);
      direction_and_matrix(objective, x, found.get(), &P);
      if (found->exact_fallbacks() == 1 && found->negative_share() < 1) break;
      found.reset();
    }
    REQUIRE(found);
    akvf::NewtonPreconditioner2D& exact = *found;
    CHECK(exact.last_partly_filtered());
    const double share = exact.negative_share();
    // 1/16, then 4x per failure: the failures before the share that factored.
    const int failures = share == 0.25 ? 1 : 0;
    CHECK((share == 1.0 / 16 || share == 0.25));
    CHECK(exact.partial_fallbacks() == failures);
    akvf::NewtonPreconditioner2D clamped(objective);
    Eigen::MatrixXd P_clamped;
    direction_and_matrix(objective, x, &clamped, &P_clamped);
    // P = (1 - share) H + share P_clamped, up to multiples of I (the
    // rotation's and the Tikhonov shifts): the rest is parallel to v.
    std::mt19937 rng(5);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 3; ++trial) {
      Eigen::VectorXd v(x.size());
      for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = normal(rng);
      const Eigen::VectorXd Hv = hessian_times(objective, x, v);
      const Eigen::VectorXd rest = P * v - (1 - share) * Hv - share * (P_clamped * v);
      const double along = rest.dot(v) / v.squaredNorm();
      CHECK(along >= 0);
      CHECK((rest - along * v).norm() <= 1e-5 * Hv.norm());
      CHECK((P * v - P_clamped * v).norm() > 1e-3 * Hv.norm());  // not the clamp
    }
    // While the exact Hessian waits, the share that served is kept; after a
    // fallback that served at once, the next one keeps a quarter of it (and
    // at the same x is quadrupled back).
    direction_and_matrix(objective, x, &exact, &P);
    CHECK(exact.last_partly_filtered());
    CHECK(exact.negative_share() == share);
    CHECK(exact.partial_fallbacks() == failures);
    direction_and_matrix(objective, x, &exact, &P);
    CHECK(exact.exact_fallbacks() == 2);
    CHECK(exact.negative_share() == share);
    CHECK(exact.partial_fallbacks() == 2 * failures);
    // After a fallback that served at once, a step the flip-free bound set
    // quadruples the share (a trust region's radius shrinking), with no
    // failed factorization.
    direction_and_matrix(objective, x, &exact, &P);
    CHECK(exact.negative_share() == share);
    direction_and_matrix(objective, x, &exact, &P, 0.5);
    CHECK(exact.last_partly_filtered());
    CHECK(exact.negative_share() == std::min(1.0, 4 * share));
    CHECK(exact.partial_fallbacks() == 2 * failures);
  }
  SUBCASE("after a unit step that took E more than halfway down to its infimum, nothing nearer the exact Hessian") {
    akvf::TriMesh mesh = akvf::test::grid_disk(7, 6, 0.2, 3);
    const akvf::DistortionObjective2D objective = unit_area_objective(&mesh);
    // Symmetric Dirichlet at a uniform scale s is 2 (s^2 + s^-2); its infimum is 4.
    const auto scaled = [&](double s) { return Eigen::VectorXd(akvf::stack_uv(mesh.V.leftCols<2>() * s)); };
    akvf::NewtonPreconditioner2D exact(objective, {}, akvf::default_newton_projection(2),
                                       akvf::EigenvalueFilter::kExact);
    Eigen::MatrixXd P;
    direction_and_matrix(objective, scaled(0.8), &exact, &P, 0);  // the run's first assembly: the clamp
    CHECK(exact.negative_share() == 1);
    direction_and_matrix(objective, scaled(0.99), &exact, &P);  // E - 4: 0.41 -> 0.0008
    CHECK(exact.last_filter() == akvf::EigenvalueFilter::kClamp);
    CHECK(exact.exact_assemblies() == 0);
    CHECK(exact.negative_share() == 1);
    direction_and_matrix(objective, scaled(0.99), &exact, &P);  // a unit step that left all of it
    CHECK(exact.last_filter() == akvf::EigenvalueFilter::kExact);
    CHECK(exact.report().find("exact Hessian at 1 of 1 tries") != std::string::npos);
  }
  SUBCASE("solved by CG, which cannot tell whether the Hessian is definite, the element Hessians are clamped") {
    const akvf::DistortionObjective2D& objective = bumpy_objective;
    const Eigen::VectorXd x = shrunk_map(0.2, 0.8);
    akvf::FactorOptions by_cg;
    by_cg.cg_tolerance = 0.01;
    akvf::NewtonPreconditioner2D exact(objective, by_cg, akvf::default_newton_projection(2),
                                       akvf::EigenvalueFilter::kExact);
    Eigen::MatrixXd P;
    direction_and_matrix(objective, x, &exact, &P);
    CHECK(exact.last_filter() == akvf::EigenvalueFilter::kClamp);
    CHECK(exact.exact_assemblies() == 0);
  }
}
