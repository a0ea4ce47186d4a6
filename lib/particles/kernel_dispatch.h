#pragma once
// OPF_KERNEL marks a hot loop that GCC compiles three times (AVX-512, AVX2 + FMA, baseline
// x86-64) and picks from at load time by the CPU it runs on (function multi-versioning), so one
// build is fast on any x86-64 machine without -march=native (which would change Eigen's
// alignment against the Debian-built MRPT and Ceres). Kernels exchange raw arrays only.
// Results are deterministic for a given seed on a given machine; machines that pick different
// versions may differ in the last bits (fused multiply-adds).

// OPF_KERNEL_DISPATCH is defined where this is so: the hand-written AVX-512 paths
// (sorted_gather.h, member_table_step.h) exist only then, and run where cpu_has_avx512f().

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(OPF_NO_DISPATCH)
#define OPF_KERNEL_DISPATCH 1
#define OPF_KERNEL [[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]]
#else
#define OPF_KERNEL
#endif

namespace opf::kernels {

/// Whether this build dispatches by CPU and the CPU it runs on has AVX-512F (read once).
inline bool cpu_has_avx512f() {
#ifdef OPF_KERNEL_DISPATCH
  static const bool available = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") != 0;
  }();
  return available;
#else
  return false;
#endif
}

}  // namespace opf::kernels
