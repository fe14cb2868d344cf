#pragma once
// Uninitialized arrays for large working sets (the supernodal factor L), in
// memory the kernel may back by transparent huge pages: 2 MiB aligned and,
// on Linux, marked madvise(MADV_HUGEPAGE), which is what Debian's default
// (transparent_hugepage=madvise) backs with 2 MiB pages. A run's first
// factorization then takes a page fault per 2 MiB of L instead of per 4 KiB
// (measured: docs/notes/2026-11-29-memory-traffic.md). Only placement
// changes, never a value.
#include <cstddef>
#include <memory>

namespace akvf {

struct FreeDeleter {
  void operator()(void* p) const noexcept;
};

using HugePageDoubles = std::unique_ptr<double[], FreeDeleter>;

// n uninitialized doubles (throws std::bad_alloc when the memory is not there).
HugePageDoubles allocate_huge_page_doubles(std::size_t n);

}  // namespace akvf
