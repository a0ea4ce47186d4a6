#pragma once
// Which version of the particle kernels this CPU runs (kernel_dispatch.h), for benchmark reports.

namespace opf::kernels {

/// "x86-64-v4 (AVX-512)", "x86-64-v3 (AVX2, FMA)" or "x86-64 baseline (SSE2)".
const char* instruction_set();

}  // namespace opf::kernels
