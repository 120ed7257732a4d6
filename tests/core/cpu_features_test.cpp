#include "core/cpu_features.hpp"

#include <gtest/gtest.h>

// The C library's answer (what the run-time width choices use) agrees with the compiler's own
// probe of the processor (docs/performance.md §50).
TEST(CpuFeatures, AgreeWithTheCompilersProbe) {
#if defined(__x86_64__)
  __builtin_cpu_init();
  EXPECT_EQ(ncoffset::core::cpuHasAvx(), __builtin_cpu_supports("avx") != 0);
  EXPECT_EQ(ncoffset::core::cpuHasAvx2(), __builtin_cpu_supports("avx2") != 0);
#else
  EXPECT_FALSE(ncoffset::core::cpuHasAvx());
  EXPECT_FALSE(ncoffset::core::cpuHasAvx2());
#endif
}

// AVX2 is an extension of AVX: a processor (or an operating system) without AVX has neither.
TEST(CpuFeatures, Avx2ImpliesAvx) {
  if (ncoffset::core::cpuHasAvx2()) {
    EXPECT_TRUE(ncoffset::core::cpuHasAvx());
  }
}
