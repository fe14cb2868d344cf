// Metamorphic tests: permuting vertices, permuting elements, translating,
// rotating and uniformly scaling the input leave the energy and gradient-norm
// columns of the trace unchanged (1e-9 relative), in 2D and 3D, for AKVF and
// projected Newton; and uniform scales from 1e-100 to 1e+100 give the same
// energies and iterations as scale 1.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <numeric>
#include <random>

#include "akvf/internal/deformation.h"
#include "akvf/internal/parameterization.h"
#include "tests/test_support.h"

namespace {

// A transformation of the input: positions (#V by 3, row-wise) and a vertex
// permutation p (vertex v of the input becomes vertex p[v]) and an element
// order (element e of the output is element order[e] of the input).
struct Transform {
  std::string name;
  std::vector<int> vertex_to;                            // empty = identity
  std::vector<int> element_from;                         // empty = identity
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();  // rotation times scale
  Eigen::RowVector3d shift = Eigen::RowVector3d::Zero();
};

std::vector<int> random_permutation(int n, unsigned seed) {
  std::vector<int> p(n);
  std::iota(p.begin(), p.end(), 0);
  std::shuffle(p.begin(), p.end(), std::mt19937(seed));
  return p;
}

std::vector<Transform> transforms(int vertices, int elements) {
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -0.5).normalized()).toRotationMatrix();
  std::vector<Transform> list(6);
  list[0].name = "identity";
  list[1].name = "permuted vertices";
  list[1].vertex_to = random_permutation(vertices, 3);
  list[2].name = "permuted elements";
  list[2].element_from = random_permutation(elements, 5);
  list[3].name = "translated";
  list[3].shift << 12.5, -3, 40;
  list[4].name = "rotated";
  list[4].linear = rotation;
  list[5].name = "scaled by 37.5 and rotated";
  list[5].linear = 37.5 * rotation;
  return list;
}

Eigen::MatrixXd moved(const Eigen::MatrixXd& P, const Transform& t) {
  Eigen::MatrixXd out = (P * t.linear.transpose()).rowwise() + t.shift;
  if (t.vertex_to.empty()) return out;
  Eigen::MatrixXd permuted(out.rows(), out.cols());
  for (int v = 0; v < out.rows(); ++v) permuted.row(t.vertex_to[v]) = out.row(v);
  return permuted;
}

Eigen::MatrixXi renumbered(const Eigen::MatrixXi& E, const Transform& t) {
  Eigen::MatrixXi out = t.vertex_to.empty() ? E : E.unaryExpr([&](int v) { return t.vertex_to[v]; }).eval();
  if (t.element_from.empty()) return out;
  Eigen::MatrixXi reordered(out.rows(), out.cols());
  for (int e = 0; e < out.rows(); ++e) reordered.row(e) = out.row(t.element_from[e]);
  return reordered;
}

// Runs stop above the noise floor: near the minimum E is flat to rounding, so
// iterates are only determined to about sqrt(machine epsilon) and gradient
// norms below ~1e-6 differ between equivalent inputs by their own size.
constexpr double kGradientFloor = 1e-5;

void check_same_trace(const akvf::OptimizerResult& a, const akvf::OptimizerResult& b) {
  REQUIRE(a.trace.size() == b.trace.size());
  CHECK(a.status == b.status);
  for (std::size_t i = 0; i < a.trace.size(); ++i) {
    CAPTURE(i);
    CHECK(b.trace[i].energy == doctest::Approx(a.trace[i].energy).epsilon(1e-9));
    CHECK(b.trace[i].grad_norm == doctest::Approx(a.trace[i].grad_norm).epsilon(1e-9));
    CHECK(b.trace[i].flips == 0);
  }
}

akvf::OptimizerResult param_run(const akvf::TriMesh& mesh, const std::string& method, int iterations) {
  akvf::ParamConfig config;
  config.preconditioner = method;
  config.optimizer.max_iterations = iterations;
  config.optimizer.gradient_tolerance = kGradientFloor;
  const akvf::ParamSetup setup = akvf::prepare_parameterization(mesh, "m", config);
  return akvf::run_parameterization(setup, config).result;
}

}  // namespace

TEST_CASE("2D: permuted, translated, rotated and scaled inputs give the same energy trace (AKVF, Newton)") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(9, 8);
  for (const char* method : {"akvf", "newton"}) {
    CAPTURE(method);
    const akvf::OptimizerResult reference = param_run(mesh, method, 12);
    for (const Transform& t : transforms(mesh.num_vertices(), mesh.num_faces())) {
      CAPTURE(t.name);
      akvf::TriMesh changed;
      changed.V = moved(mesh.V, t);
      changed.F = renumbered(mesh.F, t);
      check_same_trace(reference, param_run(changed, method, 12));
    }
  }
}

TEST_CASE("3D: permuted, translated, rotated and scaled inputs give the same energy trace (AKVF, Newton)") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(3);
  // Bottom fixed, top lifted and turned: soft constraints (w = 1e5).
  akvf::PositionConstraints constraints;
  std::vector<Eigen::RowVector3d> targets;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Eigen::RowVector3d p = mesh.V.row(v);
    if (p.z() != 0 && p.z() != 1) continue;
    constraints.vertices.push_back(v);
    const Eigen::Vector3d centred(p.x() - 0.5, p.y() - 0.5, 0);
    targets.push_back((Eigen::AngleAxisd(p.z() * 0.4, Eigen::Vector3d::UnitZ()) * centred).transpose() +
                      Eigen::RowVector3d(0.5, 0.5, 1.2 * p.z()));
  }
  constraints.targets.resize(static_cast<Eigen::Index>(targets.size()), 3);
  for (std::size_t c = 0; c < targets.size(); ++c) constraints.targets.row(c) = targets[c];

  auto run = [](const akvf::TetMesh& m, const akvf::PositionConstraints& c, const std::string& method) {
    akvf::DeformConfig config;
    config.preconditioner = method;
    config.optimizer.max_iterations = 10;
    config.optimizer.gradient_tolerance = kGradientFloor;
    return akvf::run_deformation(m, "t", c, config).result;
  };
  for (const char* method : {"akvf", "newton"}) {
    CAPTURE(method);
    const akvf::OptimizerResult reference = run(mesh, constraints, method);
    for (const Transform& t : transforms(mesh.num_vertices(), mesh.num_tets())) {
      CAPTURE(t.name);
      akvf::TetMesh changed;
      changed.V = moved(mesh.V, t);
      changed.T = renumbered(mesh.T, t);
      akvf::PositionConstraints moved_constraints;
      moved_constraints.targets = (constraints.targets * t.linear.transpose()).rowwise() + t.shift;
      for (int v : constraints.vertices) moved_constraints.vertices.push_back(t.vertex_to.empty() ? v : t.vertex_to[v]);
      check_same_trace(reference, run(changed, moved_constraints, method));
    }
  }
}

TEST_CASE("uniform scales from 1e-100 to 1e+100 give the energies and iterations of scale 1, beyond, a clear error") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(8, 8);
  akvf::ParamConfig config;
  const akvf::ParamSetup reference_setup = akvf::prepare_parameterization(mesh, "m", config);
  const akvf::OptimizerResult reference = akvf::run_parameterization(reference_setup, config).result;
  REQUIRE(reference.status == akvf::TerminationStatus::kConverged);
  for (double scale : {1e-100, 1e-30, 3e-7, 1e+12, 1e+80, 1e+100}) {
    CAPTURE(scale);
    akvf::TriMesh scaled = mesh;
    scaled.V *= scale;
    const akvf::ParamSetup setup = akvf::prepare_parameterization(scaled, "m", config);
    const akvf::OptimizerResult result = akvf::run_parameterization(setup, config).result;
    check_same_trace(reference, result);
    // The UVs are at the input's scale: the reference's, times the scale.
    const Eigen::MatrixXd UV = akvf::output_uv(setup, result.x) / scale;
    const Eigen::MatrixXd reference_uv = akvf::output_uv(reference_setup, reference.x);
    CHECK((UV - reference_uv).norm() <= 1e-12 * reference_uv.norm());
  }
  akvf::TriMesh tiny = mesh;
  tiny.V *= 1e-320;
  CHECK(akvf::test::error_message([&] {
          akvf::prepare_parameterization(tiny, "tiny.obj", config);
        }).find("tiny.obj: coordinates too small to normalize: the mesh's extent ") == 0);
}
