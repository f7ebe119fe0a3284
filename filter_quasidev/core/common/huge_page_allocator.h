// An allocator for a factor's values (quasi_definite_ldlt.h), the engine's largest and most
// written array: a block of kHugePage to kMostHugeBytes is mapped on its own, aligned to
// kHugePage and advised as huge pages (MADV_HUGEPAGE), so that where the kernel gives transparent
// huge pages on request (Debian's default, "madvise") it is backed by 2 MiB pages: one page fault
// each instead of one per 4 KiB. Other blocks come from the heap, as they do where the kernel
// gives huge pages to every block ("always") or to none ("never"), and elsewhere than Linux.
//
// Measured against the build before (docs/performance.md, "Huge pages for the factors"): the
// shirt re-cut into 2 at --max-iter 5 (factors of up to 7.8 MB) 100 → 92 ms in the engine and a
// third fewer page faults, medians of 25 alternating runs; the 40k GCD tee at --max-iter 10 (up
// to 30 MB) 715 → 694 ms; garments whose factors stay below 2 MiB unchanged. But on a
// 1M-triangle cylinder, whose preconditioner's factors hold about 400 MB each, the advice made
// the factorisation stage 0.92 → 1.27 s (the kernel compacts memory to find that many 2 MiB
// pages), hence the upper bound.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace qd::common {

constexpr size_t kHugePage = size_t{2} << 20;
constexpr size_t kMostHugeBytes = size_t{64} << 20;

template <typename T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <typename U>
  explicit HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(size_t n) {
#if defined(__linux__)
    if (huge(n)) {
      const size_t bytes = rounded(n), mapped = bytes + kHugePage;  // room to align the start
      void* p = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (p == MAP_FAILED) throw std::bad_alloc();
      const auto start = reinterpret_cast<uintptr_t>(p);
      const uintptr_t aligned = (start + kHugePage - 1) & ~(uintptr_t{kHugePage} - 1);
      const uintptr_t end = aligned + bytes;
      if (aligned > start) munmap(p, aligned - start);  // the unaligned head and tail go back
      if (start + mapped > end) munmap(reinterpret_cast<void*>(end), start + mapped - end);
      madvise(reinterpret_cast<void*>(aligned), bytes, MADV_HUGEPAGE);  // a request, not a need
      return reinterpret_cast<T*>(aligned);
    }
#endif
    return std::allocator<T>().allocate(n);
  }

  void deallocate(T* p, size_t n) {
#if defined(__linux__)
    if (huge(n)) {
      munmap(p, rounded(n));
      return;
    }
#endif
    std::allocator<T>().deallocate(p, n);
  }

  // Whether a block of n values is mapped on its own.
  static bool huge(size_t n) {
#if defined(__linux__)
    return n >= kHugePage / sizeof(T) && n <= kMostHugeBytes / sizeof(T);
#else
    (void)n;
    return false;
#endif
  }

 private:
  static size_t rounded(size_t n) {  // the bytes of n values, in whole huge pages
    return (n * sizeof(T) + kHugePage - 1) / kHugePage * kHugePage;
  }
};

template <typename T, typename U>
bool operator==(const HugePageAllocator<T>&, const HugePageAllocator<U>&) {
  return true;
}
template <typename T, typename U>
bool operator!=(const HugePageAllocator<T>&, const HugePageAllocator<U>&) {
  return false;
}

}  // namespace qd::common
