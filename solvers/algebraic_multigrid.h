#pragma once
// Algebraic multigrid for the sparse SPD systems of the preconditioners, the
// solve path that scales to millions of unknowns where a Cholesky factor's
// fill does not (docs/design.md, "Linear solvers"). One V-cycle of hypre's
// BoomerAMG (from Debian's libhypre-dev) on a hierarchy built once from a
// matrix; conjugate gradients around it live in factored_preconditioner.cpp,
// where the null space is projected and the hierarchy is reused across
// iterations.
//
// hypre is an MPI library: the first setup() initializes MPI (as a
// singleton, one process, no mpirun) unless the program already did, and
// finalizes it at exit. Built without hypre (not found at configure time, or AKVF_WITH_HYPRE=OFF),
// available() is false and require_available() and setup() throw
// OptionsError naming what to install.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

namespace akvf {

class AlgebraicMultigrid {
 public:
  AlgebraicMultigrid();
  ~AlgebraicMultigrid();
  AlgebraicMultigrid(const AlgebraicMultigrid&) = delete;
  AlgebraicMultigrid& operator=(const AlgebraicMultigrid&) = delete;

  // True if this build links hypre.
  static bool available();
  // OptionsError saying what to install unless available().
  static void require_available();

  // Builds the hierarchy of the SPD matrix whose upper triangle (column major)
  // is `upper`. The unknowns come in groups of block_size consecutive ones
  // (a vertex's coordinates): coarsened as block_size coupled functions, the
  // systems approach for elasticity-like operators such as K.
  void setup(const Eigen::SparseMatrix<double>& upper, int block_size);
  bool ready() const;
  // z = one V-cycle on A z = r from z = 0 (symmetric: forward then backward
  // Gauss-Seidel smoothing, so a valid preconditioner for CG).
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd* z) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace akvf
