#!/usr/bin/env bash
# Fuzzes the readers of user input with libFuzzer (clang, with AddressSanitizer and
# UndefinedBehaviorSanitizer): the measurement log, the estimator settings file, the experiment
# file, opf detect's segmentation spec and opf sweep's sweep file, each for SECONDS (default 60),
# starting from tests/fuzz/corpus/<target>/ (the grown corpus goes to a scratch directory). A
# crash stops the run; its input is kept as tests/fuzz/regressions/<target>/<crash file>
# (replayed by the test suite from then on) and printed in hex, and the script exits 1.
#   bash scripts/run_fuzzers.sh [SECONDS]        (CI runs it after the tests)
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
bash "$repo/scripts/setup.sh" >/dev/null  # clang and libclang-rt come from scripts/packages.txt
build="$repo/build-fuzz"
mkdir -p "$build"
# The build's output is kept, and shown when it fails: a fuzzer that does not build is a failure
# to read, not a silent exit.
if ! { cmake -S "$repo/fuzz" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ &&
  cmake --build "$build" -j 2; } >"$build/build.log" 2>&1; then
  echo "fuzz: building the fuzzers failed ($build/build.log):" >&2
  grep -E "error|undefined reference" "$build/build.log" | head -n 20 >&2 || tail -n 40 "$build/build.log" >&2
  exit 1
fi
status=0
# A sweep file names bundled experiments, read from the source tree's experiments/.
export OPF_DATA_DIR="$repo"
for target in measurement_log estimator_settings experiment_file segmentation_spec sweep_file; do
  scratch="$(mktemp -d)"
  cp "$repo/tests/fuzz/corpus/$target/"* "$scratch/"
  regressions="$repo/tests/fuzz/regressions/$target"
  log="$build/$target.log"
  if "$build/${target}_fuzzer" -max_total_time="$seconds" -print_final_stats=1 \
      -artifact_prefix="$regressions/" "$scratch" >"$log" 2>&1; then
    runs="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')"
    edges="$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$')"
    echo "fuzz $target: $runs inputs in ${seconds} s, $edges edges covered, no crash"
  else
    status=1
    echo "fuzz $target: CRASH; the input is kept in $regressions/ (commit it):" >&2
    grep -E "ERROR|SUMMARY|runtime error|Test unit written" "$log" >&2 || tail -n 20 "$log" >&2
    for crash in "$regressions"/crash-* "$regressions"/leak-* "$regressions"/timeout-*; do
      [ -f "$crash" ] && { echo "  $crash:" >&2; od -An -tx1 "$crash" | head -n 20 >&2; }
    done
  fi
  rm -rf "$scratch"
done
exit "$status"
