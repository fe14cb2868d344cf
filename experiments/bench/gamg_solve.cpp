#include "experiments/bench/gamg_solve.h"

#include <mpi.h>
#include <petscksp.h>

#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace akvf_bench {

namespace {

void check(PetscErrorCode code, const char* what) {
  if (code != 0)
    throw std::runtime_error(std::string("PETSc: ") + what + " failed (error " + std::to_string(code) + ")");
}

// PETSc once (it initializes MPI as a singleton unless hypre did first, and
// then finalizes it too); finalized at exit, before hypre's MPI_Finalize
// when hypre came first (atexit runs the later registration first).
void initialize_petsc() {
  static std::once_flag once;
  std::call_once(once, [] {
    check(PetscInitializeNoArguments(), "PetscInitialize");
    // Options for exploring the settings (AKVF_GAMG_OPTIONS="-pc_gamg_threshold 0.02 ...").
    if (const char* extra = std::getenv("AKVF_GAMG_OPTIONS"))
      check(PetscOptionsInsertString(nullptr, extra), "options");
    std::atexit([] {
      int finalized = 0;
      MPI_Finalized(&finalized);
      if (!finalized) PetscFinalize();
    });
  });
}

Vec make_vector(const Eigen::VectorXd& values) {
  Vec v = nullptr;
  check(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(values.size()), &v), "VecCreateSeq");
  PetscScalar* data = nullptr;
  check(VecGetArray(v, &data), "VecGetArray");
  for (Eigen::Index i = 0; i < values.size(); ++i) data[i] = values[i];
  check(VecRestoreArray(v, &data), "VecRestoreArray");
  return v;
}

void read_vector(Vec v, Eigen::VectorXd* out) {
  PetscInt n = 0;
  check(VecGetLocalSize(v, &n), "VecGetLocalSize");
  const PetscScalar* data = nullptr;
  check(VecGetArrayRead(v, &data), "VecGetArrayRead");
  out->resize(n);
  for (PetscInt i = 0; i < n; ++i) (*out)[i] = data[i];
  check(VecRestoreArrayRead(v, &data), "VecRestoreArrayRead");
}

}  // namespace

struct GamgSolve::Impl {
  Mat matrix = nullptr;
  KSP ksp = nullptr;
  void release() {
    if (ksp) KSPDestroy(&ksp);
    if (matrix) MatDestroy(&matrix);
  }
  ~Impl() { release(); }
};

GamgSolve::GamgSolve() : impl_(std::make_unique<Impl>()) { initialize_petsc(); }
GamgSolve::~GamgSolve() = default;

void GamgSolve::setup(const Eigen::SparseMatrix<double>& upper, const Eigen::VectorXd& x) {
  impl_->release();
  // The whole symmetric matrix in compressed rows (PETSc's AIJ), rows sorted.
  const Eigen::SparseMatrix<double, Eigen::RowMajor> full = upper.selfadjointView<Eigen::Upper>();
  const PetscInt n = static_cast<PetscInt>(full.rows());
  std::vector<PetscInt> start(full.outerIndexPtr(), full.outerIndexPtr() + n + 1);
  std::vector<PetscInt> columns(full.innerIndexPtr(), full.innerIndexPtr() + full.nonZeros());
  Mat& A = impl_->matrix;
  check(MatCreate(PETSC_COMM_SELF, &A), "MatCreate");
  check(MatSetSizes(A, n, n, n, n), "MatSetSizes");
  check(MatSetBlockSize(A, 2), "MatSetBlockSize");
  check(MatSetType(A, MATSEQAIJ), "MatSetType");
  check(MatSeqAIJSetPreallocationCSR(A, start.data(), columns.data(), full.valuePtr()), "preallocation");
  check(MatSetOption(A, MAT_SPD, PETSC_TRUE), "MAT_SPD");

  Vec coordinates = make_vector(x);
  check(VecSetBlockSize(coordinates, 2), "VecSetBlockSize");
  MatNullSpace rigid = nullptr;
  check(MatNullSpaceCreateRigidBody(coordinates, &rigid), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(A, rigid), "MatSetNearNullSpace");
  MatNullSpaceDestroy(&rigid);
  VecDestroy(&coordinates);

  KSP& ksp = impl_->ksp;
  check(KSPCreate(PETSC_COMM_SELF, &ksp), "KSPCreate");
  check(KSPSetOperators(ksp, A, A), "KSPSetOperators");
  check(KSPSetType(ksp, KSPCG), "KSPSetType");
  check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  PC pc = nullptr;
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PCSetType(pc, PCGAMG), "PCSetType");
  check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
  check(KSPSetUp(ksp), "KSPSetUp");
  check(PCSetUp(pc), "PCSetUp");
}

int GamgSolve::levels() const {
  PC pc = nullptr;
  check(KSPGetPC(impl_->ksp, &pc), "KSPGetPC");
  PetscInt levels = 0;
  check(PCMGGetLevels(pc, &levels), "PCMGGetLevels");
  return static_cast<int>(levels);
}

void GamgSolve::cycle(const Eigen::VectorXd& r, Eigen::VectorXd* z) {
  PC pc = nullptr;
  check(KSPGetPC(impl_->ksp, &pc), "KSPGetPC");
  Vec b = make_vector(r), y = nullptr;
  check(VecDuplicate(b, &y), "VecDuplicate");
  check(PCApply(pc, b, y), "PCApply");
  read_vector(y, z);
  VecDestroy(&b);
  VecDestroy(&y);
}

int GamgSolve::solve(const Eigen::VectorXd& g, double tolerance, Eigen::VectorXd* d) {
  check(KSPSetTolerances(impl_->ksp, tolerance, 0.0, PETSC_DEFAULT, 1000), "KSPSetTolerances");
  Vec b = make_vector(g), y = nullptr;
  check(VecDuplicate(b, &y), "VecDuplicate");
  check(KSPSolve(impl_->ksp, b, y), "KSPSolve");
  KSPConvergedReason reason;
  check(KSPGetConvergedReason(impl_->ksp, &reason), "KSPGetConvergedReason");
  if (reason < 0)
    throw std::runtime_error("PETSc: CG with GAMG did not converge (KSPConvergedReason " +
                             std::to_string(static_cast<int>(reason)) + ")");
  PetscInt iterations = 0;
  check(KSPGetIterationNumber(impl_->ksp, &iterations), "KSPGetIterationNumber");
  read_vector(y, d);
  VecDestroy(&b);
  VecDestroy(&y);
  return static_cast<int>(iterations);
}

}  // namespace akvf_bench
