// ElementMatrix: the pattern built from the vertex graph and the ordered
// assembly on any number of threads against the plain reference, a triplet
// per local slot summed by Eigen in element order.
#include <doctest/doctest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "framework/optimization/element_matrix.h"
#include "tests/test_support.h"

namespace {

// A symmetric local matrix whose entries depend on the element and the slot.
template <int D, int N>
void local_matrix(int e, typename akvf::ElementMatrix<D, N>::Local* M) {
  constexpr int n = D * N;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i <= j; ++i) (*M)(i, j) = (*M)(j, i) = std::sin(0.37 * e + 1.3 * i + 0.71 * j) + (i == j ? 3 : 0);
}

template <int D, int N>
Eigen::SparseMatrix<double> triplet_reference(const Eigen::MatrixXi& elements, int num_vertices) {
  std::vector<Eigen::Triplet<double>> triplets;
  typename akvf::ElementMatrix<D, N>::Local M;
  for (int e = 0; e < elements.rows(); ++e) {
    local_matrix<D, N>(e, &M);
    for (int j = 0; j < D * N; ++j)
      for (int i = 0; i <= j; ++i) {
        const int a = D * elements(e, i / D) + i % D, b = D * elements(e, j / D) + j % D;
        triplets.emplace_back(std::min(a, b), std::max(a, b), M(i, j));
      }
  }
  Eigen::SparseMatrix<double> upper(D * num_vertices, D * num_vertices);
  upper.setFromTriplets(triplets.begin(), triplets.end());
  return upper;
}

// Assembled on 1, 2, 3 and 8 threads (each thread's part of the nonzeros,
// with the elements on the parts' borders visited by each of their parts),
// one local matrix at a time and in batches.
template <int D, int N>
void check_against_reference(const Eigen::MatrixXi& elements, int num_vertices) {
  akvf::ElementMatrix<D, N> matrix(elements, num_vertices);
  const Eigen::SparseMatrix<double> reference = triplet_reference<D, N>(elements, num_vertices);
  for (const int threads : {1, 2, 3, 8}) {
    CAPTURE(threads);
    for (const bool batches : {false, true}) {
      CAPTURE(batches);
      bool batches_valid = true;
      tbb::task_arena(threads).execute([&] {
        using Local = typename akvf::ElementMatrix<D, N>::Local;
        if (!batches) {
          matrix.assemble([](int e, Local* M) { local_matrix<D, N>(e, M); });
          return;
        }
        matrix.assemble_batches([&](const int* batch, int count, Local* locals) {
          // 1 to kBatch elements, in increasing order.
          if (count < 1 || count > akvf::ElementMatrix<D, N>::kBatch) batches_valid = false;
          for (int i = 0; i < count; ++i) {
            if (batch[i] < 0 || batch[i] >= elements.rows() || (i > 0 && batch[i] <= batch[i - 1]))
              batches_valid = false;
            local_matrix<D, N>(batch[i], &locals[i]);
          }
        });
      });
      CHECK(batches_valid);
      const Eigen::SparseMatrix<double>& upper = matrix.upper();
      REQUIRE(upper.isCompressed());
      REQUIRE(upper.nonZeros() == reference.nonZeros());
      const auto same = [](const auto* a, const auto* b, Eigen::Index n) { return std::equal(a, a + n, b); };
      CHECK(same(upper.outerIndexPtr(), reference.outerIndexPtr(), upper.outerSize() + 1));
      CHECK(same(upper.innerIndexPtr(), reference.innerIndexPtr(), upper.nonZeros()));
      // The same sums in the same order (increasing element): the same bits.
      CHECK(same(upper.valuePtr(), reference.valuePtr(), upper.nonZeros()));
    }
  }
}

}  // namespace

TEST_CASE("element matrices: the pattern and the sums are those of one triplet per local slot, bit for bit") {
  SUBCASE("triangles") {
    const akvf::TriMesh grid = akvf::test::grid_disk(140, 130, 0.2, 3);
    check_against_reference<2, 3>(grid.F, static_cast<int>(grid.V.rows()));
  }
  SUBCASE("triangles in shuffled order") {
    akvf::TriMesh grid = akvf::test::grid_disk(140, 130, 0.2, 3);
    std::vector<int> order(grid.F.rows());
    for (int f = 0; f < grid.F.rows(); ++f) order[f] = f;
    std::shuffle(order.begin(), order.end(), std::mt19937(11));
    Eigen::MatrixXi shuffled(grid.F.rows(), 3);
    for (int f = 0; f < grid.F.rows(); ++f) shuffled.row(f) = grid.F.row(order[f]);
    check_against_reference<2, 3>(shuffled, static_cast<int>(grid.V.rows()));
  }
  SUBCASE("vertices numbered at random (most elements in several threads' parts)") {
    akvf::TriMesh grid = akvf::test::grid_disk(60, 50, 0.2, 3);
    std::vector<int> number(grid.V.rows());
    for (int v = 0; v < grid.V.rows(); ++v) number[v] = v;
    std::shuffle(number.begin(), number.end(), std::mt19937(5));
    for (int f = 0; f < grid.F.rows(); ++f)
      for (int k = 0; k < 3; ++k) grid.F(f, k) = number[grid.F(f, k)];
    check_against_reference<2, 3>(grid.F, static_cast<int>(grid.V.rows()));
  }
  SUBCASE("tetrahedra") {
    const akvf::TetMesh cube = akvf::test::tet_grid(6);
    check_against_reference<3, 4>(cube.T, cube.num_vertices());
  }
  SUBCASE("elements listed in any vertex order") {
    akvf::TriMesh grid = akvf::test::grid_disk(9, 7, 0.2, 3);
    for (int f = 0; f < grid.F.rows(); f += 2) std::swap(grid.F(f, 0), grid.F(f, 2));  // clockwise ones too
    check_against_reference<2, 3>(grid.F, static_cast<int>(grid.V.rows()));
  }
}

// akvf-newton's switch: Newton's matrix takes AKVF's storage instead of a
// copy (taking_storage_of), and moving a matrix moves its storage (Eigen
// 3.4's SparseMatrix would copy it).
TEST_CASE("element matrices: a matrix on another's storage and a moved matrix keep the pattern and the bits") {
  const akvf::TriMesh grid = akvf::test::grid_disk(9, 7, 0.2, 3);
  const int num_vertices = static_cast<int>(grid.V.rows());
  const auto fill = [](int e, akvf::ElementMatrix2D::Local* M) { local_matrix<2, 3>(e, M); };
  akvf::ElementMatrix2D donor(grid.F, num_vertices);
  donor.assemble(fill);
  const Eigen::SparseMatrix<double> reference = donor.upper();
  const double* storage = donor.upper().valuePtr();

  akvf::ElementMatrix2D taken = akvf::ElementMatrix2D::taking_storage_of(&donor);
  CHECK(taken.upper().valuePtr() == storage);  // no new allocation
  CHECK(donor.upper().nonZeros() == 0);        // the donor keeps no values
  CHECK(taken.same_pattern(donor));            // but still names the pattern
  CHECK(taken.upper().nonZeros() == reference.nonZeros());
  CHECK(taken.upper().norm() == 0);  // values zeroed
  taken.assemble(fill);
  CHECK((taken.upper() - reference).norm() == 0);

  akvf::ElementMatrix2D moved(std::move(taken));
  CHECK(moved.upper().valuePtr() == storage);
  CHECK((moved.upper() - reference).norm() == 0);
  const akvf::ElementMatrix2D copy = akvf::ElementMatrix2D::with_pattern_of(moved);
  CHECK(copy.upper().valuePtr() != storage);
  CHECK(copy.same_pattern(moved));
  CHECK(copy.upper().norm() == 0);
}
