// Initial maps: Tutte embedding and the flap optimization of §5.4.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "akvf/rest_geometry.h"
#include "framework/mesh/chart_layout.h"
#include "framework/mesh/initialization.h"
#include "framework/mesh/mesh_validation.h"
#include "framework/optimization/distortion_objective.h"
#include "solvers/sparse_cholesky.h"
#include "tests/test_support.h"

TEST_CASE("Tutte maps a disk without inverted triangles onto a circle of the mesh's area") {
  for (auto weights : {akvf::TutteWeights::kUniform, akvf::TutteWeights::kCotangent}) {
    const akvf::TriMesh mesh = akvf::test::bumpy_disk(9, 7);
    const auto disk = akvf::prepare_disk_mesh(mesh, "bumpy");
    akvf::Warnings warnings;
    const Eigen::MatrixXd UV = akvf::tutte_embedding(mesh, disk.boundary_loops[0], weights, &warnings);
    CHECK(akvf::count_inverted_triangles(mesh.F, UV) == 0);
    const double radius = std::sqrt(akvf::rest_triangles(mesh).total_area / std::numbers::pi);
    for (int v : disk.boundary_loops[0]) CHECK(UV.row(v).norm() == doctest::Approx(radius).epsilon(1e-12));
  }
}

TEST_CASE("a given solver gives the Tutte map Eigen's gives, and one that declines falls back to Eigen's") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(9, 7);
  const auto disk = akvf::prepare_disk_mesh(mesh, "bumpy");
  akvf::Warnings warnings;
  const auto tutte = [&](akvf::TutteWeights weights, const akvf::SpdSolver& solver) {
    return akvf::tutte_embedding(mesh, disk.boundary_loops[0], weights, &warnings, solver);
  };
  const akvf::SpdSolver declines = [](const Eigen::SparseMatrix<double>&, const Eigen::MatrixXd&,
                                      const std::vector<int>&, Eigen::MatrixXd*) { return false; };
  // The unknowns are the interior vertices, in increasing order.
  std::vector<int> interior;
  std::vector<bool> on_boundary(mesh.num_vertices(), false);
  for (int v : disk.boundary_loops[0]) on_boundary[v] = true;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (!on_boundary[v]) interior.push_back(v);
  int calls = 0;
  const akvf::SpdSolver cholmod_solver = [&](const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B,
                                             const std::vector<int>& vertices, Eigen::MatrixXd* X) {
    ++calls;
    CHECK(vertices == interior);
    return akvf::solve_positive_definite(A, B, X);
  };
  for (auto weights : {akvf::TutteWeights::kUniform, akvf::TutteWeights::kCotangent}) {
    const Eigen::MatrixXd eigen = tutte(weights, {});
    calls = 0;
    const Eigen::MatrixXd cholmod = tutte(weights, cholmod_solver);
    CHECK(calls == 1);
    CHECK((cholmod - eigen).cwiseAbs().maxCoeff() <= 1e-12 * eigen.cwiseAbs().maxCoeff());
    CHECK(tutte(weights, declines) == eigen);
  }
}

TEST_CASE("per-chart Tutte systems name their unknowns by the whole mesh's vertices") {
  // Two disks side by side in one mesh, one chart each; the second's
  // vertices numbered after the first's.
  const akvf::TriMesh first = akvf::test::bumpy_disk(6, 5), second = akvf::test::bumpy_disk(5, 7);
  const int n1 = first.num_vertices();
  akvf::TriMesh mesh;
  mesh.V.resize(n1 + second.num_vertices(), 3);
  mesh.V << first.V, second.V;
  mesh.F.resize(first.num_faces() + second.num_faces(), 3);
  mesh.F << first.F, (second.F.array() + n1).matrix();
  std::vector<int> face_chart(mesh.num_faces(), 1);
  std::fill(face_chart.begin(), face_chart.begin() + first.num_faces(), 0);
  std::vector<std::vector<int>> loops = {akvf::prepare_disk_mesh(first, "first").boundary_loops[0],
                                         akvf::prepare_disk_mesh(second, "second").boundary_loops[0]};
  for (int& v : loops[1]) v += n1;
  std::vector<std::vector<int>> expected(2);
  for (int c = 0; c < 2; ++c) {
    std::vector<bool> on_loop(mesh.num_vertices(), false);
    for (int v : loops[c]) on_loop[v] = true;
    for (int v = c == 0 ? 0 : n1; v < (c == 0 ? n1 : mesh.num_vertices()); ++v)
      if (!on_loop[v]) expected[c].push_back(v);
  }
  std::vector<std::vector<int>> seen;
  const akvf::SpdSolver recording = [&](const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B,
                                        const std::vector<int>& vertices, Eigen::MatrixXd* X) {
    seen.push_back(vertices);
    return akvf::solve_positive_definite(A, B, X);
  };
  akvf::Warnings warnings;
  const Eigen::MatrixXd UV =
      akvf::tutte_embedding_charts(mesh, loops, face_chart, akvf::TutteWeights::kUniform, &warnings, recording);
  CHECK(seen == expected);
  CHECK(akvf::count_inverted_triangles(mesh.F, UV) == 0);
}

TEST_CASE("cotangent Tutte falls back to uniform weights when it would fold") {
  // Obtuse triangles give negative cotangent weights; a needle fan folds.
  akvf::TriMesh mesh = akvf::test::grid_disk(6, 6, 0.45, 3);
  mesh.V.col(0) *= 40;  // very anisotropic cells: many obtuse angles
  const auto disk = akvf::prepare_disk_mesh(mesh, "stretched");
  akvf::Warnings warnings;
  const Eigen::MatrixXd UV =
      akvf::tutte_embedding(mesh, disk.boundary_loops[0], akvf::TutteWeights::kCotangent, &warnings);
  CHECK(akvf::count_inverted_triangles(mesh.F, UV) == 0);
  if (!warnings.empty()) CHECK(warnings[0].find("using uniform weights instead") != std::string::npos);
}

TEST_CASE("flap optimization makes a flap triangle isometric to its 3D shape") {
  // A strip of two triangles where vertex 3 lies in one triangle only.
  akvf::TriMesh mesh;
  mesh.V.resize(4, 3);
  mesh.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1.2, 0.9, 0.4;
  mesh.F.resize(2, 3);
  mesh.F << 0, 1, 2, 1, 3, 2;
  Eigen::MatrixXd UV(4, 2);
  UV << 0, 0, 1, 0, 0, 1, 0.3, 0.3;             // vertex 3 badly placed (even inverted)
  CHECK(akvf::optimize_flaps(mesh, &UV) == 2);  // vertices 0 and 3 are flaps
  const auto rest = akvf::rest_triangles(mesh);
  // Face 1 = (1, 3, 2): its Jacobian is a rotation after the move.
  Eigen::Matrix2d Ds;
  Ds << (UV.row(3) - UV.row(1)).transpose(), (UV.row(2) - UV.row(1)).transpose();
  const Eigen::Matrix2d J = Ds * rest.Dm_inv[1];
  CHECK((J.transpose() * J - Eigen::Matrix2d::Identity()).norm() <= 1e-12);
  CHECK(J.determinant() > 0);
}
