// A mesh's vertex graph ordered once (solvers/fill_reducing_ordering.h): the
// same analysis as SparseCholesky computes for a matrix on the mesh, and
// restricted to a subset of the vertices, an ordering of the subgraph.
#include <doctest/doctest.h>

#include <algorithm>

#include "framework/optimization/distortion_objective.h"
#include "preconditioners/killing_operator_2d.h"
#include "solvers/fill_reducing_ordering.h"
#include "solvers/sparse_cholesky.h"
#include "tests/test_support.h"

namespace {

// The shifted Killing operator of the grid (2 unknowns per vertex).
akvf::ElementMatrix2D shifted_killing(const akvf::TriMesh& grid) {
  const Eigen::VectorXd x = akvf::stack_uv(akvf::test::jittered_uv(grid, 0.2, 7));
  const Eigen::VectorXd area = Eigen::VectorXd::Constant(grid.F.rows(), 1.0 / static_cast<double>(grid.F.rows()));
  akvf::ElementMatrix2D K(grid.F, static_cast<int>(grid.V.rows()));
  akvf::assemble_killing_operator_2d(grid.F, x, area, true, &K);
  K.add_to_diagonal(1e-3 * K.mean_diagonal());
  return K;
}

Eigen::VectorXd solved(akvf::SparseCholesky& cholesky, const Eigen::SparseMatrix<double>& upper) {
  cholesky.factorize(upper);
  Eigen::VectorXd x;
  cholesky.solve(Eigen::VectorXd::LinSpaced(upper.rows(), -1.0, 2.0).array().sin(), &x);
  return x;
}

}  // namespace

TEST_CASE("the vertex graph's ordering, computed once, gives the analysis and the bits of SparseCholesky's own") {
  // 20 x 20: AMD; 363 x 363: METIS, started beside AMD
  // (fill_reducing_ordering.cpp, start_metis_early).
  for (const int nx : {20, 363}) {
    CAPTURE(nx);
    const akvf::TriMesh grid = akvf::test::grid_disk(nx, nx, 0.2, 3);
    const akvf::ElementMatrix2D K = shifted_killing(grid);
    const akvf::UpperVertexGraph graph = akvf::upper_vertex_graph(grid.F, static_cast<int>(grid.V.rows()));
    const akvf::BlockOrdering ordering = akvf::fill_reducing_ordering(graph, 2);
    CHECK(ordering.method == (nx == 20 ? "amd" : "metis"));
    CHECK(ordering.postordered);
    CHECK(akvf::postordered(graph, ordering).permutation == ordering.permutation);  // so it is taken as it is
    akvf::SparseCholesky own, given;
    own.analyze(K.upper(), 2);
    given.analyze(K.upper(), 2, &ordering);
    CHECK(given.ordering() == own.ordering());
    CHECK(given.factor_nonzeros() == own.factor_nonzeros());
    CHECK(given.factor_flops() == own.factor_flops());
    const Eigen::VectorXd x_own = solved(own, K.upper()), x_given = solved(given, K.upper());
    CHECK((x_own - x_given).cwiseAbs().maxCoeff() == 0.0);
  }
}

TEST_CASE("an ordering restricted to some vertices orders the system on them") {
  // The graph Laplacian of the interior vertices of a grid, plus the
  // identity (a Tutte-like system), ordered by the restriction of the whole
  // grid's ordering.
  const akvf::TriMesh grid = akvf::test::grid_disk(30, 30, 0.2, 3);
  const int n = static_cast<int>(grid.V.rows());
  const akvf::UpperVertexGraph graph = akvf::upper_vertex_graph(grid.F, n);
  const akvf::BlockOrdering ordering = akvf::fill_reducing_ordering(graph, 2, true);
  std::vector<int> boundary(n, 0);
  for (int v = 0; v < n; ++v) boundary[v] = (v % 30 == 0 || v % 30 == 29 || v < 30 || v >= n - 30);
  std::vector<int> interior, index(n, -1);
  for (int v = 0; v < n; ++v)
    if (!boundary[v]) {
      index[v] = static_cast<int>(interior.size());
      interior.push_back(v);
    }
  const int m = static_cast<int>(interior.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (int v = 0; v < n; ++v)
    for (int k = graph.column_start[v]; k < graph.column_start[v + 1]; ++k) {
      const int u = graph.row[k];
      if (index[u] < 0 || index[v] < 0) continue;
      if (u == v) {
        entries.emplace_back(index[v], index[v], 7.0);
      } else {
        entries.emplace_back(index[u], index[v], -1.0);
        entries.emplace_back(index[v], index[u], -1.0);
      }
    }
  Eigen::SparseMatrix<double> A(m, m);
  A.setFromTriplets(entries.begin(), entries.end());

  const std::vector<int> order = akvf::restricted_order(ordering, interior);
  REQUIRE(static_cast<int>(order.size()) == m);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < m; ++i) REQUIRE(sorted[i] == i);
  // In the whole ordering's sequence.
  std::vector<int> position(n);
  for (int a = 0; a < n; ++a) position[ordering.permutation[a]] = a;
  for (int i = 1; i < m; ++i) CHECK(position[interior[order[i - 1]]] < position[interior[order[i]]]);

  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(m, 2);
  Eigen::MatrixXd X;
  const akvf::BlockOrdering restricted{order, ordering.method};
  REQUIRE(akvf::solve_positive_definite(A, B, &X, &restricted));
  CHECK((A * X - B).norm() <= 1e-12 * B.norm());

  CHECK(akvf::test::error_message([&] {
          akvf::SparseCholesky cholesky;
          Eigen::SparseMatrix<double> upper = A.triangularView<Eigen::Upper>();
          upper.makeCompressed();
          cholesky.analyze(upper, 1, &ordering);  // an ordering of more vertices
        }).find("blocks") != std::string::npos);
}
