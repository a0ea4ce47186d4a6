// The benchmark program's entry point: Google Benchmark's own, plus the build facts a reader of
// the JSON report needs next to the machine facts it records anyway (CPU, caches, load).

#include "opf/core/heap_policy.h"
#include "opf/particles/instruction_set.h"

#include <benchmark/benchmark.h>

int main(int argc, char** argv) {
  opf::retain_freed_heap_memory();  // as the `opf` program does (core/heap_policy.h)
  benchmark::AddCustomContext("compiler", "g++ " __VERSION__);
  benchmark::AddCustomContext("build_type", OPF_BUILD_TYPE);
  benchmark::AddCustomContext("cxx_flags", OPF_CXX_FLAGS);
  benchmark::AddCustomContext("particle_kernels", opf::kernels::instruction_set());
  // Set in lib/CMakeLists.txt for the kernels' sources only.
  benchmark::AddCustomContext("particle_kernel_flags",
                              "-fno-math-errno -fno-trapping-math -fopenmp-simd "
                              "-ffp-contract=fast, target_clones x86-64-v4/x86-64-v3/default");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
