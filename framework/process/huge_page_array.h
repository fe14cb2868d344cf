#pragma once
// Uninitialized arrays for large working sets (the supernodal factor L, the
// element matrices' assembly buffer), in memory the kernel may back by
// transparent huge pages: on Linux a 2 MiB aligned mapping of their own,
// marked madvise(MADV_HUGEPAGE), which is what Debian's default
// (transparent_hugepage=madvise) backs with 2 MiB pages. Their first use
// then takes a page fault per 2 MiB instead of per 4 KiB (measured:
// docs/notes/2026-11-30-page-faults.md). Memory from the heap
// would not do: where the heap already maps 4 KiB pages the advice changes
// nothing. Arrays under 1 MiB come from the heap. Only placement changes,
// never a value.
#include <cstddef>
#include <memory>

namespace akvf {

// Unmaps a mapping of `bytes` bytes, or frees heap memory (bytes 0).
struct HugePageDeleter {
  std::size_t bytes = 0;
  void operator()(void* p) const noexcept;
};

using HugePageDoubles = std::unique_ptr<double[], HugePageDeleter>;

// n uninitialized doubles (throws std::bad_alloc when the memory is not there).
HugePageDoubles allocate_huge_page_doubles(std::size_t n);

}  // namespace akvf
