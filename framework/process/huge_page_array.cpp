#include "framework/process/huge_page_array.h"

#include <algorithm>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace akvf {

void FreeDeleter::operator()(void* p) const noexcept { std::free(p); }

HugePageDoubles allocate_huge_page_doubles(std::size_t n) {
  constexpr std::size_t kHugePage = std::size_t{1} << 21;
  if (n > (static_cast<std::size_t>(-1) - kHugePage) / sizeof(double)) throw std::bad_alloc();
  // aligned_alloc wants a multiple of the alignment.
  const std::size_t bytes = (std::max<std::size_t>(n, 1) * sizeof(double) + kHugePage - 1) / kHugePage * kHugePage;
  void* memory = std::aligned_alloc(kHugePage, bytes);
  if (!memory) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
  madvise(memory, bytes, MADV_HUGEPAGE);  // advice only: where refused, the pages stay 4 KiB
#endif
  return HugePageDoubles(static_cast<double*>(memory));
}

}  // namespace akvf
