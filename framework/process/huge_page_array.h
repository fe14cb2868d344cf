#pragma once
// Uninitialized arrays for large working sets (the supernodal factor L), in
// memory the kernel may back by transparent huge pages: 2 MiB aligned and,
// on Linux, marked madvise(MADV_HUGEPAGE), which is what Debian's default
// (transparent_hugepage=madvise) backs with 2 MiB pages. A run's first
// factorization then takes a page fault per 2 MiB of L instead of per 4 KiB:
// `akvf_benchmarks --benchmark_filter=FirstIteration` on horse_b (L 16 MiB),
// 42-43 ms against 47-49 ms on 4 KiB pages (2026-11-29, the 2-core VM); the
// later factorizations and solves, on memory already mapped, measured the
// same within noise. Only placement changes, never a value.
#include <cstddef>
#include <memory>

namespace akvf {

struct FreeDeleter {
  void operator()(void* p) const noexcept;
};

template <class T>
using HugePageArray = std::unique_ptr<T[], FreeDeleter>;

// n uninitialized doubles (throws std::bad_alloc when the memory is not there).
HugePageArray<double> allocate_huge_page_doubles(std::size_t n);

}  // namespace akvf
