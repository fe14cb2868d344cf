#pragma once
// Sparse Cholesky factorization of a symmetric positive definite matrix with
// CHOLMOD's analysis (supernodal, with small supernodes merged more than
// CHOLMOD does where it would factor simplicially: sparse_cholesky.cpp says
// why) and our multi-threaded numeric factorization, hidden behind a small class.
// The symbolic analysis (fill-reducing ordering, elimination tree) is done
// once for a sparsity pattern; each factorize() is numeric only (§5.2). CHOLMOD's
// 32-bit integers serve while the factor has fewer than 2^31 entries; past
// that (CHOLMOD reports its analysis too large for them) the analysis is
// redone with its 64-bit interface (cholmod_l_*): the same arithmetic.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>

#include "akvf/error.h"
#include "solvers/fill_reducing_ordering.h"

namespace akvf {

// CHOLMOD met a non-positive pivot: A is not positive definite, or is only
// semidefinite and rounding tipped a pivot below zero.
class NotPositiveDefinite : public NumericalError {
 public:
  using NumericalError::NumericalError;
};

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Symbolic analysis of the pattern of `upper` (the upper triangle, column
  // major, compressed). Later factorize() calls must use the same pattern.
  // With block_size b > 1 the unknowns come in groups of b consecutive ones
  // (the coordinates of a vertex) that share their couplings; the ordering is
  // then found on the graph of the groups, which is b^2 times smaller.
  // With `order` the blocks' elimination order is given instead of
  // computed: a permutation of the blocks, postordered here unless it says
  // it is (BlockOrdering::postordered), best a fill-reducing ordering of a
  // graph that contains this pattern's block graph
  // (solvers/fill_reducing_ordering.h: a mesh's vertex graph, ordered once
  // for the matrices on it). Given the ordering analyze(upper, block_size)
  // would compute, the analysis is the same.
  void analyze(const Eigen::SparseMatrix<double>& upper, int block_size = 1, const BlockOrdering* order = nullptr);
  // Takes over the analysis of `other` (analyzed, not yet factored): what
  // analyze() would compute for its pattern, without the ordering work
  // (solvers/symbolic_analysis_cache.h).
  void copy_analysis(const SparseCholesky& other);
  // Numeric factorization A = L L^T: a supernodal factor on the calling
  // arena's threads (solvers/supernodal_factorization.h), a simplicial one (only with
  // use_cholmod_alone) by CHOLMOD.
  // Throws NotPositiveDefinite if A is not (numerically) positive
  // definite, NumericalError on other failures.
  void factorize(const Eigen::SparseMatrix<double>& upper);
  // x = A^-1 b (x is resized), with L at its current precision.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd* x);
  // Rounds a supernodal L to single precision in place, until the next
  // factorize(): each solve then reads half the bytes, and its result
  // carries L's rounding, a relative 6e-8 per entry (enough for a
  // preconditioner). A simplicial L stays in double.
  void round_factor_to_single();
  bool factor_is_single() const;

  bool analyzed() const;
  // True for a supernodal factor (solved by our own supernodal triangular
  // solves), false for CHOLMOD's simplicial one (only with use_cholmod_alone).
  bool supernodal() const;
  // Nonzeros of the factor L after the last analyze().
  double factor_nonzeros() const;
  // Floating-point operations of one numeric factorization.
  double factor_flops() const;
  // Bytes the factor will take (values and row indices), known from the
  // analysis before any numeric work.
  double factor_bytes() const;
  // Frees the analysis and the factor (analyzed() is false again).
  void clear();
  // Takes `other`'s analysis and factor (for a matrix of the same pattern,
  // whose next factorize() overwrites the factor); `other` is left cleared.
  void take_over(SparseCholesky* other);
  // 32 or 64: CHOLMOD's integer width chosen by the last analysis (0 before).
  int index_bits() const;
  // Tests: analyze with the 64-bit interface whatever the factor's size.
  void use_64_bit_indices(bool on);
  // The fill-reducing ordering of the last analysis: "amd", or "metis" (its
  // nested dissection, computed besides AMD's on large meshes and kept when
  // it needs fewer flops; sparse_cholesky.cpp says when).
  std::string ordering() const;
  // Tests: compute METIS's ordering besides AMD's whatever the size.
  void always_try_metis(bool on);
  // Tests and benchmarks: supernodal factors by CHOLMOD's own numeric
  // factorization (one core) instead of SupernodalFactorization (every
  // thread, the same factor to rounding; solvers/supernodal_factorization.h).
  void use_cholmod_factorization(bool on);
  // Benchmarks: CHOLMOD alone, as it factors with its default settings:
  // simplicial L D L^T (one core) below its supernodal switch, its own
  // amalgamation, its own numeric factorization (the speed table's unit).
  // Set before analyze().
  void use_cholmod_alone(bool on);
  // The share of a numeric factorization's flops on the elimination tree's
  // longest chain: what no number of threads shortens
  // (solvers/supernodal_tree.h). 1 for a simplicial factor.
  double factor_critical_path_share();
  // The share of the factor's entries whose triangular solves run on one
  // thread when the solve has `threads` threads (the top of the elimination
  // tree, solvers/supernodal_solve.h). 1 for a simplicial factor.
  double solve_top_share(int threads);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// X = A^-1 B for a sparse symmetric positive definite A (both triangles
// stored): one analysis, one factorization and a solve per column of B.
// Returns false if A is not (numerically) positive definite.
// `order`, if given: the elimination order of A's rows (analyze's).
bool solve_positive_definite(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B, Eigen::MatrixXd* X,
                             const BlockOrdering* order = nullptr);

// "MAJOR.MINOR.PATCH" of the CHOLMOD the project was built against.
std::string cholmod_version();

}  // namespace akvf
