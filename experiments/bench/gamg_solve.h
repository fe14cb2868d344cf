#pragma once
// PETSc's smoothed-aggregation multigrid (GAMG) around conjugate gradients,
// for the micro-benchmarks only: the measurement behind the choice of
// hypre's BoomerAMG for `--linear-solver amg` (issue 16 asks to choose
// between them by measurement). Not part of the
// library. Built when PETSc is found at configure time (Debian's
// petsc-dev, which scripts/setup.sh does not install: the measurement is
// the only user).
//
// The setup is given K's near-null space, the rigid motions at the current
// map x (PETSc's MatNullSpaceCreateRigidBody from the vertex positions:
// two translations and the rotation in 2D), which smoothed aggregation
// interpolates exactly on every level; BoomerAMG as we use it has no such
// input (with the rigid motions as interpolation vectors it doubled its
// setup for no fewer iterations).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

namespace akvf_bench {

class GamgSolve {
 public:
  GamgSolve();
  ~GamgSolve();
  GamgSolve(const GamgSolve&) = delete;
  GamgSolve& operator=(const GamgSolve&) = delete;

  // Builds the hierarchy of the SPD matrix whose upper triangle is `upper`
  // (2 unknowns per vertex, interleaved), with the rigid motions at the
  // vertex positions `x` (2 per vertex) as near-null space.
  void setup(const Eigen::SparseMatrix<double>& upper, const Eigen::VectorXd& x);
  // One V-cycle on A z = r from z = 0.
  void cycle(const Eigen::VectorXd& r, Eigen::VectorXd* z);
  // CG preconditioned by one V-cycle per iteration, from d = 0 to
  // |g - A d| <= tolerance |g|; returns the iterations.
  int solve(const Eigen::VectorXd& g, double tolerance, Eigen::VectorXd* d);
  // The hierarchy's levels.
  int levels() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace akvf_bench
