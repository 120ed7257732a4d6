#pragma once

// Which vector instructions the processor has, for the paths that choose a width at run time.
//
// Asked of the C library where it can tell (glibc 2.33+, <sys/platform/x86.h>): it probed the
// processor once at start-up anyway. __builtin_cpu_supports would link libgcc's own start-up
// probe, which asks again with about a dozen CPUID instructions; under a hypervisor each one
// leaves the guest (about 6 µs on the machines we measure on), 0.07 ms of a 100,000-block run
// (docs/performance.md §50). CPU_FEATURE_ACTIVE also says whether the operating system saves the
// wide registers, not only whether the processor has them.

#if defined(__x86_64__) && defined(__has_include)
#if __has_include(<sys/platform/x86.h>)
#if defined(__clang__)
#define _Bool bool  // glibc's header (2.36) writes C's _Bool, which only g++ accepts in C++
#include <sys/platform/x86.h>
#undef _Bool
#else
#include <sys/platform/x86.h>
#endif
#define NCOFFSET_GLIBC_CPU_FEATURES 1
#endif
#endif

namespace ncoffset::core {

inline bool cpuHasAvx() {
#if defined(NCOFFSET_GLIBC_CPU_FEATURES)
  return CPU_FEATURE_ACTIVE(AVX);
#elif defined(__x86_64__)
  __builtin_cpu_init();  // may be asked from a static initializer, before libgcc's
  return __builtin_cpu_supports("avx");
#else
  return false;
#endif
}

inline bool cpuHasAvx2() {
#if defined(NCOFFSET_GLIBC_CPU_FEATURES)
  return CPU_FEATURE_ACTIVE(AVX2);
#elif defined(__x86_64__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

}  // namespace ncoffset::core
