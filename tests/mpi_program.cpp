// A program that runs MPI itself and uses akvf's multigrid path: akvf must
// leave MPI to it (no second MPI_Init, no MPI_Finalize behind its back), and a
// run on the CHOLMOD path must not initialize MPI at all.
// Usage: mpi_program own|none
#include <mpi.h>

#include <akvf/akvf.h>

#include <cmath>
#include <cstdio>
#include <cstring>

namespace {

akvf::ParameterizeResult run(const char* linear_solver) {
  const int n = 30;
  Eigen::MatrixXd V(n * n, 3);
  Eigen::MatrixXi F(2 * (n - 1) * (n - 1), 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = i / (n - 1.0), y = j / (n - 1.0);
      V.row(i * n + j) << x, y, 0.3 * std::sin(3 * x) * std::cos(2 * y);
    }
  int f = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j;
      F.row(f++) << a, a + n, a + n + 1;
      F.row(f++) << a, a + n + 1, a + 1;
    }
  akvf::ParameterizeOptions options;
  options.linear_solver = linear_solver;
  options.max_iters = 20;
  return akvf::parameterize(V, F, options);
}

int initialized() {
  int flag = 0;
  MPI_Initialized(&flag);
  return flag;
}

}  // namespace

int main(int argc, char** argv) {
  const bool own = argc > 1 && std::strcmp(argv[1], "own") == 0;
  if (!own) {  // a program without MPI: the CHOLMOD path leaves it alone
    run("cholmod");
    if (initialized()) {
      std::printf("FAIL: a CHOLMOD run initialized MPI\n");
      return 1;
    }
    std::printf("a CHOLMOD run left MPI uninitialized\n");
    return 0;
  }
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  const akvf::ParameterizeResult r = run("amg");
  if (r.statistics.preconditioner.multigrid_setups == 0) {
    std::printf("FAIL: the multigrid path was not taken\n");
    return 1;
  }
  int finalized = 0;
  MPI_Finalized(&finalized);
  int size = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Barrier(MPI_COMM_WORLD);  // MPI is still the program's, and working
  if (finalized || size != 1) {
    std::printf("FAIL: MPI finalized %d, size %d after the run\n", finalized, size);
    return 1;
  }
  MPI_Finalize();  // the program's own, once
  std::printf("the program's MPI was used by the multigrid path and left to it (%d multigrid setups)\n",
              r.statistics.preconditioner.multigrid_setups);
  return 0;
}
