// Unfolding a planar map by moving single vertices into their stars' kernels.
#include <doctest/doctest.h>

#include "akvf/mesh_io.h"
#include "framework/mesh/fold_repair.h"
#include "framework/mesh/initialization.h"
#include "framework/mesh/mesh_topology.h"
#include "tests/test_support.h"

namespace {

// Whether every triangle of vertex v is positive under UV.
bool star_is_positive(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, int v) {
  for (int f = 0; f < F.rows(); ++f)
    if ((F.row(f).array() == v).any() && akvf::count_inverted_triangles(F.row(f), UV) > 0) return false;
  return true;
}

}  // namespace

TEST_CASE("an interior vertex pushed across its link goes back into its star's kernel, and nothing else moves") {
  const akvf::TriMesh grid = akvf::test::grid_disk(5, 5);
  Eigen::MatrixXd UV = grid.V.leftCols(2);
  const int centre = 12;  // (2, 2) of the 5 x 5 grid
  UV.row(centre) << 0.5 + 0.4, 0.5 + 0.05;
  REQUIRE(akvf::count_inverted_triangles(grid.F, UV) > 0);
  const Eigen::MatrixXd folded = UV;
  CHECK(akvf::unfold_by_star_kernels(grid.F, &UV) == std::vector<int>{centre});
  CHECK(akvf::count_inverted_triangles(grid.F, UV) == 0);
  for (int v = 0; v < UV.rows(); ++v)
    if (v != centre) CHECK(UV.row(v) == folded.row(v));
  // The kernel of a square grid's star is the square of its four edge neighbours' cells.
  CHECK(std::abs(UV(centre, 0) - 0.5) < 0.25);
  CHECK(std::abs(UV(centre, 1) - 0.5) < 0.25);
}

TEST_CASE("a boundary vertex folded over its neighbours is moved back, clipped to its star's box") {
  const akvf::TriMesh grid = akvf::test::grid_disk(4, 4);
  Eigen::MatrixXd UV = grid.V.leftCols(2);
  const int edge_vertex = 1;  // on the boundary y = 0
  UV.row(edge_vertex) << 1.0 / 3, 0.6;
  const int inverted = akvf::count_inverted_triangles(grid.F, UV);
  REQUIRE(inverted > 0);
  const std::vector<int> moved = akvf::unfold_by_star_kernels(grid.F, &UV);
  CHECK(moved.size() == 1);
  CHECK(akvf::count_inverted_triangles(grid.F, UV) == 0);
  for (int v : moved) {
    CHECK(star_is_positive(grid.F, UV, v));
    CHECK(UV.row(v).minCoeff() >= 0);
    CHECK(UV.row(v).maxCoeff() <= 1);
  }
}

TEST_CASE("a mirrored map stays folded where no single vertex can unfold it, and the repair stops") {
  const akvf::TriMesh grid = akvf::test::grid_disk(5, 5);
  Eigen::MatrixXd UV = grid.V.leftCols(2);
  UV.col(0) *= -1;  // every triangle inverted; an interior star's kernel is empty
  const std::vector<int> moved = akvf::unfold_by_star_kernels(grid.F, &UV);
  CHECK(akvf::count_inverted_triangles(grid.F, UV) > 0);
  for (int v : moved) CHECK(star_is_positive(grid.F, UV, v));
}

TEST_CASE("a flip-free map is left as it is") {
  const akvf::TriMesh grid = akvf::test::grid_disk(6, 4, 0.2);
  Eigen::MatrixXd UV = grid.V.leftCols(2);
  const Eigen::MatrixXd before = UV;
  CHECK(akvf::unfold_by_star_kernels(grid.F, &UV).empty());
  CHECK(UV == before);
}
