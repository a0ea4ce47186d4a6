#include "opf/core/heap_policy.h"

#include <gtest/gtest.h>

#include <vector>

namespace opf {
namespace {

// Under AddressSanitizer malloc is ASan's, which ignores mallopt: the function says so.
TEST(HeapPolicy, GlibcTakesTheSettingsAndAllocationStillWorks) {
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
  EXPECT_TRUE(retain_freed_heap_memory());
#else
  EXPECT_FALSE(retain_freed_heap_memory());
#endif
  // Large blocks freed and taken again, as a filter's generations are.
  for (int step = 0; step < 100; ++step) {
    std::vector<double> generation(15000, step);
    EXPECT_EQ(generation.back(), step);
  }
}

}  // namespace
}  // namespace opf
