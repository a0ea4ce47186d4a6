#!/usr/bin/env bash
# Fuzzes the readers of user input with libFuzzer (clang, with AddressSanitizer and
# UndefinedBehaviorSanitizer): the measurement log, the estimator settings file, the experiment
# file, opf detect's segmentation spec and opf sweep's sweep file, each for SECONDS (default 60)
# of one core, two at a time, starting from tests/fuzz/corpus/<target>/ (the grown corpus goes to
# a scratch directory). A crash fails the run; its input is kept as
# tests/fuzz/regressions/<target>/<crash file> (replayed by the test suite from then on) and
# printed in hex, and the script exits 1.
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
# A sweep file names bundled experiments, read from the source tree's experiments/.
export OPF_DATA_DIR="$repo"
# One target: SECONDS of fuzzing from its corpus; its verdict (a line ending in "no crash", or
# the crash's report) goes to $build/<target>.verdict.
fuzz_target() {
  local target="$1" scratch regressions log runs edges crash
  scratch="$(mktemp -d)"
  cp "$repo/tests/fuzz/corpus/$target/"* "$scratch/"
  regressions="$repo/tests/fuzz/regressions/$target"
  log="$build/$target.log"
  if "$build/${target}_fuzzer" -max_total_time="$seconds" -print_final_stats=1 \
      -artifact_prefix="$regressions/" "$scratch" >"$log" 2>&1; then
    runs="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')"
    edges="$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$')"
    echo "fuzz $target: $runs inputs in ${seconds} s, $edges edges covered, no crash" \
      >"$build/$target.verdict"
  else
    {
      echo "fuzz $target: CRASH; the input is kept in $regressions/ (commit it):"
      grep -E "ERROR|SUMMARY|runtime error|Test unit written" "$log" || tail -n 20 "$log"
      for crash in "$regressions"/crash-* "$regressions"/leak-* "$regressions"/timeout-*; do
        [ -f "$crash" ] && { echo "  $crash:"; od -An -tx1 "$crash" | head -n 20; }
      done
    } >"$build/$target.verdict"
  fi
  rm -rf "$scratch"
}
# Two targets at a time, one per core: each still gets SECONDS of one core.
targets=(measurement_log estimator_settings experiment_file segmentation_spec sweep_file)
for target in "${targets[@]}"; do
  rm -f "$build/$target.verdict"
  while (($(jobs -rp | wc -l) >= 2)); do wait -n || true; done
  fuzz_target "$target" &
done
wait
status=0
for target in "${targets[@]}"; do
  if grep -q "no crash$" "$build/$target.verdict" 2>/dev/null; then
    cat "$build/$target.verdict"
  else
    status=1
    cat "$build/$target.verdict" >&2 2>/dev/null || echo "fuzz $target: no verdict" >&2
  fi
done
exit "$status"
