// A program that runs MPI itself and uses akvf's multigrid path: akvf must
// leave MPI to it (no second MPI_Init, no MPI_Finalize behind its back), and a
// run on the CHOLMOD path must not initialize MPI at all.
// Usage: mpi_program own|none
#include <mpi.h>

#include <akvf/akvf.h>

#include <cstdio>
#include <cstring>

#include "tests/test_support.h"

namespace {

akvf::ParameterizeResult run(akvf::LinearSolver linear_solver) {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(30, 30);
  akvf::ParameterizeOptions options;
  options.linear_solver = linear_solver;
  options.max_iters = 20;
  return akvf::parameterize(mesh.V, mesh.F, options);
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
    run(akvf::LinearSolver::kCholmod);
    if (initialized()) {
      std::printf("FAIL: a CHOLMOD run initialized MPI\n");
      return 1;
    }
    std::printf("a CHOLMOD run left MPI uninitialized\n");
    return 0;
  }
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  const akvf::ParameterizeResult r = run(akvf::LinearSolver::kAmg);
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
