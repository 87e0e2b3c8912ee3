// The huge-page allocator: small and large vectors work, large ones start on a 2 MiB boundary.
#include "core/huge_page_allocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

namespace voltree {
namespace {

TEST(HugePageAllocator, SmallAndLargeVectors) {
  HugePageVector<float> small(100, 1.f);
  EXPECT_FLOAT_EQ(std::accumulate(small.begin(), small.end(), 0.f), 100.f);
  HugePageVector<uint32_t> large(3 << 20);  // 12 MiB
  std::iota(large.begin(), large.end(), 0u);
  EXPECT_EQ(large.back(), (3u << 20) - 1);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(large.data()) % (2 << 20), 0u);
  large.resize(10);  // shrinking keeps the block; growing again reallocates through the allocator
  large.shrink_to_fit();
  EXPECT_EQ(large.size(), 10u);
}

TEST(HugePageAllocator, OverAlignedElements) {
  struct alignas(64) Line {
    float values[16];
  };
  HugePageVector<Line> lines(5);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(lines.data()) % 64, 0u);
}

}  // namespace
}  // namespace voltree
