#include "framework/process/huge_page_array.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace akvf {

namespace {

constexpr std::size_t kHugePage = std::size_t{1} << 21;

// Heap memory, 64-byte aligned (a cache line).
HugePageDoubles heap_doubles(std::size_t n) {
  const std::size_t bytes = (std::max<std::size_t>(n, 1) * sizeof(double) + 63) / 64 * 64;
  void* memory = std::aligned_alloc(64, bytes);
  if (!memory) throw std::bad_alloc();
  return HugePageDoubles(static_cast<double*>(memory), HugePageDeleter{0});
}

}  // namespace

void HugePageDeleter::operator()(void* p) const noexcept {
#if defined(__linux__)
  if (bytes > 0) {
    munmap(p, bytes);
    return;
  }
#endif
  std::free(p);
}

HugePageDoubles allocate_huge_page_doubles(std::size_t n) {
  if (n > (static_cast<std::size_t>(-1) - 2 * kHugePage) / sizeof(double)) throw std::bad_alloc();
  if (n * sizeof(double) < kHugePage / 2) return heap_doubles(n);
#if defined(__linux__)
  // One huge page more than whole huge pages, cut to a 2 MiB boundary.
  const std::size_t bytes = (n * sizeof(double) + kHugePage - 1) / kHugePage * kHugePage;
  void* mapped = mmap(nullptr, bytes + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) throw std::bad_alloc();
  const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(mapped);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start) munmap(mapped, aligned - start);
  const std::uintptr_t end = aligned + bytes, mapped_end = start + bytes + kHugePage;
  if (mapped_end > end) munmap(reinterpret_cast<void*>(end), mapped_end - end);
  void* memory = reinterpret_cast<void*>(aligned);
#if defined(MADV_HUGEPAGE)
  madvise(memory, bytes, MADV_HUGEPAGE);  // advice only: where refused, the pages stay 4 KiB
#endif
  return HugePageDoubles(static_cast<double*>(memory), HugePageDeleter{bytes});
#else
  return heap_doubles(n);
#endif
}

}  // namespace akvf
