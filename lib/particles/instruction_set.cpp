#include "opf/particles/instruction_set.h"

namespace opf::kernels {

const char* instruction_set() {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(OPF_NO_DISPATCH)
  if (__builtin_cpu_supports("x86-64-v4")) return "x86-64-v4 (AVX-512)";
  if (__builtin_cpu_supports("x86-64-v3")) return "x86-64-v3 (AVX2, FMA)";
  return "x86-64 baseline (SSE2)";
#else
  return "compiler default (no dispatch)";
#endif
}
}  // namespace opf::kernels
