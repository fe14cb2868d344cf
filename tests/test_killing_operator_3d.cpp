// The volumetric Killing operator of Eq. (9)-(10).
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <random>

#include "akvf/motion_bases.h"
#include "akvf/rest_geometry.h"
#include "energies/amips.h"
#include "energies/arap.h"
#include "energies/exp_symmetric_dirichlet.h"
#include "energies/mips.h"
#include "energies/symmetric_dirichlet.h"
#include "framework/mesh/tet_validation.h"
#include "framework/optimization/distortion_objective.h"
#include "preconditioners/energy_scale.h"
#include "preconditioners/killing_operator_3d.h"
#include "tests/test_support.h"

namespace {

Eigen::VectorXd stack(const Eigen::MatrixXd& V) {
  const Eigen::MatrixXd Vt = V.transpose();
  return Eigen::Map<const Eigen::VectorXd>(Vt.data(), Vt.size());
}

// Eq. (6) with n = 3: Vol [grad phi_j grad phi_i^T + (grad phi_i . grad phi_j) I], from hat gradients.
Eigen::Matrix<double, 12, 12> fem_local(const Eigen::Vector3d p[4]) {
  Eigen::Matrix3d Ds;
  Ds << p[1] - p[0], p[2] - p[0], p[3] - p[0];
  const double volume = Ds.determinant() / 6;
  const Eigen::Matrix3d inv = Ds.inverse();  // rows: gradients of phi_1..3
  Eigen::Vector3d grad[4];
  for (int k = 1; k < 4; ++k) grad[k] = inv.row(k - 1).transpose();
  grad[0] = -(grad[1] + grad[2] + grad[3]);
  Eigen::Matrix<double, 12, 12> K;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      K.block<3, 3>(3 * i, 3 * j) =
          volume * (grad[j] * grad[i].transpose() + grad[i].dot(grad[j]) * Eigen::Matrix3d::Identity());
  return K;
}

}  // namespace

TEST_CASE("Eq. (9)-(10) equal the FEM form Eq. (6) with n = 3 on random tets") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int tested = 0;
  for (int trial = 0; trial < 200 && tested < 100; ++trial) {
    Eigen::Vector3d p[4];
    for (auto& q : p) q = Eigen::Vector3d(u(rng), u(rng), u(rng));
    const double volume = (p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])) / 6;
    if (std::abs(volume) < 1e-2) continue;
    if (volume < 0) std::swap(p[2], p[3]);
    akvf::ElementMatrix3D::Local closed_form;
    akvf::killing_local_matrix_3d(p, 1.0, &closed_form);
    const Eigen::Matrix<double, 12, 12> fem = fem_local(p);
    CHECK((closed_form - fem).norm() <= 1e-10 * fem.norm());
    ++tested;
  }
  CHECK(tested == 100);
}

TEST_CASE("3D K is symmetric PSD with exactly the six rigid motions in its null space") {
  akvf::TetMesh mesh = akvf::test::tet_grid(2);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (int v = 0; v < mesh.num_vertices(); ++v) mesh.V.row(v) += Eigen::RowVector3d(u(rng), u(rng), u(rng));
  for (int t = 0; t < mesh.num_tets(); ++t) REQUIRE(akvf::signed_tet_volume(mesh, t) > 0);
  const Eigen::VectorXd x = stack(mesh.V);
  akvf::ElementMatrix3D matrix(mesh.T, mesh.num_vertices());
  akvf::assemble_killing_operator_3d(mesh.T, x, &matrix);
  const Eigen::MatrixXd K(matrix.full());
  CHECK((K - K.transpose()).norm() <= 1e-12 * K.norm());
  bool psd = false;
  double gap = 0;
  CHECK(akvf::test::null_space_dimension(K, &psd, &gap) == 6);
  CHECK(psd);
  CHECK(gap > 1e3);
  const Eigen::MatrixXd rigid = akvf::rigid_motion_basis_3d(x);
  CHECK((K * rigid).norm() <= 1e-10 * K.norm());
  CHECK((rigid.transpose() * rigid - Eigen::MatrixXd::Identity(6, 6)).norm() <= 1e-12);
}

TEST_CASE("3D: at a rotation the Hessian is c K_beta(x), beta the energy's divergence weight") {
  akvf::TetMesh mesh = akvf::test::tet_grid(2);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (int v = 0; v < mesh.num_vertices(); ++v) mesh.V.row(v) += Eigen::RowVector3d(u(rng), u(rng), u(rng));
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::VectorXd x = stack(mesh.V * rotation.transpose());
  std::normal_distribution<double> n;
  for (const auto& density : std::vector<std::shared_ptr<akvf::DistortionDensity3D>>{
           std::make_shared<akvf::SymmetricDirichlet3D>(), std::make_shared<akvf::Arap3D>(),
           std::make_shared<akvf::ExpSymmetricDirichlet3D>(0.5), std::make_shared<akvf::Mips3D>(),
           std::make_shared<akvf::Amips3D>(1.5)}) {
    CAPTURE(density->name());
    const double beta = akvf::rest_divergence_weight(*density);
    // 1 for the isometric energies, 0 for MIPS (scale invariant), 9/4 for
    // AMIPS, whose volume term (g + 1/g)/4 curves along a dilation g = (1 + t)^3.
    const double expected = density->name() == "mips" ? 0.0 : density->name() == "amips" ? 2.25 : 1.0;
    CHECK(beta == doctest::Approx(expected).epsilon(1e-12));
    const akvf::DistortionObjective3D objective(mesh.T, akvf::rest_tets(mesh), density, mesh.num_vertices());
    akvf::ElementMatrix3D matrix(mesh.T, mesh.num_vertices());
    akvf::assemble_killing_operator_3d(mesh.T, x, &matrix, beta);
    const Eigen::MatrixXd K(matrix.full());
    const double c = akvf::rest_shear_curvature(*density) / (4 * objective.rest().total_volume);
    for (int trial = 0; trial < 3; ++trial) {
      const Eigen::VectorXd v = Eigen::VectorXd::NullaryExpr(x.size(), [&](Eigen::Index) { return n(rng); });
      // v^T H v by central differences of the gradient.
      const double h = 1e-5;
      Eigen::VectorXd g_plus, g_minus;
      objective.value_and_gradient(x + h * v, &g_plus);
      objective.value_and_gradient(x - h * v, &g_minus);
      const double curvature = v.dot(g_plus - g_minus) / (2 * h);
      CHECK(curvature == doctest::Approx(c * v.dot(K * v)).epsilon(1e-6));
    }
  }
}

TEST_CASE("3D K_0 has the rigid motions and the dilation as null space, and K along a dilation is 6 Vol") {
  akvf::TetMesh mesh = akvf::test::tet_grid(2);
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (int v = 0; v < mesh.num_vertices(); ++v) mesh.V.row(v) += Eigen::RowVector3d(u(rng), u(rng), u(rng));
  const Eigen::VectorXd x = stack(mesh.V);
  akvf::ElementMatrix3D K0(mesh.T, mesh.num_vertices()), K(mesh.T, mesh.num_vertices());
  akvf::assemble_killing_operator_3d(mesh.T, x, &K0, 0.0);
  akvf::assemble_killing_operator_3d(mesh.T, x, &K);
  const Eigen::MatrixXd dense0(K0.full()), dense(K.full());
  bool psd = false;
  double gap = 0;
  CHECK(akvf::test::null_space_dimension(dense0, &psd, &gap) == 7);
  CHECK(psd);
  CHECK(gap > 1e3);
  double volume = 0;
  for (int t = 0; t < mesh.num_tets(); ++t) volume += akvf::signed_tet_volume(mesh, t);
  // (1/2)|2 I|^2 = 6 per unit volume for K, 0 for K_0.
  CHECK(x.dot(dense * x) == doctest::Approx(6 * volume).epsilon(1e-10));
  CHECK(std::abs(x.dot(dense0 * x)) <= 1e-10 * volume);
}
