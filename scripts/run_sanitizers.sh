#!/usr/bin/env bash
# Builds the toolkit with AddressSanitizer and UndefinedBehaviorSanitizer (GCC, into
# build-sanitize/) and runs the test suite there: any memory error, leak (LeakSanitizer at each
# test's exit) or undefined behaviour fails its test. -O1 -g1 halves the compile time of -O2 -g
# and keeps file:line in the reports; NDEBUG as in the release build, so the same code is
# checked. UBSan's null and alignment checks are off: they guard every Eigen expression and
# double the compile time, while a null dereference still stops the test with ASan's SEGV report
# and stack, and x86-64 executes misaligned scalar loads (the one aligned SIMD store, in
# sorted_gather.cpp, faults if misaligned).
# Left to the regular build: the workflow tests that only drive Python and TeX on `opf` output
# (small result sets, notebooks, report), the install check (an uninstrumented project links the
# package), the layer probes (compile-only), the Python module (an instrumented module needs an
# instrumented interpreter), Table I's accuracy check (20 reproductions; their code runs
# instrumented in the estimator and driver tests) and the benchmark program (speed is not checked
# here; what it times runs in the tests; `Report\.` excludes its checks) and the benchmark
# subsets (real motion, its ablation, the hand scenes, the real-video script: Python drivers of
# `opf run` and `opf evaluate`, whose estimators, drivers and readers run instrumented in the
# estimator, driver and program tests; instrumented, they took 3.7 of its 21 test-minutes).
# So only the test program and `opf` are built.
#   bash scripts/run_sanitizers.sh [extra ctest arguments]
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$repo/scripts/setup.sh" >/dev/null
build="$repo/build-sanitize"
flags="-fsanitize=address,undefined -fno-sanitize=null,alignment -fno-omit-frame-pointer"
cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" -DOPF_BUILD_PYTHON=OFF >/dev/null
cmake --build "$build" -j 2 --target opf_tests opf_cli
# intercept_tls_get_addr=0: LeakSanitizer misreads some dynamic TLS blocks as glibc 2.19's (by
# their address alone) and its tracer then crashes scanning a bogus range ("Tracer caught signal
# 11", google/sanitizers#1322); whether it strikes depends on the process's memory layout. Leaks
# are still found on the heap, the stacks and static TLS.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:intercept_tls_get_addr=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
cd "$build"
ctest --output-on-failure -j 2 \
  -E "SmallResults|Notebooks|Report\\.|Package\\.|Layers\\.|TableOne\\.|RealMotion\\..*Subset|RealVideo\\." "$@"
