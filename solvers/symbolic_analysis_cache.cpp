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

bool SymbolicAnalysisCache::kept(const Eigen::SparseMatrix<double>& upper, int block_size) const {
  return std::any_of(entries_.begin(), entries_.end(),
                     [&](const Entry& entry) { return entry.matches(upper, block_size); });
}

bool SymbolicAnalysisCache::holds(const Eigen::SparseMatrix<double>& upper, int block_size) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return kept(upper, block_size);
}

namespace {

// An entry for the pattern of `upper`, with an empty analysis.
template <class Entry>
Entry entry_of(const Eigen::SparseMatrix<double>& upper, int block_size) {
  Entry entry;
  entry.column_start.assign(upper.outerIndexPtr(), upper.outerIndexPtr() + upper.outerSize() + 1);
  entry.row.assign(upper.innerIndexPtr(), upper.innerIndexPtr() + upper.nonZeros());
  entry.block_size = block_size;
  entry.analysis = std::make_unique<SparseCholesky>();
  return entry;
}

}  // namespace

bool SymbolicAnalysisCache::analyze(const Eigen::SparseMatrix<double>& upper, int block_size, SparseCholesky* cholesky,
                                    const BlockOrdering* order) {
  const std::lock_guard<std::mutex> lock(mutex_);
  for (Entry& entry : entries_) {
    if (entry.matches(upper, block_size)) {
      cholesky->copy_analysis(*entry.analysis);
      const bool first = !entry.taken;
      entry.taken = true;
      return first;
    }
  }
  cholesky->analyze(upper, block_size, order);
  entries_.push_back(entry_of<Entry>(upper, block_size));
  entries_.back().analysis->copy_analysis(*cholesky);
  return true;
}

bool SymbolicAnalysisCache::copy(const Eigen::SparseMatrix<double>& upper, int block_size,
                                 SparseCholesky* cholesky) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  for (const Entry& entry : entries_)
    if (entry.matches(upper, block_size)) {
      cholesky->copy_analysis(*entry.analysis);
      return true;
    }
  return false;
}

void SymbolicAnalysisCache::prepare(const Eigen::SparseMatrix<double>& upper, int block_size,
                                    const BlockOrdering* order) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (kept(upper, block_size)) return;
  }
  // Computed without the lock: a solve may take another entry meanwhile.
  Entry entry = entry_of<Entry>(upper, block_size);
  entry.analysis->analyze(upper, block_size, order);
  entry.taken = false;
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!kept(upper, block_size)) entries_.push_back(std::move(entry));
}

}  // namespace akvf
