// The public API of <akvf/akvf.h>: one-call parameterize and deform, the
// stateful Parameterizer, option validation, statistics as numbers, typed
// errors, and the same bits as the command line for the same options.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "akvf/akvf.h"
#include "akvf/internal/option_schema.h"
#include "cli/akvf_cli.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

namespace fs = std::filesystem;

namespace {

int inverted(const Eigen::MatrixXd& uv, const Eigen::MatrixXi& F) {
  int count = 0;
  for (int f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector2d e1 = uv.row(F(f, 1)) - uv.row(F(f, 0)), e2 = uv.row(F(f, 2)) - uv.row(F(f, 0));
    count += !(e1.x() * e2.y() - e1.y() * e2.x() > 0);
  }
  return count;
}

}  // namespace

TEST_CASE("akvf::parameterize with default options converges on a curved grid, no inverted triangle") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(12, 10);
  const akvf::ParameterizeResult r = akvf::parameterize(mesh.V, mesh.F);
  CHECK(r.status == akvf::TerminationStatus::kConverged);
  CHECK(r.uv.rows() == mesh.V.rows());
  CHECK(r.uv.cols() == 2);
  CHECK(inverted(r.uv, mesh.F) == 0);
  CHECK(r.grad_norm() < 1e-3);
  CHECK(r.iterations() == r.statistics.iterations);
  CHECK(r.statistics.preconditioner.factorizations >= 1);
  CHECK(r.statistics.seconds >= r.statistics.preconditioner_seconds);
  CHECK(r.message == "gradient norm below 0.001000");
}

TEST_CASE("the API gives the command line's bits for the same mesh and options") {
  const fs::path dir = fs::temp_directory_path() / "akvf_api_cli";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(10, 9);
  akvf::test::write_obj(dir / "m.obj", mesh);
  std::ostringstream out, err;
  REQUIRE(akvf::run_akvf({"param", (dir / "m.obj").string(), "-q", "--precond", "newton", "--texture", "none", "--out",
                          (dir / "uv.obj").string(), "--trace", (dir / "t.csv").string()},
                         out, err) == 0);
  akvf::ParameterizeOptions options;
  options.preconditioner = "newton";
  const akvf::TriMesh read = akvf::read_triangle_mesh((dir / "m.obj").string());
  const akvf::ParameterizeResult r = akvf::parameterize(read.V, read.F, options);
  // The UV OBJ holds the map with 17 digits: the same doubles.
  std::ifstream uv_file(dir / "uv.obj");
  std::string line;
  int v = 0;
  while (std::getline(uv_file, line))
    if (line.rfind("vt ", 0) == 0) {
      std::istringstream fields(line.substr(3));
      double u = 0, w = 0;
      fields >> u >> w;
      CHECK(u == r.uv(v, 0));
      CHECK(w == r.uv(v, 1));
      ++v;
    }
  CHECK(v == mesh.num_vertices());
  CHECK(out.str().find("after " + std::to_string(r.iterations()) + " iterations") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("a Parameterizer solves again with the same bits, from a given map, and with new options") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(9, 9);
  akvf::Parameterizer solver(mesh.V, mesh.F);
  const akvf::ParameterizeResult first = solver.solve(), second = solver.solve();
  CHECK(first.uv == second.uv);
  CHECK(first.uv == akvf::parameterize(mesh.V, mesh.F).uv);
  // The symbolic analysis is done once per mesh: the second solve takes it
  // from the first (and still gives the same bits).
  CHECK(first.statistics.preconditioner.symbolic_analyses == 1);
  CHECK(second.statistics.preconditioner.symbolic_analyses == 0);
  CHECK(second.statistics.preconditioner.factorizations == first.statistics.preconditioner.factorizations);
  // From its own result (rescaled to the input's area, so not quite the
  // optimizer's last iterate): converged again at once.
  const akvf::ParameterizeResult again = solver.solve(first.uv);
  CHECK(again.status == akvf::TerminationStatus::kConverged);
  CHECK(again.iterations() <= 3);
  CHECK(again.energy() == doctest::Approx(first.energy()).epsilon(1e-6));
  // New options without a new start map.
  akvf::ParameterizeOptions options;
  options.preconditioner = "slim";
  solver.set_options(options);
  const akvf::ParameterizeResult slim = solver.solve();
  CHECK(slim.status == akvf::TerminationStatus::kConverged);
  CHECK(slim.energy() == doctest::Approx(first.energy()).epsilon(1e-5));
  CHECK(slim.statistics.preconditioner.symbolic_analyses == 0);  // SLIM's matrix has AKVF's pattern
  // A bad option is refused and the old ones kept.
  options.preconditioner = "slm";
  CHECK(akvf::test::error_message([&] { solver.set_options(options); }).find("unknown preconditioner 'slm'") == 0);
  CHECK(solver.options().preconditioner == "slim");
  // A start map of the wrong shape or with an inverted triangle.
  CHECK(akvf::test::error_message([&] {
          solver.solve(Eigen::MatrixXd::Zero(3, 2));
        }).find("the start map must be #V by 2") == 0);
  Eigen::MatrixXd flipped = first.uv;
  flipped.col(0) *= -1;
  CHECK(akvf::test::error_message([&] {
          solver.solve(flipped);
        }).find("the start map inverts a triangle: triangle 0") == 0);
}

TEST_CASE("options are validated in one place, with the messages the command line prints") {
  akvf::ParameterizeOptions options;
  std::string error;
  CHECK(options.is_valid(&error));
  options.exponent = -1;
  CHECK_FALSE(options.is_valid(&error));
  CHECK(error == "exponent must be > 0, found -1");
  options = {};
  options.energy = "nope";
  CHECK_FALSE(options.is_valid(&error));
  CHECK(error.find("unknown energy 'nope' (valid: symmetric-dirichlet, ") == 0);
  options = {};
  options.akvf_reuse = 1;
  CHECK_FALSE(options.is_valid(&error));
  CHECK(error == "akvf_reuse must be in [0, 1), found 1");
  options = {};
  options.threads = -1;
  CHECK_FALSE(options.is_valid(&error));
  options = {};
  CHECK(akvf::test::error_message([&] {
          akvf::set_option_text(akvf::parameterize_option_fields(), "init", "harmonic", &options);
        }) == "unknown initialization 'harmonic' (valid: auto, tutte, cotan, conformal, boundary-first, file)");
  CHECK(akvf::test::error_message([&] {
          akvf::set_option_text(akvf::parameterize_option_fields(), "acceleration", "sometimes", &options);
        }) == "unknown acceleration 'sometimes' (valid: auto, on, off)");
  akvf::set_option_text(akvf::parameterize_option_fields(), "init", "cotangent", &options);  // an alias
  CHECK(options.init == akvf::InitialMap::kCotan);
  CHECK(akvf::choice_name(options.init) == "cotan");
  akvf::DeformOptions deform;
  CHECK(deform.is_valid());
  deform.weight = 0;
  CHECK_FALSE(deform.is_valid(&error));
  CHECK(error == "weight must be > 0, found 0");
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(5, 5);
  options.newton_reuse = 1.5;
  CHECK_FALSE(options.is_valid(&error));
  CHECK(error == "newton_reuse must be auto or in [0, 1), found 1.5");
  CHECK_THROWS_AS(akvf::parameterize(mesh.V, mesh.F, options), akvf::OptionsError);
}

TEST_CASE("bad arrays are typed errors naming the problem") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(5, 5);
  CHECK_THROWS_AS(akvf::parameterize(mesh.V.leftCols(2), mesh.F), akvf::InputError);
  Eigen::MatrixXi F = mesh.F;
  F(3, 1) = 999;
  CHECK(akvf::test::error_message([&] { akvf::parameterize(mesh.V, F); }) ==
        "mesh: face 3 has vertex index 999 out of range (25 vertices) (numbered from 0)");
  Eigen::MatrixXd V = mesh.V;
  V(2, 0) = std::nan("");
  CHECK_THROWS_AS(akvf::parameterize(V, mesh.F), akvf::ValidationError);
}

TEST_CASE("callbacks see every row and can stop the run") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(8, 8);
  akvf::ParameterizeOptions options;
  int rows = 0;
  options.callbacks.push_back([&](const akvf::IterationSummary& row, const Eigen::VectorXd&) {
    ++rows;
    return row.iteration == 2 ? akvf::CallbackAction::kStop : akvf::CallbackAction::kContinue;
  });
  const akvf::ParameterizeResult r = akvf::parameterize(mesh.V, mesh.F, options);
  CHECK(r.status == akvf::TerminationStatus::kUserStopped);
  CHECK(rows == 3);
  CHECK(r.iterations() == 2);
}

TEST_CASE("akvf::deform lifts a tet grid without inverting a tet, the result is at the input's scale") {
  akvf::TetMesh mesh = akvf::test::tet_grid(3);
  mesh.V *= 250;  // units of the user's choice
  akvf::PositionConstraints constraints;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (mesh.V(v, 2) == 0 || mesh.V(v, 2) == 250) constraints.vertices.push_back(v);
  constraints.targets.resize(static_cast<Eigen::Index>(constraints.vertices.size()), 3);
  for (std::size_t c = 0; c < constraints.vertices.size(); ++c) {
    constraints.targets.row(c) = mesh.V.row(constraints.vertices[c]);
    if (mesh.V(constraints.vertices[c], 2) == 250) constraints.targets(c, 2) = 300;
  }
  akvf::DeformOptions options;
  options.max_iters = 40;
  const akvf::DeformResult r = akvf::deform(mesh.V, mesh.T, constraints, options);
  CHECK(akvf::is_normal_termination(r.status));
  CHECK(r.x.rows() == mesh.num_vertices());
  CHECK(r.x.col(2).maxCoeff() == doctest::Approx(300).epsilon(1e-3));
  for (const auto& row : r.trace) CHECK(row.flips == 0);
  CHECK(r.statistics.preconditioner.factorizations >= 1);
  CHECK(akvf::test::error_message([&] {
          akvf::PositionConstraints bad = constraints;
          bad.vertices[0] = -4;
          akvf::deform(mesh.V, mesh.T, bad, options);
        }) == "constraint 0: vertex index -4 out of range (64 vertices, 0-based)");
}

TEST_CASE("a Deformer solves for new targets and options on one prepared mesh, with deform()'s bits") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(2);
  akvf::PositionConstraints constraints;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (mesh.V(v, 2) == 0 || mesh.V(v, 2) == 1) constraints.vertices.push_back(v);
  constraints.targets.resize(static_cast<Eigen::Index>(constraints.vertices.size()), 3);
  for (std::size_t c = 0; c < constraints.vertices.size(); ++c)
    constraints.targets.row(c) = mesh.V.row(constraints.vertices[c]) * 1.1;
  akvf::DeformOptions options;
  options.max_iters = 10;
  const akvf::Deformer deformer(mesh.V, mesh.T);
  const akvf::DeformResult a = deformer.solve(constraints, options);
  CHECK(a.x == akvf::deform(mesh.V, mesh.T, constraints, options).x);
  CHECK(a.statistics.preconditioner.symbolic_analyses == 1);
  options.preconditioner = "newton";
  constraints.targets *= 1.05;
  const akvf::DeformResult b = deformer.solve(constraints, options);
  CHECK(b.statistics.preconditioner.symbolic_analyses == 0);  // taken from the first solve
  CHECK(akvf::is_normal_termination(b.status));
  CHECK(b.x.col(2).maxCoeff() > a.x.col(2).maxCoeff());
}
