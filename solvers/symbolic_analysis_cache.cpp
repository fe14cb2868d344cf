#include "solvers/symbolic_analysis_cache.h"

#include <algorithm>

namespace akvf {

bool SymbolicAnalysisCache::analyze(const Eigen::SparseMatrix<double>& upper, int block_size,
                                    SparseCholesky* cholesky) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const int* start = upper.outerIndexPtr();
  const int* row = upper.innerIndexPtr();
  const Eigen::Index n = upper.outerSize();
  for (const Entry& entry : entries_) {
    if (entry.block_size != block_size || static_cast<Eigen::Index>(entry.column_start.size()) != n + 1 ||
        static_cast<Eigen::Index>(entry.row.size()) != upper.nonZeros())
      continue;
    if (std::equal(entry.column_start.begin(), entry.column_start.end(), start) &&
        std::equal(entry.row.begin(), entry.row.end(), row)) {
      cholesky->copy_analysis(*entry.analysis);
      return false;
    }
  }
  cholesky->analyze(upper, block_size);
  Entry entry;
  entry.column_start.assign(start, start + n + 1);
  entry.row.assign(row, row + upper.nonZeros());
  entry.block_size = block_size;
  entry.analysis = std::make_unique<SparseCholesky>();
  entry.analysis->copy_analysis(*cholesky);
  entries_.push_back(std::move(entry));
  return true;
}

}  // namespace akvf
