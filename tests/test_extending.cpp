// The worked examples of docs/extending.md, compiled and run: a
// preconditioner and a line search of one's own, registered by name and
// used through the API like the built-in ones. (The energy example is
// examples/custom_energy, built against the installed package.)
#include <doctest/doctest.h>

#include <algorithm>

#include "akvf/akvf.h"
#include "akvf/backtracking_line_search.h"
#include "akvf/internal/preconditioner_settings.h"
#include "akvf/optimizer.h"
#include "framework/optimization/distortion_objective.h"
#include "preconditioners/factored_preconditioner.h"
#include "tests/test_support.h"

namespace {

// The uniform graph Laplacian of the mesh's edges, per coordinate: constant,
// so it is assembled and factored once; its null space is the translations.
class GraphLaplacian final : public akvf::FactoredPreconditioner2D {
 public:
  explicit GraphLaplacian(const akvf::MeshObjective2D& objective) : akvf::FactoredPreconditioner2D(objective, {}) {}
  std::string name() const override { return "graph-laplacian"; }

 private:
  void assemble(const akvf::OptimizationState&, Matrix* matrix) override {
    matrix->assemble([](int, Matrix::Local* local) {
      local->setZero();  // dofs: corner 0's (u, v), corner 1's, corner 2's; upper triangle read
      for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
          for (int c = 0; c < 2; ++c) {  // an interior edge is in two triangles: half each
            (*local)(2 * i + c, 2 * i + c) += 0.5;
            (*local)(2 * j + c, 2 * j + c) += 0.5;
            (*local)(2 * i + c, 2 * j + c) -= 0.5;
          }
    });
  }
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override {
    return akvf::motion_basis(2, akvf::MotionProjection::kTranslations, x);
  }
  bool is_constant() const override { return true; }
};

}  // namespace

TEST_CASE("a preconditioner and a line search of one's own run by name through the API") {
  akvf::register_preconditioner_2d("graph-laplacian", "uniform graph Laplacian per coordinate",
                                   [](const akvf::MeshObjective2D& objective, const akvf::PreconditionerSettings2D&) {
                                     return std::make_unique<GraphLaplacian>(objective);
                                   });
  akvf::register_line_search("backtracking-0.7", "Armijo backtracking shrinking by 0.7",
                             [](const akvf::LineSearchSettings& settings) {
                               akvf::LineSearchSettings mine = settings;
                               mine.rho = 0.7;
                               return std::make_unique<akvf::BacktrackingLineSearch>(mine);
                             });
  akvf::ParameterizeOptions options;
  options.preconditioner = "graph-laplacian";
  options.line_search = "backtracking-0.7";
  options.max_iters = 5000;
  int max_flips = 0;
  options.callbacks.push_back([&](const akvf::IterationSummary& row, const Eigen::VectorXd&) {
    max_flips = std::max(max_flips, row.flips);
    return akvf::CallbackAction::kContinue;
  });
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(9, 8);
  const akvf::ParameterizeResult r = akvf::parameterize(mesh.V, mesh.F, options);
  CHECK(r.status == akvf::TerminationStatus::kConverged);
  CHECK(max_flips == 0);
  CHECK(r.statistics.preconditioner.factorizations == 1);  // constant: factored once
  CHECK(r.energy() == doctest::Approx(akvf::parameterize(mesh.V, mesh.F).energy()).epsilon(1e-5));
  CHECK(options.is_valid());
}

namespace {

// An objective of one's own, written against the interface the
// preconditioners see (akvf/mesh_objective.h): the volume
// distortion of a tet mesh plus w sum |x_v - p_v|^2 over some vertices v with
// targets p_v, with that term's Hessian diagonal as the added one.
class PulledVertices final : public akvf::MeshObjective3D {
 public:
  PulledVertices(const akvf::DistortionObjective3D& distortion, std::vector<int> vertices,
                 std::vector<Eigen::Vector3d> targets, double w)
      : distortion_(distortion),
        pulled_(std::move(vertices)),
        targets_(std::move(targets)),
        w_(w),
        diagonal_(Eigen::VectorXd::Zero(num_variables())) {
    for (const int v : pulled_) diagonal_.segment<3>(3 * v).setConstant(2 * w_);
  }

  int num_variables() const override { return distortion_.num_variables(); }
  double value(const Eigen::VectorXd& x) const override { return distortion_.value(x) + pull(x, nullptr); }
  double value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const override {
    const double e = distortion_.value_and_gradient(x, gradient);
    return e + pull(x, gradient);
  }
  double max_feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const override {
    return distortion_.max_feasible_step(x, d);
  }
  int count_inverted(const Eigen::VectorXd& x) const override { return distortion_.count_inverted(x); }

  const Eigen::MatrixXi& elements() const override { return distortion_.elements(); }
  int num_vertices() const override { return distortion_.num_vertices(); }
  const Rest& rest() const override { return distortion_.rest(); }
  const Eigen::VectorXd& weights() const override { return distortion_.weights(); }
  const akvf::DistortionDensity<3>& density() const override { return distortion_.density(); }
  Matrix jacobian(const Eigen::VectorXd& x, int e) const override { return distortion_.jacobian(x, e); }
  const Eigen::VectorXd& added_hessian_diagonal() const override { return diagonal_; }

 private:
  // w sum |x_v - p_v|^2, adding its gradient when asked.
  double pull(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const {
    double sum = 0;
    for (std::size_t i = 0; i < pulled_.size(); ++i) {
      const Eigen::Vector3d r = x.segment<3>(3 * pulled_[i]) - targets_[i];
      sum += w_ * r.squaredNorm();
      if (gradient) gradient->segment<3>(3 * pulled_[i]) += 2 * w_ * r;
    }
    return sum;
  }

  const akvf::DistortionObjective3D& distortion_;
  std::vector<int> pulled_;
  std::vector<Eigen::Vector3d> targets_;
  double w_;
  Eigen::VectorXd diagonal_;
};

}  // namespace

TEST_CASE("every 3D preconditioner, by name, runs on an objective of one's own through its interface") {
  const akvf::TetMesh mesh = akvf::test::tet_grid(3);
  const akvf::DistortionObjective3D distortion(
      mesh.T, akvf::rest_tets(mesh), akvf::energies_3d().create("symmetric-dirichlet", {}), mesh.num_vertices());
  // The grid's eight corners: the bottom ones held, the top ones pulled up by 20 %.
  std::vector<int> corners;
  std::vector<Eigen::Vector3d> targets;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Eigen::Vector3d p = mesh.V.row(v).transpose();
    if ((p.array() == 0 || p.array() == 1).all()) {
      corners.push_back(v);
      targets.push_back(p + Eigen::Vector3d(0, 0, 0.2 * p.z()));
    }
  }
  REQUIRE(corners.size() == 8);
  const PulledVertices objective(distortion, corners, targets, 10.0);
  const Eigen::VectorXd rest = akvf::stack_rows(mesh.V);

  const akvf::BacktrackingLineSearch line_search(akvf::LineSearchSettings{});
  akvf::OptimizerOptions options;
  options.max_iterations = 300;
  options.gradient_tolerance = 1e-6;
  std::vector<double> minima;
  for (const auto& entry : akvf::preconditioners_3d().entries()) {
    const std::string& name = entry.first;  // not a structured binding: clang 14 cannot capture one
    CAPTURE(name);
    const auto preconditioner =
        akvf::preconditioners_3d().create(name, objective, akvf::default_preconditioner_settings_3d());
    const akvf::OptimizerResult r = akvf::minimize(objective, *preconditioner, line_search, rest, options);
    CHECK(objective.count_inverted(r.x) == 0);
    if (name == "identity") continue;  // gradient descent: slow, only safe
    CHECK(r.status == akvf::TerminationStatus::kConverged);
    minima.push_back(r.trace.back().energy);
    CHECK(minima.back() > 6 + 1e-3);  // the pull deforms the grid
  }
  REQUIRE(minima.size() >= 4);
  for (const double e : minima) CHECK(e == doctest::Approx(minima.front()).epsilon(1e-8));
}
