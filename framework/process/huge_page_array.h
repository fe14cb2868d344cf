#pragma once
// Uninitialized arrays for large working sets that every iteration reads
// all over (the supernodal factor L), in memory the kernel may back by
// transparent huge pages: 2 MiB aligned and, on Linux, marked
// madvise(MADV_HUGEPAGE), which is what Debian's default
// (transparent_hugepage=madvise) backs with 2 MiB pages. A factorization and
// its solves visit L's supernodes in elimination-tree order, a page or two
// at a time; on 4 KiB pages most such visits also miss the TLB, and the
// first factorization takes a page fault every 4 KiB. Only placement
// changes: the values, and so the results, are the same bits.
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
