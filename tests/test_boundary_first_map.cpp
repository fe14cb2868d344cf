// The boundary-first map (framework/optimization/boundary_first_map.h) and
// init taking it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "akvf/internal/demo_mesh.h"
#include "akvf/internal/parameterization.h"
#include "akvf/parameterize.h"
#include "energies/symmetric_dirichlet.h"
#include "framework/mesh/mesh_validation.h"
#include "framework/mesh/plane_geometry.h"
#include "framework/optimization/boundary_first_map.h"
#include "framework/optimization/conformal_map.h"
#include "framework/optimization/uniform_scale.h"
#include "tests/test_support.h"

namespace {

struct Flattened {
  double energy;                   // symmetric Dirichlet at the best uniform scale
  double least_ratio, most_ratio;  // boundary edges, map length over rest length, at that scale
};

Flattened flattened(const akvf::TriMesh& mesh, const std::vector<int>& loop, const Eigen::MatrixXd& UV) {
  REQUIRE(UV.rows() == mesh.num_vertices());
  CHECK(akvf::count_inverted_triangles(mesh.F, UV) == 0);
  const akvf::DistortionObjective2D objective(mesh.F, akvf::rest_triangles(mesh),
                                              std::make_shared<akvf::SymmetricDirichlet2D>(), mesh.num_vertices());
  const Eigen::VectorXd x = akvf::stack_uv(UV);
  const double scale = akvf::best_uniform_scale(objective, x);
  Flattened result{objective.value(scale * x), INFINITY, 0};
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const int a = loop[i], b = loop[(i + 1) % loop.size()];
    const double ratio = scale * (UV.row(b) - UV.row(a)).norm() / (mesh.V.row(b) - mesh.V.row(a)).norm();
    result.least_ratio = std::min(result.least_ratio, ratio);
    result.most_ratio = std::max(result.most_ratio, ratio);
  }
  return result;
}

}  // namespace

TEST_CASE("the boundary-first map of a developable disk is an isometry, whichever way the loop runs") {
  const auto disk = akvf::prepare_disk_mesh(akvf::bent_bar(31, 6), "bar");
  std::vector<int> loop = disk.boundary_loops[0];
  for (const bool reversed : {false, true}) {
    CAPTURE(reversed);
    if (reversed) std::reverse(loop.begin(), loop.end());
    const Flattened map = flattened(disk.mesh, loop, akvf::boundary_first_map(disk.mesh, loop));
    CHECK(map.energy == doctest::Approx(4).epsilon(1e-9));
    CHECK(map.least_ratio == doctest::Approx(1).epsilon(1e-9));
    CHECK(map.most_ratio == doctest::Approx(1).epsilon(1e-9));
  }
}

TEST_CASE("on a curved disk the boundary-first map keeps the boundary's lengths, the least-squares map does not") {
  // The bumps' curvature changes the interior's scale (the Yamabe equation);
  // the boundary keeps its lengths up to the closing of the curve.
  const auto disk = akvf::prepare_disk_mesh(akvf::test::bumpy_disk(21, 17), "bumpy");
  const std::vector<int>& loop = disk.boundary_loops[0];
  const Flattened first = flattened(disk.mesh, loop, akvf::boundary_first_map(disk.mesh, loop));
  const Flattened least_squares =
      flattened(disk.mesh, loop, akvf::conformal_map(disk.mesh, akvf::rest_triangles(disk.mesh), loop));
  CHECK(first.energy > 4.01);
  CHECK(first.most_ratio / first.least_ratio < least_squares.most_ratio / least_squares.least_ratio);
  CHECK(first.most_ratio / first.least_ratio < 1.05);
}

TEST_CASE("init boundary-first starts there, and auto takes a conformal map on a bumpy disk") {
  akvf::ParameterizeOptions options;
  options.max_iters = 0;
  options.init = akvf::InitialMap::kBoundaryFirst;
  const akvf::TriMesh bumpy = akvf::test::bumpy_disk(15, 12);
  const akvf::ParameterizeResult result = akvf::parameterize(bumpy.V, bumpy.F, options);
  CHECK(result.initial_map == akvf::InitialMap::kBoundaryFirst);
  CHECK(result.warnings.empty());
  // auto takes the lowest of the three starts; on this disk none is Tutte's.
  options.init = akvf::InitialMap::kAuto;
  CHECK(akvf::parameterize(bumpy.V, bumpy.F, options).initial_map != akvf::InitialMap::kTutte);
}
