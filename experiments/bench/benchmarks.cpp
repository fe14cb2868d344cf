// Google Benchmark micro-benchmarks of one AKVF iteration's parts on the
// paper's meshes (read from $AKVF_DATA_DIR or ../shared/meshes):
//   K assembly (Eq. 5), energy + gradient, numeric factorization, solve, one
//   whole iteration with a factorization (update, solve, flip-free line
//   search, gradient); a density's energy, gradient and projected Hessian,
//   hand-written against automatic differentiation; the 3D projected Hessian
//   in closed form against a 9x9 eigensolver; the 2D Hessian's closed-form
//   eigensystem; the algebraic multigrid
//   path (hierarchy setup, one V-cycle, a CG solve to 1e-2) on horse_b and
//   horse_b subdivided to 16x and 64x its faces (635 K and 2.5 M), with the
//   direct path's parts and a whole iteration at the same sizes, and
//   PETSc's GAMG on the same systems where PETSc is installed (gamg_solve.h).
// Run: ./build/akvf_benchmarks [--benchmark_filter=horse]
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <random>

#include "akvf/autodiff_density.h"
#include "akvf/backtracking_line_search.h"
#include "akvf/internal/parameterization.h"
#include "akvf/mesh_io.h"
#include "akvf/threads.h"
#include "energies/arap.h"
#include "energies/symmetric_dirichlet.h"
#include "experiments/bench/gamg_solve.h"
#include "framework/mesh/mesh_subdivision.h"
#include "framework/process/native_runtime.h"
#include "preconditioners/akvf_preconditioner_2d.h"
#include "solvers/algebraic_multigrid.h"
#include "solvers/dense_block_kernels.h"
#include "solvers/sparse_cholesky.h"

namespace {

std::string data_dir() {
  if (const char* dir = std::getenv("AKVF_DATA_DIR")) return dir;
  for (const char* candidate : {"../shared/meshes", "../../shared/meshes", "../../../shared/meshes"})
    if (std::filesystem::is_directory(candidate)) return candidate;
  return "";
}

// The problem after a few iterations, so K and the energy are in a typical
// state (not the Tutte start).
struct Fixture {
  akvf::ParamSetup setup;
  Eigen::VectorXd x;
};

// `mesh` after `subdivide` rounds of midpoint subdivision (faces x 4 each).
Fixture* fixture(const std::string& mesh, int subdivide = 0) {
  static std::map<std::pair<std::string, int>, std::unique_ptr<Fixture>> cache;
  auto& slot = cache[{mesh, subdivide}];
  if (!slot) {
    const std::string dir = data_dir();
    if (dir.empty()) return nullptr;
    const std::string path = dir + "/tri/" + mesh;
    akvf::ParamConfig config;
    config.optimizer.max_iterations = 5;
    config.global_injectivity = false;  // the paper's Algorithm 1, the problem the peers solve
    config.conformal = akvf::ConformalStart::kNever;  // from Tutte's map: the conformal one is hilbert_b's minimum
    config.boundary_first = akvf::ConformalStart::kNever;
    auto f = std::make_unique<Fixture>();
    f->setup = akvf::prepare_parameterization(akvf::subdivide_midpoint(akvf::read_triangle_mesh(path), subdivide), path,
                                              config);
    f->x = akvf::run_parameterization(f->setup, config).result.x;
    slot = std::move(f);
  }
  return slot.get();
}

#define REQUIRE_FIXTURE(state, mesh, ...)                       \
  Fixture* f = fixture(mesh, ##__VA_ARGS__);                    \
  if (!f) {                                                     \
    state.SkipWithError("meshes not found: set AKVF_DATA_DIR"); \
    return;                                                     \
  }

void BM_KillingAssembly(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::DistortionObjective2D& objective = *f->setup.objective;
  akvf::ElementMatrix2D K(objective.elements(), objective.num_vertices());
  for (auto _ : state) {
    akvf::assemble_killing_operator_2d(objective.elements(), f->x, objective.rest().area, true, &K);
    benchmark::DoNotOptimize(K.upper().valuePtr());
  }
}

// K's sparsity pattern and assembly plan, built once per run.
void BM_ElementPattern(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::DistortionObjective2D& objective = *f->setup.objective;
  for (auto _ : state) {
    akvf::ElementMatrix2D K(objective.elements(), objective.num_vertices());
    benchmark::DoNotOptimize(K.upper().innerIndexPtr());
  }
}

void BM_EnergyGradient(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  Eigen::VectorXd g;
  for (auto _ : state) benchmark::DoNotOptimize(f->setup.objective->value_and_gradient(f->x, &g));
}

void BM_Energy(benchmark::State& state, const std::string& mesh) {
  REQUIRE_FIXTURE(state, mesh);
  for (auto _ : state) benchmark::DoNotOptimize(f->setup.objective->value(f->x));
}

// K(x) + eps I of the fixture's iterate, as the AKVF preconditioner factors it.
akvf::ElementMatrix2D shifted_killing_operator(const Fixture& f) {
  const akvf::DistortionObjective2D& objective = *f.setup.objective;
  akvf::ElementMatrix2D K(objective.elements(), objective.num_vertices());
  akvf::assemble_killing_operator_2d(objective.elements(), f.x, objective.rest().area, true, &K);
  K.add_to_diagonal(1e-8 * K.mean_diagonal());
  return K;
}

// by_cholmod: CHOLMOD alone (its default analysis settings and its own
// one-core numeric factorization) instead of ours (every factor supernodal,
// small supernodes merged more, solvers/supernodal_factorization.h on
// `threads` threads, 0 = all cores).
void BM_NumericFactorization(benchmark::State& state, const std::string& mesh, int subdivide, bool by_cholmod,
                             int threads) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::ThreadLimit limit(threads);
  const akvf::ElementMatrix2D K = shifted_killing_operator(*f);
  akvf::SparseCholesky cholesky;
  cholesky.use_cholmod_alone(by_cholmod);
  cholesky.analyze(K.upper(), 2);
  for (auto _ : state) cholesky.factorize(K.upper());
  state.counters["nnz(L)"] = cholesky.factor_nonzeros();
  state.counters["MiB(L)"] = cholesky.factor_bytes() / (1 << 20);
  state.counters["flops"] = benchmark::Counter(cholesky.factor_flops(), benchmark::Counter::kIsIterationInvariantRate);
  if (!by_cholmod) state.counters["critical_path"] = cholesky.factor_critical_path_share();
}

void BM_SymbolicAnalysis(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::ElementMatrix2D K = shifted_killing_operator(*f);
  for (auto _ : state) {
    akvf::SparseCholesky cholesky;
    cholesky.analyze(K.upper(), 2);
  }
}

// single: with the factor rounded to single precision (the reuse CG's solves).
void BM_Solve(benchmark::State& state, const std::string& mesh, int subdivide, int threads, bool single) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::ThreadLimit limit(threads);
  const akvf::ElementMatrix2D K = shifted_killing_operator(*f);
  akvf::SparseCholesky cholesky;
  cholesky.analyze(K.upper(), 2);  // as the AKVF preconditioner does
  cholesky.factorize(K.upper());
  if (single) cholesky.round_factor_to_single();
  Eigen::VectorXd g, d;
  f->setup.objective->value_and_gradient(f->x, &g);
  for (auto _ : state) {
    cholesky.solve(g, &d);
    benchmark::DoNotOptimize(d.data());
  }
  state.counters["serial_share"] =
      cholesky.solve_top_share(threads > 0 ? threads : tbb::this_task_arena::max_concurrency());
}

void BM_SymmetricProduct(benchmark::State& state, const std::string& mesh) {
  REQUIRE_FIXTURE(state, mesh);
  const akvf::ElementMatrix2D K = shifted_killing_operator(*f);
  const Eigen::VectorXd x = f->x;
  Eigen::VectorXd y(x.size());
  for (auto _ : state) {
    y.noalias() = K.upper().selfadjointView<Eigen::Upper>() * x;
    benchmark::DoNotOptimize(y.data());
  }
}

void BM_WholeIteration(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::DistortionObjective2D& objective = *f->setup.objective;
  akvf::AkvfOptions2D options;
  options.factor.reuse_tolerance = 0;                         // Algorithm 1: a numeric factorization every iteration
  options.factor.vertex_ordering = f->setup.vertex_ordering;  // a run's ordering
  akvf::AkvfPreconditioner2D preconditioner(objective, options);
  const akvf::BacktrackingLineSearch line_search;  // default settings
  Eigen::VectorXd g, d;
  // The symbolic analysis (once per run) and the first factorization, outside the timing.
  const double start = objective.value_and_gradient(f->x, &g);
  preconditioner.update({f->x, g, start, 0});
  for (auto _ : state) {
    const double energy = objective.value_and_gradient(f->x, &g);
    preconditioner.update({f->x, g, energy, 1});
    preconditioner.apply(g, &d);
    d = -d;
    benchmark::DoNotOptimize(line_search.search(objective, f->x, energy, g, d));
  }
}

// A run's setup (validation, normalization, the initial map), with the
// Tutte map alone or with the conformal map tried beside it (init auto:
// akvf/parameterization.cpp, take_conformal_start).
void BM_Setup(benchmark::State& state, const std::string& mesh, akvf::ConformalStart conformal) {
  const std::string dir = data_dir();
  if (dir.empty()) {
    state.SkipWithError("meshes not found: set AKVF_DATA_DIR");
    return;
  }
  const akvf::TriMesh input = akvf::read_triangle_mesh(dir + "/tri/" + mesh);
  akvf::ParamConfig config;
  config.global_injectivity = false;
  config.conformal = conformal;
  config.boundary_first = conformal;
  for (auto _ : state) benchmark::DoNotOptimize(akvf::prepare_parameterization(input, mesh, config).x0.data());
}

// A run's first AKVF iteration: the preconditioner built (K's pattern), the
// symbolic analysis on the run's ordering, the first factorization (its
// memory touched for the first time) and solve.
void BM_FirstIteration(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::DistortionObjective2D& objective = *f->setup.objective;
  akvf::AkvfOptions2D options;
  options.factor.vertex_ordering = f->setup.vertex_ordering;
  Eigen::VectorXd g, d;
  const double energy = objective.value_and_gradient(f->x, &g);
  for (auto _ : state) {
    akvf::AkvfPreconditioner2D preconditioner(objective, options);
    preconditioner.update({f->x, g, energy, 0});
    preconditioner.apply(g, &d);
    benchmark::DoNotOptimize(d.data());
  }
}

// The multigrid path (solvers/algebraic_multigrid.h) on K(x) + eps I:
// building the hierarchy, one V-cycle, and AKVF's solve (CG preconditioned by
// V-cycles to 1e-2 relative, rigid motions projected) with a built hierarchy.
void BM_MultigridSetup(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::ElementMatrix2D K = shifted_killing_operator(*f);
  akvf::AlgebraicMultigrid multigrid;
  for (auto _ : state) multigrid.setup(K.upper(), 2);
  state.counters["unknowns"] = static_cast<double>(f->x.size());
}

void BM_MultigridCycle(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::ElementMatrix2D K = shifted_killing_operator(*f);
  akvf::AlgebraicMultigrid multigrid;
  multigrid.setup(K.upper(), 2);
  Eigen::VectorXd g, z;
  f->setup.objective->value_and_gradient(f->x, &g);
  for (auto _ : state) {
    multigrid.apply(g, &z);
    benchmark::DoNotOptimize(z.data());
  }
}

void BM_MultigridSolve(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  akvf::AkvfOptions2D options;
  options.factor.linear_solver = akvf::LinearSolver::kAmg;
  akvf::AkvfPreconditioner2D preconditioner(*f->setup.objective, options);
  Eigen::VectorXd g, d;
  const double energy = f->setup.objective->value_and_gradient(f->x, &g);
  preconditioner.update({f->x, g, energy, 1});
  preconditioner.apply(g, &d);  // builds the hierarchy; later solves reuse it on the same matrix
  const int setup_iterations = preconditioner.statistics().cg_iterations;
  for (auto _ : state) {
    preconditioner.apply(g, &d);
    benchmark::DoNotOptimize(d.data());
  }
  const akvf::PreconditionerStatistics s = preconditioner.statistics();
  state.counters["cg_iterations"] = static_cast<double>(s.cg_iterations - setup_iterations) / state.iterations();
  state.counters["setups"] = s.multigrid_setups;
}

#ifdef AKVF_BENCH_WITH_PETSC
// PETSc's GAMG on the same K(x) + eps I, with the rigid motions at x as its
// near-null space (gamg_solve.h): the hierarchy's setup, one V-cycle, and CG
// to 1e-2 relative, as the multigrid cases above.
void BM_GamgSetup(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::ElementMatrix2D K = shifted_killing_operator(*f);
  akvf_bench::GamgSolve gamg;
  for (auto _ : state) gamg.setup(K.upper(), f->x);
  state.counters["levels"] = gamg.levels();
}

void BM_GamgCycle(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::ElementMatrix2D K = shifted_killing_operator(*f);
  akvf_bench::GamgSolve gamg;
  gamg.setup(K.upper(), f->x);
  Eigen::VectorXd g, z;
  f->setup.objective->value_and_gradient(f->x, &g);
  for (auto _ : state) {
    gamg.cycle(g, &z);
    benchmark::DoNotOptimize(z.data());
  }
}

void BM_GamgSolve(benchmark::State& state, const std::string& mesh, int subdivide) {
  REQUIRE_FIXTURE(state, mesh, subdivide);
  const akvf::ElementMatrix2D K = shifted_killing_operator(*f);
  akvf_bench::GamgSolve gamg;
  gamg.setup(K.upper(), f->x);
  Eigen::VectorXd g, d;
  f->setup.objective->value_and_gradient(f->x, &g);
  int iterations = 0;
  for (auto _ : state) {
    iterations = gamg.solve(g, 1e-2, &d);
    benchmark::DoNotOptimize(d.data());
  }
  state.counters["cg_iterations"] = iterations;
}
#endif

// The symmetric Dirichlet density written once as a template, for automatic
// differentiation (akvf/autodiff_density.h).
struct TemplateSymmetricDirichlet {
  template <class T>
  T operator()(const Eigen::Matrix<T, 2, 2>& J) const {
    const T det = J.determinant();
    return J.squaredNorm() * (T(1.0) + T(1.0) / (det * det));
  }
};

// Energy, gradient and projected Hessian of every face of the mesh at a
// typical iterate, on one thread: the hand-written density against the same
// density differentiated automatically.
void BM_DensityDerivatives(benchmark::State& state, const std::string& mesh, bool automatic) {
  REQUIRE_FIXTURE(state, mesh);
  const akvf::DistortionObjective2D& objective = *f->setup.objective;
  const akvf::SymmetricDirichlet2D hand_written;
  const akvf::AutodiffDensity<2, TemplateSymmetricDirichlet> differentiated("sd", 4, {});
  const akvf::DistortionDensity2D& density =
      automatic ? static_cast<const akvf::DistortionDensity2D&>(differentiated) : hand_written;
  std::vector<Eigen::Matrix2d> jacobians;
  for (int e = 0; e < objective.elements().rows(); ++e) jacobians.push_back(objective.jacobian(f->x, e));
  for (auto _ : state) {
    double sum = 0;
    Eigen::Matrix2d gradient;
    for (const Eigen::Matrix2d& J : jacobians) {
      sum += density.value_and_gradient(J, &gradient);
      sum += density.projected_hessian(J)(0, 0) + gradient(0, 0);
    }
    benchmark::DoNotOptimize(sum);
  }
}

// The closed-form eigensystem of every face's symmetric Dirichlet Hessian
// at a typical iterate, on one thread (what projected Newton assembles from).
void BM_HessianEigensystem2D(benchmark::State& state, const std::string& mesh) {
  REQUIRE_FIXTURE(state, mesh);
  const akvf::DistortionObjective2D& objective = *f->setup.objective;
  const akvf::SymmetricDirichlet2D density;
  std::vector<Eigen::Matrix2d> jacobians;
  for (int e = 0; e < objective.elements().rows(); ++e) jacobians.push_back(objective.jacobian(f->x, e));
  for (auto _ : state) {
    double sum = 0;
    for (const Eigen::Matrix2d& J : jacobians) {
      const auto pairs = density.hessian_eigensystem(J);
      sum += pairs.values[3] + pairs.modes[3](1, 0);
    }
    benchmark::DoNotOptimize(sum);
  }
}

// The projected Hessian of 10 000 random tet Jacobians (singular values in
// [0.3, 3], det > 0), for a 3D energy: the closed-form eigensystem
// (singular_eigensystem_3d.h) against the generic 9x9 eigensolver it replaced.
template <class Density>
void BM_ProjectedHessian3D(benchmark::State& state, bool eigensolver) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coordinate(-1, 1), stretch(0.3, 3.0);
  std::vector<Eigen::Matrix3d> jacobians;
  while (jacobians.size() < 10000) {
    const Eigen::Matrix3d J = Eigen::Matrix3d::NullaryExpr([&](Eigen::Index, Eigen::Index) { return coordinate(rng); });
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Vector3d sigma(stretch(rng), stretch(rng), stretch(rng));
    if (J.determinant() > 0) jacobians.push_back(svd.matrixU() * sigma.asDiagonal() * svd.matrixV().transpose());
  }
  const Density density;
  for (auto _ : state) {
    double sum = 0;
    for (const Eigen::Matrix3d& J : jacobians)
      sum +=
          (eigensolver ? density.akvf::DistortionDensity3D::projected_hessian(J) : density.projected_hessian(J))(0, 0);
    benchmark::DoNotOptimize(sum);
  }
}

// One supernode's dense operations (solvers/dense_block_kernels.h) on a
// block of c columns and 2c rows: the update by an earlier supernode of c
// columns, and the block's Cholesky factorization; as loops or as BLAS
// calls, on one thread or on two at once (the factorization's two cores,
// which meet at OpenBLAS's buffer pool): where the loops stop being faster
// on two threads sets kLoopUpdateFlops and kLoopCholeskyFlops.
void BM_DenseBlock(benchmark::State& state, bool cholesky, bool loops) {
  const int c = static_cast<int>(state.range(0)), rows = 2 * c;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> entry(-1, 1);
  Eigen::MatrixXd L = Eigen::MatrixXd::NullaryExpr(rows, c, [&](Eigen::Index, Eigen::Index) { return entry(rng); });
  Eigen::MatrixXd spd = L.transpose() * L + c * Eigen::MatrixXd::Identity(c, c);
  Eigen::MatrixXd block(rows, c);
  block.topRows(c) = spd;
  block.bottomRows(c) = L.topRows(c);
  Eigen::MatrixXd work(rows, c);
  for (auto _ : state) {
    if (cholesky) {
      work = block;
      benchmark::DoNotOptimize(loops ? akvf::loop_cholesky(rows, c, work.data())
                                     : akvf::blas_cholesky(rows, c, work.data()));
    } else if (loops) {
      akvf::loop_update(rows, c, c, L.data(), rows, work.data());
    } else {
      akvf::blas_update(rows, c, c, L.data(), rows, work.data());
    }
    benchmark::ClobberMemory();
  }
  state.counters["flops"] = cholesky ? akvf::cholesky_flops(rows, c) : akvf::update_flops(rows, c, c);
}

void register_all() {
  for (const bool cholesky : {false, true})
    for (const bool loops : {true, false})
      for (const int threads : {1, 2})
        benchmark::RegisterBenchmark(
            ("DenseBlock/" + std::string(cholesky ? "cholesky/" : "update/") + (loops ? "loops" : "blas")).c_str(),
            BM_DenseBlock, cholesky, loops)
            ->DenseRange(4, 40, 4)
            ->Arg(48)
            ->Arg(64)
            ->Arg(96)
            ->Arg(128)
            ->Threads(threads)
            ->Unit(benchmark::kMicrosecond);
  for (const bool eigensolver : {false, true}) {
    const std::string how = eigensolver ? "eigensolver" : "closed-form";
    benchmark::RegisterBenchmark(("ProjectedHessian3D/symmetric-dirichlet/" + how).c_str(),
                                 BM_ProjectedHessian3D<akvf::SymmetricDirichlet3D>, eigensolver)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("ProjectedHessian3D/arap/" + how).c_str(), BM_ProjectedHessian3D<akvf::Arap3D>,
                                 eigensolver)
        ->Unit(benchmark::kMillisecond);
  }
  // The paper's meshes whose K CHOLMOD alone would factor simplicially (L D
  // L^T on one core, below its supernodal switch), which SparseCholesky
  // analyzes again as supernodal with more merging: the factorization,
  // solve and analysis there.
  for (const std::string mesh : {"camel_b.obj", "cow_b.obj", "tricera_b.obj"}) {
    benchmark::RegisterBenchmark(("NumericFactorization/" + mesh).c_str(), BM_NumericFactorization, mesh, 0, false, 0)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Solve/" + mesh).c_str(), BM_Solve, mesh, 0, 0, false)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("SymbolicAnalysis/" + mesh).c_str(), BM_SymbolicAnalysis, mesh, 0)
        ->Unit(benchmark::kMillisecond);
  }
  for (const std::string mesh : {"camelhead.off", "hilbert_b.obj", "horse_b.obj"}) {
    benchmark::RegisterBenchmark(("KillingAssembly/" + mesh).c_str(), BM_KillingAssembly, mesh, 0)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("ElementPattern/" + mesh).c_str(), BM_ElementPattern, mesh, 0)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("EnergyGradient/" + mesh).c_str(), BM_EnergyGradient, mesh, 0)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Energy/" + mesh).c_str(), BM_Energy, mesh)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("NumericFactorization/" + mesh).c_str(), BM_NumericFactorization, mesh, 0, false, 0)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("NumericFactorization/cholmod/" + mesh).c_str(), BM_NumericFactorization, mesh, 0,
                                 true, 0)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("SymbolicAnalysis/" + mesh).c_str(), BM_SymbolicAnalysis, mesh, 0)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Solve/" + mesh).c_str(), BM_Solve, mesh, 0, 0, false)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Solve/single/" + mesh).c_str(), BM_Solve, mesh, 0, 0, true)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("SymmetricProduct/" + mesh).c_str(), BM_SymmetricProduct, mesh)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("WholeIteration/" + mesh).c_str(), BM_WholeIteration, mesh, 0)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("FirstIteration/" + mesh).c_str(), BM_FirstIteration, mesh, 0)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Setup/tutte/" + mesh).c_str(), BM_Setup, mesh, akvf::ConformalStart::kNever)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Setup/auto/" + mesh).c_str(), BM_Setup, mesh, akvf::ConformalStart::kAuto)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("DensityDerivatives/hand-written/" + mesh).c_str(), BM_DensityDerivatives, mesh,
                                 false)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("DensityDerivatives/autodiff/" + mesh).c_str(), BM_DensityDerivatives, mesh, true)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("HessianEigensystem2D/" + mesh).c_str(), BM_HessianEigensystem2D, mesh)
        ->Unit(benchmark::kMillisecond);
  }
  // The direct path at the multigrid cases' sizes: its cost grows faster
  // than the mesh (fill), which is what the multigrid path is for. With the
  // per-element parts and a whole iteration at the same sizes, they say how
  // each part of an iteration grows from horse_b to 16 and 64 times its
  // faces.
  for (const int subdivide : {2, 3}) {
    const std::string name = "horse_b.obj/x" + std::to_string(1 << (2 * subdivide));
    benchmark::RegisterBenchmark(("KillingAssembly/" + name).c_str(), BM_KillingAssembly, "horse_b.obj", subdivide)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("EnergyGradient/" + name).c_str(), BM_EnergyGradient, "horse_b.obj", subdivide)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("WholeIteration/" + name).c_str(), BM_WholeIteration, "horse_b.obj", subdivide)
        ->Unit(benchmark::kMillisecond);
    for (const bool by_cholmod : {false, true})
      benchmark::RegisterBenchmark(("NumericFactorization/" + std::string(by_cholmod ? "cholmod/" : "") + name).c_str(),
                                   BM_NumericFactorization, "horse_b.obj", subdivide, by_cholmod, 0)
          ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Solve/" + name).c_str(), BM_Solve, "horse_b.obj", subdivide, 0, false)
        ->Unit(benchmark::kMillisecond);
    // Ours on one thread: what the threads buy (the same bits).
    benchmark::RegisterBenchmark(("NumericFactorization/" + name + "/threads:1").c_str(), BM_NumericFactorization,
                                 "horse_b.obj", subdivide, false, 1)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Solve/" + name + "/threads:1").c_str(), BM_Solve, "horse_b.obj", subdivide, 1, false)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("SymbolicAnalysis/" + name).c_str(), BM_SymbolicAnalysis, "horse_b.obj", subdivide)
        ->Unit(benchmark::kMillisecond);
  }
  if (!akvf::AlgebraicMultigrid::available()) return;
  for (const int subdivide : {0, 2, 3}) {
    const std::string name = "horse_b.obj/x" + std::to_string(1 << (2 * subdivide));
    benchmark::RegisterBenchmark(("MultigridSetup/" + name).c_str(), BM_MultigridSetup, "horse_b.obj", subdivide)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("MultigridCycle/" + name).c_str(), BM_MultigridCycle, "horse_b.obj", subdivide)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("MultigridSolve/" + name).c_str(), BM_MultigridSolve, "horse_b.obj", subdivide)
        ->Unit(benchmark::kMillisecond);
#ifdef AKVF_BENCH_WITH_PETSC
    benchmark::RegisterBenchmark(("GamgSetup/" + name).c_str(), BM_GamgSetup, "horse_b.obj", subdivide)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("GamgCycle/" + name).c_str(), BM_GamgCycle, "horse_b.obj", subdivide)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("GamgSolve/" + name).c_str(), BM_GamgSolve, "horse_b.obj", subdivide)
        ->Unit(benchmark::kMillisecond);
#endif
  }
}

}  // namespace

int main(int argc, char** argv) {
  akvf::configure_native_runtime(argv);
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
