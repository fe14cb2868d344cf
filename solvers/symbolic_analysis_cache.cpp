#include "solvers/symbolic_analysis_cache.h"

#include <algorithm>

namespace akvf {

bool SymbolicAnalysisCache::Entry::matches(const Eigen::SparseMatrix<double>& upper, int size) const {
  const Eigen::Index n = upper.outerSize();
  return block_size == size && static_cast<Eigen::Index>(column_start.size()) == n + 1 &&
         static_cast<Eigen::Index>(row.size()) == upper.nonZeros() &&
         std::equal(column_start.begin(), column_start.end(), upper.outerIndexPtr()) &&
         std::equal(row.begin(), row.end(), upper.innerIndexPtr());
}

void SymbolicAnalysisCache::forget(const Eigen::SparseMatrix<double>& upper, int block_size) {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::erase_if(entries_, [&](const Entry& entry) { return entry.matches(upper, block_size); });
}

bool SymbolicAnalysisCache::analyze(const Eigen::SparseMatrix<double>& upper, int block_size,
                                    SparseCholesky* cholesky, const BlockOrdering* order) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const int* start = upper.outerIndexPtr();
  const int* row = upper.innerIndexPtr();
  const Eigen::Index n = upper.outerSize();
  for (const Entry& entry : entries_) {
    if (entry.matches(upper, block_size)) {
      cholesky->copy_analysis(*entry.analysis);
      return false;
    }
  }
  cholesky->analyze(upper, block_size, order);
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
