#!/bin/bash
# Runs every benchmark suite with repetitions and writes Google Benchmark's JSON report (machine,
# compiler, flags and every figure), then prints the issue's targets against the medians.
#   bash bench/run_benchmarks.sh [OUT.json] [extra opf_bench options, e.g. --benchmark_filter=Ensemble]
# Default OUT: bench/results/<host>-<date>.json. About 5 minutes on 2 cores. Run it on an idle
# machine: the medians of 5 repetitions absorb some noise, not a concurrent build.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-bench/results/$(hostname)-$(date +%Y-%m-%d).json}"
shift || true
mkdir -p "$(dirname "$out")"
# Repetitions interleaved at random across the suite: each benchmark's five spread over its
# minutes, so a spell of a busy host reaches some repetitions of every benchmark, not all of a few.
build/bin/opf_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_enable_random_interleaving=true \
  --benchmark_min_time=0.2 --benchmark_out="$out" --benchmark_out_format=json "$@"
/usr/bin/python3 bench/summarise.py "$out"
