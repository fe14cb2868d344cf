// SparseCholesky: ordering on the vertex graph, our (multi-threaded) supernodal
// solve and CHOLMOD's simplicial one against a direct dense reference.
#include <doctest/doctest.h>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>
#include <new>
#include <numeric>
#include <random>
#include <utility>

#include "akvf/error.h"
#include "framework/mesh/vertex_graph.h"
#include "framework/optimization/distortion_objective.h"
#include "framework/process/huge_page_array.h"
#include "preconditioners/killing_operator_2d.h"
#include "solvers/fill_reducing_ordering.h"
#include "solvers/sparse_cholesky.h"
#include "solvers/supernodal_tree.h"
#include "solvers/symbolic_analysis_cache.h"
#include "tests/test_support.h"

namespace {

// The shifted Killing operator of a jittered nx by nx grid (2 unknowns per vertex).
akvf::ElementMatrix2D shifted_killing(int nx) {
  const akvf::TriMesh grid = akvf::test::grid_disk(nx, nx, 0.2, 3);
  const Eigen::MatrixXd uv = akvf::test::jittered_uv(grid, 0.2, 7);
  const Eigen::VectorXd x = akvf::stack_uv(uv);
  Eigen::VectorXd area(grid.F.rows());
  for (int f = 0; f < grid.F.rows(); ++f) area[f] = 1.0 / static_cast<double>(grid.F.rows());
  akvf::ElementMatrix2D K(grid.F, static_cast<int>(grid.V.rows()));
  akvf::assemble_killing_operator_2d(grid.F, x, area, true, &K);
  K.add_to_diagonal(1e-3 * K.mean_diagonal());
  return K;
}

// |K x - b| / |b| for x solved by `cholesky` (factored for K), b fixed.
double solve_residual(akvf::SparseCholesky& cholesky, const akvf::ElementMatrix2D& K) {
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.upper().rows(), -1.0, 2.0).array().sin();
  Eigen::VectorXd x;
  cholesky.solve(b, &x);
  const Eigen::SparseMatrix<double> A = K.upper().selfadjointView<Eigen::Upper>();
  return (A * x - b).norm() / b.norm();
}

double relative_residual(const akvf::ElementMatrix2D& K, int block_size, bool cholmod_alone, bool* supernodal) {
  akvf::SparseCholesky cholesky;
  cholesky.use_cholmod_alone(cholmod_alone);
  cholesky.analyze(K.upper(), block_size);
  cholesky.factorize(K.upper());
  *supernodal = cholesky.supernodal();
  return solve_residual(cholesky, K);
}

}  // namespace

TEST_CASE("supernodal and simplicial factors solve to machine precision, ordered by vertex or by unknown") {
  for (const int nx : {6, 70}) {
    const akvf::ElementMatrix2D K = shifted_killing(nx);
    for (const int block_size : {1, 2})
      for (const bool cholmod_alone : {false, true}) {
        CAPTURE(nx);
        CAPTURE(block_size);
        CAPTURE(cholmod_alone);
        bool supernodal = false;
        CHECK(relative_residual(K, block_size, cholmod_alone, &supernodal) <= 1e-10);
        // Ours is always supernodal; CHOLMOD alone factors the small grid
        // simplicially (below its supernodal switch).
        CHECK(supernodal == (!cholmod_alone || nx == 70));
      }
  }
}

TEST_CASE("below CHOLMOD's supernodal switch the factor is supernodal, with CHOLMOD's merging limits") {
  // A 20 x 20 grid: CHOLMOD alone factors its K simplicially.
  const akvf::ElementMatrix2D K = shifted_killing(20);
  const auto factor_bytes = [&](bool cholmod_alone) {
    akvf::SparseCholesky cholesky;
    cholesky.use_cholmod_alone(cholmod_alone);
    cholesky.analyze(K.upper(), 2);
    REQUIRE(cholesky.supernodal() == !cholmod_alone);
    cholesky.factorize(K.upper());
    CHECK(solve_residual(cholesky, K) <= 1e-10);
    return cholesky.factor_bytes();
  };
  // The supernodes' dense blocks hold some explicit zeros, a few more than
  // the simplicial factor's entries.
  const double simplicial = factor_bytes(true), supernodal = factor_bytes(false);
  CHECK(supernodal >= simplicial);
  CHECK(supernodal < 1.5 * simplicial);
}

TEST_CASE("the blocks' factor predicts the supernodal switch exactly, and a wrong prediction changes no bit") {
  // 20 x 20: below CHOLMOD's switch (40 flops per entry); 70 x 70: above it.
  for (const int nx : {20, 70}) {
    CAPTURE(nx);
    const akvf::TriMesh grid = akvf::test::grid_disk(nx, nx, 0.2, 3);
    const akvf::ElementMatrix2D K = shifted_killing(nx);
    const akvf::BlockOrdering order =
        akvf::fill_reducing_ordering(akvf::upper_vertex_graph(grid.F, static_cast<int>(grid.V.rows())), 2);
    const double expected = akvf::expanded_flops_per_entry(order, 2);
    CHECK((expected < 40) == (nx == 20));
    akvf::BlockOrdering unknown = order, wrong = order;
    unknown.factor_nonzeros = unknown.factor_flops = 0;
    // As if every column of the blocks' factor held one block: about one
    // flop per entry, far below the switch.
    wrong.factor_flops = wrong.factor_nonzeros;
    CHECK(akvf::expanded_flops_per_entry(wrong, 2) < 2);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.upper().rows(), -1.0, 2.0).array().sin();
    std::vector<Eigen::VectorXd> solutions;
    std::vector<double> nonzeros, flops, bytes;
    for (const akvf::BlockOrdering* given :
         std::initializer_list<const akvf::BlockOrdering*>{&order, &unknown, &wrong}) {
      akvf::SparseCholesky cholesky;
      cholesky.analyze(K.upper(), 2, given);
      CHECK(cholesky.supernodal());
      nonzeros.push_back(cholesky.factor_nonzeros());
      flops.push_back(cholesky.factor_flops());
      bytes.push_back(cholesky.factor_bytes());
      cholesky.factorize(K.upper());
      solutions.emplace_back();
      cholesky.solve(b, &solutions.back());
    }
    // CHOLMOD's own counts of the expanded matrix.
    CHECK(expected == flops[0] / nonzeros[0]);
    for (std::size_t i = 1; i < solutions.size(); ++i) {
      CHECK(nonzeros[i] == nonzeros[0]);
      CHECK(flops[i] == flops[0]);
      CHECK(bytes[i] == bytes[0]);  // the same supernodes
      CHECK(solutions[i] == solutions[0]);
    }
  }
}

TEST_CASE("an indefinite matrix is refused by the simplicial (L D L^T) and the supernodal factorization alike") {
  for (const int nx : {6, 70})
    for (const bool cholmod_alone : {false, true}) {
      CAPTURE(nx);
      CAPTURE(cholmod_alone);
      // K + 1e-3 mean(diag K) I minus a little more than that shift: its lowest
      // eigenvalue (a rigid motion's) is about -1e-5 mean(diag K).
      akvf::ElementMatrix2D K = shifted_killing(nx);
      K.add_to_diagonal(-1.01e-3 * K.mean_diagonal() / 1.001);
      akvf::SparseCholesky cholesky;
      cholesky.use_cholmod_alone(cholmod_alone);
      cholesky.analyze(K.upper(), 2);
      CHECK_THROWS_AS(cholesky.factorize(K.upper()), akvf::NotPositiveDefinite);
      CHECK(cholesky.supernodal() == (!cholmod_alone || nx == 70));
      if (!cholmod_alone) {  // the two-core factorization leaves no factor to solve with
        Eigen::VectorXd x;
        CHECK_THROWS_AS(cholesky.solve(Eigen::VectorXd::Ones(K.upper().rows()), &x), akvf::NumericalError);
      }
      // A failed factorization stops both cores; the next one on the same
      // analysis runs in full.
      K.add_to_diagonal(1.01e-3 * K.mean_diagonal() / 1.001);
      cholesky.factorize(K.upper());
      CHECK(solve_residual(cholesky, K) <= 1e-9);
    }
}

TEST_CASE("a block size that does not divide the matrix is refused") {
  const akvf::ElementMatrix2D K = shifted_killing(4);
  akvf::SparseCholesky cholesky;
  CHECK(akvf::test::error_message([&] { cholesky.analyze(K.upper(), 3); }).find("block size") != std::string::npos);
}

namespace {

// x = A^-1 b by `cholesky` (analyzed), factored on `factor_threads` threads
// and solved on `solve_threads`.
Eigen::VectorXd factor_and_solve(akvf::SparseCholesky& cholesky, const akvf::ElementMatrix2D& K,
                                 const Eigen::VectorXd& b, int factor_threads, int solve_threads) {
  Eigen::VectorXd x;
  const auto on = [](int threads, const auto& work) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    tbb::task_arena arena(threads);
    arena.execute(work);
  };
  on(factor_threads, [&] { cholesky.factorize(K.upper()); });
  on(solve_threads, [&] { cholesky.solve(b, &x); });
  return x;
}

}  // namespace

TEST_CASE("the factor has the same bits on 1, 2, 3, 4 and 8 threads, 32- or 64-bit, and CHOLMOD's to rounding") {
  // 70 x 70: AMD's ordering; 160 x 160: METIS's, a tree with several
  // branches at the top and blocks large enough for BLAS
  // (dense_block_kernels.h).
  for (const int nx : {70, 160}) {
    CAPTURE(nx);
    const akvf::ElementMatrix2D K = shifted_killing(nx);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.upper().rows(), -1.0, 2.0).array().sin();
    akvf::SparseCholesky cholmod;
    cholmod.use_cholmod_factorization(true);
    cholmod.analyze(K.upper(), 2);
    cholmod.factorize(K.upper());
    Eigen::VectorXd by_cholmod;
    cholmod.solve(b, &by_cholmod);
    std::vector<Eigen::VectorXd> ours_solutions;
    for (const bool wide : {false, true}) {
      CAPTURE(wide);
      akvf::SparseCholesky ours;
      ours.use_64_bit_indices(wide);
      ours.analyze(K.upper(), 2);
      REQUIRE(ours.supernodal());
      CHECK(ours.ordering() == (nx == 70 ? "amd" : "metis"));
      // Most of the flops are off the tree's longest chain, so threads have
      // subtrees to share.
      CHECK(ours.factor_critical_path_share() < 0.5);
      // Factored on each thread count (more threads than cores still run as
      // separate threads), solved on two: a second factorization reuses the
      // first's lists and memory.
      for (const int threads : {1, 2, 3, 4, 8, 1}) {
        CAPTURE(threads);
        ours_solutions.push_back(factor_and_solve(ours, K, b, threads, 2));
      }
    }
    for (const Eigen::VectorXd& x : ours_solutions) CHECK(x == ours_solutions.front());
    // The small blocks' loops round differently from OpenBLAS's kernels
    // (the difference grows with K's condition number, some 1e3 here).
    CHECK((ours_solutions.front() - by_cholmod).norm() <= 1e-10 * by_cholmod.norm());
    CHECK((ours_solutions.front() - by_cholmod).norm() > 0);
  }
}

TEST_CASE(
    "the supernodal solve: the same bits for a given arena size (one as two), the same solution to rounding on any") {
  const akvf::ElementMatrix2D K = shifted_killing(160);
  akvf::SparseCholesky cholesky;
  cholesky.analyze(K.upper(), 2);
  REQUIRE(cholesky.supernodal());
  // With two threads most of the factor is in the concurrent groups.
  CHECK(cholesky.solve_top_share(2) < 0.3);
  CHECK(cholesky.solve_top_share(4) < 0.4);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.upper().rows(), -1.0, 2.0).array().cos();
  const Eigen::VectorXd one = factor_and_solve(cholesky, K, b, 1, 1);
  CHECK(factor_and_solve(cholesky, K, b, 2, 2) == one);
  for (const int threads : {3, 4, 8}) {
    CAPTURE(threads);
    const Eigen::VectorXd x = factor_and_solve(cholesky, K, b, threads, threads);
    CHECK(factor_and_solve(cholesky, K, b, 1, threads) == x);  // again, after another thread count's solve
    CHECK((x - one).norm() <= 1e-12 * one.norm());
  }
  const Eigen::SparseMatrix<double> A = K.upper().selfadjointView<Eigen::Upper>();
  CHECK((A * one - b).norm() <= 1e-10 * b.norm());
}

TEST_CASE("CHOLMOD's 64-bit interface gives the 32-bit interface's bits, analyzed or copied") {
  for (const int nx : {6, 70}) {  // simplicial and supernodal factors
    CAPTURE(nx);
    const akvf::ElementMatrix2D K = shifted_killing(nx);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.upper().rows(), -1.0, 2.0).array().sin();
    akvf::SparseCholesky narrow, wide, copied;
    wide.use_64_bit_indices(true);
    narrow.analyze(K.upper(), 2);
    wide.analyze(K.upper(), 2);
    copied.copy_analysis(wide);
    CHECK(narrow.index_bits() == 32);  // a small factor keeps 32-bit indices
    CHECK(wide.index_bits() == 64);
    CHECK(copied.index_bits() == 64);
    CHECK(wide.supernodal() == narrow.supernodal());
    CHECK(wide.factor_nonzeros() == narrow.factor_nonzeros());
    Eigen::VectorXd x_narrow, x_wide, x_copied;
    for (akvf::SparseCholesky* cholesky : {&narrow, &wide, &copied}) cholesky->factorize(K.upper());
    narrow.solve(b, &x_narrow);
    wide.solve(b, &x_wide);
    copied.solve(b, &x_copied);
    CHECK(x_wide == x_narrow);
    CHECK(x_copied == x_narrow);
    const Eigen::SparseMatrix<double> A = K.upper().selfadjointView<Eigen::Upper>();
    CHECK((A * x_wide - b).norm() <= 1e-10 * b.norm());
  }
}

// sparse_cholesky.cpp, use_metis: small meshes keep AMD's ordering; METIS's
// nested dissection, when tried, is kept only if it needs fewer flops, and
// solves the same system.
TEST_CASE("METIS's nested dissection, where it is tried, solves the same system as AMD's ordering") {
  const akvf::ElementMatrix2D K = shifted_killing(120);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.upper().rows(), -1.0, 2.0).array().sin();
  const Eigen::SparseMatrix<double> A = K.upper().selfadjointView<Eigen::Upper>();
  akvf::SparseCholesky amd, tried;
  tried.always_try_metis(true);
  amd.analyze(K.upper(), 2);
  tried.analyze(K.upper(), 2);
  CHECK(amd.ordering() == "amd");  // 120 x 120 vertices: below the size where METIS is tried
  // On a square grid nested dissection needs fewer flops already at this size.
  CHECK(tried.ordering() == "metis");
  CHECK(tried.factor_flops() < amd.factor_flops());
  akvf::SparseCholesky copied;
  copied.copy_analysis(tried);
  CHECK(copied.ordering() == tried.ordering());
  for (akvf::SparseCholesky* cholesky : {&amd, &tried}) {
    cholesky->factorize(K.upper());
    Eigen::VectorXd x;
    cholesky->solve(b, &x);
    CHECK((A * x - b).norm() <= 1e-10 * b.norm());
  }
}

TEST_CASE("on a large graph AMD's and METIS's orderings run at once and the same one is kept") {
  // 363 x 363 vertices: above the size where METIS starts beside AMD
  // (fill_reducing_ordering.cpp, start_metis_early); always_try_metis computes
  // the two one after the other and keeps the one with fewer flops, as the
  // size rule does here.
  const akvf::ElementMatrix2D K = shifted_killing(363);
  REQUIRE(K.upper().rows() / 2 >= (1 << 17));
  akvf::SparseCholesky at_once, in_turn;
  in_turn.always_try_metis(true);
  at_once.analyze(K.upper(), 2);
  in_turn.analyze(K.upper(), 2);
  CHECK(at_once.ordering() == "metis");
  CHECK(in_turn.ordering() == at_once.ordering());
  CHECK(at_once.factor_nonzeros() == in_turn.factor_nonzeros());
  CHECK(at_once.factor_flops() == in_turn.factor_flops());
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.upper().rows(), -1.0, 2.0).array().sin();
  Eigen::VectorXd x_at_once, x_in_turn;
  at_once.factorize(K.upper());
  at_once.solve(b, &x_at_once);
  in_turn.factorize(K.upper());
  in_turn.solve(b, &x_in_turn);
  CHECK((x_at_once - x_in_turn).cwiseAbs().maxCoeff() == 0.0);  // the same permutation: the same bits
}

TEST_CASE("a kept analysis is shared, and solving before a factorization is refused") {
  const akvf::ElementMatrix2D K = shifted_killing(20);
  akvf::SparseCholesky analyzed, copy;
  analyzed.analyze(K.upper(), 2);
  copy.copy_analysis(analyzed);
  Eigen::VectorXd x;
  CHECK(akvf::test::error_message([&] {
          copy.solve(Eigen::VectorXd::Ones(K.upper().rows()), &x);
        }).find("before factorize") != std::string::npos);
  copy.factorize(K.upper());
  // The source stays an unfactored analysis that can be copied again.
  akvf::SparseCholesky again;
  again.copy_analysis(analyzed);
  again.factorize(K.upper());
  Eigen::VectorXd x_copy, x_again;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.upper().rows(), 0.0, 1.0);
  copy.solve(b, &x_copy);
  again.solve(b, &x_again);
  CHECK(x_copy == x_again);
}

TEST_CASE(
    "a prepared analysis is the one analyze() computes, from the vertex graph's pattern, and counts as computed once") {
  const akvf::TriMesh grid = akvf::test::grid_disk(20, 20, 0.2, 3);
  const akvf::ElementMatrix2D K = shifted_killing(20);
  const akvf::UpperVertexGraph graph = akvf::upper_vertex_graph(grid.F, static_cast<int>(grid.V.rows()));
  const Eigen::SparseMatrix<double> pattern = akvf::block_upper_pattern<2>(graph);
  REQUIRE(pattern.nonZeros() == K.upper().nonZeros());
  CHECK(std::equal(pattern.outerIndexPtr(), pattern.outerIndexPtr() + pattern.outerSize() + 1,
                   K.upper().outerIndexPtr()));
  CHECK(std::equal(pattern.innerIndexPtr(), pattern.innerIndexPtr() + pattern.nonZeros(), K.upper().innerIndexPtr()));
  const akvf::BlockOrdering order = akvf::fill_reducing_ordering(graph, 2);
  akvf::SymbolicAnalysisCache cache;
  cache.prepare(pattern, 2, &order);
  cache.prepare(pattern, 2, &order);  // kept: not computed again
  akvf::SparseCholesky first, second, own;
  CHECK(cache.analyze(K.upper(), 2, &first, &order));  // the prepared one, taken: computed for this solve
  CHECK_FALSE(cache.analyze(K.upper(), 2, &second, &order));
  own.analyze(K.upper(), 2, &order);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.upper().rows(), 0.0, 1.0);
  Eigen::VectorXd x_first, x_second, x_own;
  for (auto [cholesky, x] : {std::pair{&first, &x_first}, {&second, &x_second}, {&own, &x_own}}) {
    cholesky->factorize(K.upper());
    cholesky->solve(b, x);
  }
  CHECK(x_first == x_own);
  CHECK(x_second == x_own);
}

namespace {

// split_subtrees's rule computed plainly: the frontier kept in the order its
// subtrees joined it, the first heaviest expanded, and each cut's groups
// filled by a stable sort of the frontier, heaviest first to the lightest.
std::vector<int> plain_split(const akvf::SupernodalTree& tree, const std::vector<double>& work, int groups) {
  const int n = static_cast<int>(tree.parent.size());
  std::vector<double> subtree = work;
  for (int node = 0; node < n; ++node)
    if (tree.parent[node] >= 0) subtree[tree.parent[node]] += subtree[node];
  const auto cut = [&](const std::vector<int>& frontier, std::vector<int>* group) {
    std::vector<int> order(frontier.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return subtree[frontier[a]] > subtree[frontier[b]]; });
    std::vector<double> load(groups, 0.0);
    group->assign(frontier.size(), 0);
    for (int i : order) {
      const auto g = std::min_element(load.begin(), load.end()) - load.begin();
      (*group)[i] = static_cast<int>(g);
      load[g] += subtree[frontier[i]];
    }
    return *std::max_element(load.begin(), load.end());
  };
  std::vector<int> frontier = tree.roots, best_frontier = frontier, group, best_group;
  double top = 0, best = cut(frontier, &best_group);
  for (int step = 0; step < 256 && !frontier.empty(); ++step) {
    const auto heaviest =
        std::max_element(frontier.begin(), frontier.end(), [&](int a, int b) { return subtree[a] < subtree[b]; });
    const int node = *heaviest;
    frontier.erase(heaviest);
    top += work[node];
    frontier.insert(frontier.end(), tree.children[node].begin(), tree.children[node].end());
    if (const double time = top + cut(frontier, &group); time < best) {
      best = time;
      best_frontier = frontier;
      best_group = group;
    }
  }
  std::vector<int> owner(n, akvf::kTop);
  for (std::size_t i = 0; i < best_frontier.size(); ++i) owner[best_frontier[i]] = best_group[i];
  for (int node = n - 1; node >= 0; --node)
    if (owner[node] == akvf::kTop && tree.parent[node] >= 0 && owner[tree.parent[node]] != akvf::kTop)
      owner[node] = owner[tree.parent[node]];
  return owner;
}

}  // namespace

TEST_CASE("the solve's split of the elimination tree follows its rule, ties included, on random forests") {
  std::mt19937 random(5);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + static_cast<int>(random() % 600);
    akvf::SupernodalTree tree;
    tree.parent.assign(n, -1);
    tree.children.resize(n);
    for (int node = 0; node < n; ++node) {  // a parent has a larger index; a few roots
      if (node + 1 < n && random() % 50 != 0) {
        tree.parent[node] = node + 1 + static_cast<int>(random() % std::min(n - node - 1, 20));
        tree.children[tree.parent[node]].push_back(node);
      } else {
        tree.roots.push_back(node);
      }
    }
    // Few distinct weights, so that many subtrees tie.
    std::vector<double> work(n);
    for (double& w : work) w = static_cast<double>(random() % 4);
    for (const int groups : {2, 3, 8})
      CHECK(akvf::split_subtrees(tree, work, groups) == plain_split(tree, work, groups));
  }
}

TEST_CASE("solve_positive_definite solves every column of a positive definite system and declines an indefinite one") {
  const akvf::ElementMatrix2D K = shifted_killing(40);
  const Eigen::SparseMatrix<double> A = K.upper().selfadjointView<Eigen::Upper>();
  Eigen::MatrixXd B(A.rows(), 2);
  B.col(0) = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0).array().sin();
  B.col(1) = Eigen::VectorXd::LinSpaced(A.rows(), 0.5, 3.0).array().cos();
  Eigen::MatrixXd X;
  REQUIRE(akvf::solve_positive_definite(A, B, &X));
  REQUIRE(X.cols() == 2);
  for (int c = 0; c < 2; ++c) CHECK((A * X.col(c) - B.col(c)).norm() <= 1e-10 * B.col(c).norm());

  akvf::ElementMatrix2D indefinite = shifted_killing(40);
  indefinite.add_to_diagonal(-1.01e-3 * indefinite.mean_diagonal() / 1.001);
  const Eigen::SparseMatrix<double> C = indefinite.upper().selfadjointView<Eigen::Upper>();
  CHECK_FALSE(akvf::solve_positive_definite(C, B, &X));
}

TEST_CASE("a factor rounded to single precision solves to its rounding until the next factorization restores it") {
  // 70 x 70: small blocks only; 160 x 160: some factored by BLAS. Several
  // threads, so that the rounding in place runs in parallel stretches.
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 4);
  for (const int nx : {70, 160}) {
    CAPTURE(nx);
    const akvf::ElementMatrix2D K = shifted_killing(nx);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.upper().rows(), -1.0, 2.0).array().sin();
    akvf::SparseCholesky cholesky;
    cholesky.analyze(K.upper(), 2);
    cholesky.factorize(K.upper());
    Eigen::VectorXd exact, rounded, rounded_twice, again;
    cholesky.solve(b, &exact);
    CHECK(!cholesky.factor_is_single());
    cholesky.round_factor_to_single();
    CHECK(cholesky.factor_is_single());
    cholesky.solve(b, &rounded);
    cholesky.round_factor_to_single();  // a second call changes nothing
    cholesky.solve(b, &rounded_twice);
    CHECK(rounded_twice == rounded);
    // L's entries carry a relative 6e-8, the solution that times at most
    // K's condition number (some 1e3 here); measured about 5e-8. (Its
    // residual |K x - b| / |b| is larger, about |K| |x| / |b| times that.)
    const double error = (rounded - exact).norm() / exact.norm();
    CHECK(error > 0);
    CHECK(error <= 1e-5);
    cholesky.factorize(K.upper());
    CHECK(!cholesky.factor_is_single());
    cholesky.solve(b, &again);
    CHECK(again == exact);
  }
}

TEST_CASE("the factor's storage is 2 MiB aligned, writable to its end, and an impossible size is refused") {
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{262144}, std::size_t{262145}}) {
    CAPTURE(n);
    const akvf::HugePageDoubles array = akvf::allocate_huge_page_doubles(n);
    REQUIRE(array != nullptr);
    CHECK(reinterpret_cast<std::uintptr_t>(array.get()) % (std::uintptr_t{1} << 21) == 0);
    for (std::size_t i = 0; i < n; ++i) array[i] = static_cast<double>(i);
    if (n > 0) CHECK(array[n - 1] == static_cast<double>(n - 1));
  }
  CHECK_THROWS_AS(akvf::allocate_huge_page_doubles(static_cast<std::size_t>(-1) / 4), std::bad_alloc);
}
