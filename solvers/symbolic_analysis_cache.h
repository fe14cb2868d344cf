#pragma once
// Symbolic analyses (fill-reducing ordering, elimination tree, supernodes)
// kept for the sparsity patterns already seen, so that repeated solves on one
// mesh (akvf::Parameterizer, akvf::Deformer) analyze each pattern once: the
// matrix preconditioners of a mesh all have the pattern of its vertex
// adjacency in D x D blocks. A copied analysis is the one analyze() computes
// for that pattern, so the factors and every iterate are bitwise the same.
// An analysis may also be prepared ahead of the solve that needs it, on a
// core that would otherwise wait (akvf/parameterization.cpp: beside the Tutte
// solve); the first solve that takes it counts it as its own.
// Safe to share between threads (a lock guards the entries).
#include <Eigen/SparseCore>
#include <memory>
#include <mutex>
#include <vector>

#include "solvers/sparse_cholesky.h"

namespace akvf {

class SymbolicAnalysisCache {
 public:
  // Gives `cholesky` the analysis of the pattern of `upper` with the given
  // block size: a copy of the cached one, or a new one (then cached;
  // `order` as for SparseCholesky::analyze).
  // Returns true if it was computed, here or by prepare() and not taken
  // before.
  bool analyze(const Eigen::SparseMatrix<double>& upper, int block_size, SparseCholesky* cholesky,
               const BlockOrdering* order = nullptr);
  // Gives `cholesky` a copy of the kept analysis of the pattern of `upper`,
  // leaving it to be taken by analyze(); false if none is kept.
  bool copy(const Eigen::SparseMatrix<double>& upper, int block_size, SparseCholesky* cholesky) const;
  // Computes and keeps the analysis analyze() would, unless one is kept.
  void prepare(const Eigen::SparseMatrix<double>& upper, int block_size, const BlockOrdering* order = nullptr);
  // Whether an analysis of the pattern of `upper` is kept.
  bool holds(const Eigen::SparseMatrix<double>& upper, int block_size) const;
  // Drops the analysis of that pattern, if kept (a factor that will not be built).
  void forget(const Eigen::SparseMatrix<double>& upper, int block_size);

 private:
  struct Entry {
    bool matches(const Eigen::SparseMatrix<double>& upper, int size) const;
    std::vector<int> column_start, row;
    int block_size = 1;
    std::unique_ptr<SparseCholesky> analysis;  // analyzed, never factored
    bool taken = true;                         // false for a prepared one until analyze() takes it
  };
  bool kept(const Eigen::SparseMatrix<double>& upper, int block_size) const;  // under the lock
  mutable std::mutex mutex_;
  std::vector<Entry> entries_;
};

}  // namespace akvf
