// HugePageAllocator: which blocks it maps on their own, that those start on a huge page and hold
// what is written to them, and that a vector on it holds the same values as on the heap.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "common/huge_page_allocator.h"

namespace qd {
namespace {

using common::HugePageAllocator;
using common::kHugePage;
using common::kMostHugeBytes;

TEST(HugePageAllocator, MapsOnlyBlocksBetweenAHugePageAndItsBound) {
  const size_t page = kHugePage / sizeof(double), most = kMostHugeBytes / sizeof(double);
#if defined(__linux__)
  EXPECT_FALSE(HugePageAllocator<double>::huge(page - 1));
  EXPECT_TRUE(HugePageAllocator<double>::huge(page));
  EXPECT_TRUE(HugePageAllocator<double>::huge(most));
  EXPECT_FALSE(HugePageAllocator<double>::huge(most + 1));
#else
  EXPECT_FALSE(HugePageAllocator<double>::huge(page));
#endif
}

TEST(HugePageAllocator, AlignsAMappedBlockToAHugePageAndKeepsItsValues) {
  HugePageAllocator<double> allocator;
  const size_t n = 3 * kHugePage / sizeof(double) + 5;  // not a whole number of huge pages
  double* p = allocator.allocate(n);
  ASSERT_NE(p, nullptr);
#if defined(__linux__)
  EXPECT_EQ(reinterpret_cast<uintptr_t>(p) % kHugePage, 0u);
#endif
  for (size_t i = 0; i < n; ++i) p[i] = static_cast<double>(i);
  double sum = 0;
  for (size_t i = 0; i < n; ++i) sum += p[i];
  EXPECT_EQ(sum, static_cast<double>(n) * static_cast<double>(n - 1) / 2);
  allocator.deallocate(p, n);
}

TEST(HugePageAllocator, HoldsAVectorAsTheHeapDoes) {
  for (size_t n : {size_t{1000}, kHugePage / sizeof(double) + 1}) {
    std::vector<double, HugePageAllocator<double>> mapped(n);
    std::vector<double> heap(n);
    std::iota(mapped.begin(), mapped.end(), 0.5);
    std::iota(heap.begin(), heap.end(), 0.5);
    EXPECT_TRUE(std::equal(mapped.begin(), mapped.end(), heap.begin())) << n << " values";
    mapped.assign(n, 0.0);
    EXPECT_EQ(std::count(mapped.begin(), mapped.end(), 0.0), static_cast<long>(n));
  }
}

}  // namespace
}  // namespace qd
