// The worked examples of docs/extending.md, compiled and run: a
// preconditioner and a line search of one's own, registered by name and
// used through the API like the built-in ones. (The energy example is
// examples/custom_energy, built against the installed package.)
#include <doctest/doctest.h>

#include <algorithm>

#include "akvf/akvf.h"
#include "preconditioners/factored_preconditioner.h"
#include "solvers/backtracking_line_search.h"
#include "tests/test_support.h"

namespace {

// The uniform graph Laplacian of the mesh's edges, per coordinate: constant,
// so it is assembled and factored once; its null space is the translations.
class GraphLaplacian final : public akvf::FactoredPreconditioner2D {
 public:
  explicit GraphLaplacian(const akvf::ParamObjective& objective) : akvf::FactoredPreconditioner2D(objective, {}) {}
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
                                   [](const akvf::ParamObjective& objective, const akvf::PreconditionerSettings&) {
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
