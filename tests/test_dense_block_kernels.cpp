// dense_block_kernels and supernodal_block_solve: the loops for small
// supernode blocks against the BLAS calls they replace, which one each size
// gets, and the triangular solves on one block against Eigen's.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <random>

#include "solvers/dense_block_kernels.h"
#include "solvers/supernodal_block_solve.h"

namespace {

Eigen::MatrixXd random_matrix(int rows, int columns, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> entry(-1, 1);
  return Eigen::MatrixXd::NullaryExpr(rows, columns, [&](Eigen::Index, Eigen::Index) { return entry(rng); });
}

// A supernode's block: a positive definite diagonal block over `rows -
// columns` more rows.
Eigen::MatrixXd supernode_block(int rows, int columns, unsigned seed) {
  const Eigen::MatrixXd G = random_matrix(rows, columns, seed);
  Eigen::MatrixXd block = G;
  block.topRows(columns) =
      G.topRows(columns).transpose() * G.topRows(columns) + columns * Eigen::MatrixXd::Identity(columns, columns);
  return block;
}

// The lower part of the rows x columns update, as computed (the rest of C
// is not defined by the operation).
Eigen::MatrixXd lower_part(const Eigen::MatrixXd& C) {
  Eigen::MatrixXd lower = C;
  for (Eigen::Index j = 0; j < C.cols(); ++j) lower.col(j).head(j).setZero();
  return lower;
}

struct Shape {
  int rows, columns, k;
};

}  // namespace

TEST_CASE("block updates: loops and BLAS compute L L(0:columns, :)^T's lower part, small and large") {
  // Every remainder of the loops' tiles (columns mod 4, rows mod 8 and 4),
  // and a block large enough for BLAS.
  for (const Shape shape :
       {Shape{1, 1, 1}, Shape{3, 3, 2}, Shape{7, 2, 5}, Shape{12, 4, 9}, Shape{13, 5, 7}, Shape{19, 6, 4},
        Shape{23, 7, 11}, Shape{40, 20, 13}, Shape{90, 30, 33}, Shape{300, 100, 60}}) {
    CAPTURE(shape.rows);
    CAPTURE(shape.columns);
    CAPTURE(shape.k);
    const int ld = shape.rows + 3;  // a descendant's block has more rows above
    const Eigen::MatrixXd L = random_matrix(ld, shape.k, 11);
    const double* first = L.data() + 3;
    Eigen::MatrixXd by_loops = Eigen::MatrixXd::Constant(shape.rows, shape.columns, 9.0);
    Eigen::MatrixXd by_blas = by_loops, dispatched = by_loops;
    akvf::loop_update(shape.rows, shape.columns, shape.k, first, ld, by_loops.data());
    akvf::blas_update(shape.rows, shape.columns, shape.k, first, ld, by_blas.data());
    akvf::block_update(shape.rows, shape.columns, shape.k, first, ld, dispatched.data());
    const Eigen::MatrixXd rows = L.middleRows(3, shape.rows);
    const Eigen::MatrixXd expected = lower_part(rows * rows.topRows(shape.columns).transpose());
    CHECK((lower_part(by_loops) - expected).cwiseAbs().maxCoeff() <= 1e-13 * shape.k);
    CHECK((lower_part(by_blas) - expected).cwiseAbs().maxCoeff() <= 1e-13 * shape.k);
    const bool small = akvf::update_flops(shape.rows, shape.columns, shape.k) < akvf::kLoopUpdateFlops;
    CHECK(lower_part(dispatched) == lower_part(small ? by_loops : by_blas));
  }
}

TEST_CASE("block Cholesky: loops and BLAS factor the diagonal block and solve the rows below") {
  for (const Shape shape : {Shape{1, 1, 0}, Shape{5, 5, 0}, Shape{9, 4, 0}, Shape{13, 7, 0}, Shape{22, 11, 0},
                            Shape{30, 12, 0}, Shape{120, 40, 0}, Shape{300, 150, 0}}) {
    CAPTURE(shape.rows);
    CAPTURE(shape.columns);
    const Eigen::MatrixXd block = supernode_block(shape.rows, shape.columns, 5);
    Eigen::MatrixXd by_loops = block, by_blas = block, dispatched = block;
    CHECK(akvf::loop_cholesky(shape.rows, shape.columns, by_loops.data()) == -1);
    CHECK(akvf::blas_cholesky(shape.rows, shape.columns, by_blas.data()) == -1);
    CHECK(akvf::block_cholesky(shape.rows, shape.columns, dispatched.data()) == -1);
    const Eigen::MatrixXd A11 = block.topRows(shape.columns);
    const Eigen::MatrixXd A21 = block.bottomRows(shape.rows - shape.columns);
    for (const Eigen::MatrixXd* result : {&by_loops, &by_blas}) {
      const Eigen::MatrixXd L11 = result->topRows(shape.columns).triangularView<Eigen::Lower>();
      const Eigen::MatrixXd L21 = result->bottomRows(shape.rows - shape.columns);
      CHECK((L11 * L11.transpose() - A11).norm() <= 1e-13 * A11.norm());
      CHECK((L21 * L11.transpose() - A21).norm() <= 1e-13 * (A21.norm() + 1));
    }
    const bool small = akvf::cholesky_flops(shape.rows, shape.columns) < akvf::kLoopCholeskyFlops;
    CHECK(dispatched == (small ? by_loops : by_blas));
  }
}

TEST_CASE("block Cholesky: loops and BLAS name the same first non-positive pivot") {
  for (const int columns : {6, 60}) {
    CAPTURE(columns);
    Eigen::MatrixXd block = supernode_block(columns + 4, columns, 3);
    const int bad = columns / 2;
    block(bad, bad) = -1.0;  // column bad's pivot is then negative
    block.row(bad).head(bad).setZero();
    block.col(bad).segment(bad + 1, columns - bad - 1).setZero();
    Eigen::MatrixXd by_loops = block, by_blas = block;
    CHECK(akvf::loop_cholesky(columns + 4, columns, by_loops.data()) == bad);
    CHECK(akvf::blas_cholesky(columns + 4, columns, by_blas.data()) == bad);
  }
}

TEST_CASE("block solves: forward and backward on a supernode's block, every panel width") {
  for (const int columns : {1, 2, 3, 4, 5, 7, 8, 9, 13}) {
    for (const int below : {0, 1, 3, 4, 11}) {
      CAPTURE(columns);
      CAPTURE(below);
      const int rows = columns + below;
      Eigen::MatrixXd block = supernode_block(rows, columns, 17);
      REQUIRE(akvf::loop_cholesky(rows, columns, block.data()) == -1);
      const Eigen::MatrixXd L11 = block.topRows(columns).triangularView<Eigen::Lower>();
      const Eigen::MatrixXd L21 = block.bottomRows(below);
      const Eigen::VectorXd y = random_matrix(columns, 1, 23), known = random_matrix(below, 1, 29);

      Eigen::VectorXd w = Eigen::VectorXd::Zero(rows);
      w.head(columns) = y;
      akvf::forward_block(rows, columns, block.data(), w.data());
      const Eigen::VectorXd x = L11.triangularView<Eigen::Lower>().solve(y);
      CHECK((w.head(columns) - x).cwiseAbs().maxCoeff() <= 1e-12);
      if (below > 0) CHECK((w.tail(below) + L21 * x).cwiseAbs().maxCoeff() <= 1e-12);

      w.head(columns) = y;
      w.tail(below) = known;
      akvf::backward_block(rows, columns, block.data(), w.data());
      const Eigen::VectorXd expected =
          L11.transpose().triangularView<Eigen::Upper>().solve(y - L21.transpose() * known);
      CHECK((w.head(columns) - expected).cwiseAbs().maxCoeff() <= 1e-12);
      CHECK(w.tail(below) == known);
    }
  }
}
