#!/usr/bin/env bash
# The real-motion benchmark: set up (as the quick-start commands do), then every estimator under
# both presets on the shipped recordings and OpenCV's sample clips, 3 seeds, in parallel across
# the cores (experiments/real_motion/run_benchmark.py; its protocol in
# experiments/real_motion/README.md). Writes results.csv, profile.csv, summary.md and a figure
# per kind of motion into OUT_DIR (default results/real_motion).
# Usage: bash scripts/run_real_motion.sh [OUT_DIR] [run_benchmark.py options, e.g. --subset]
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$repo/scripts/setup.sh"
out="${1:-$repo/results/real_motion}"
(($# > 0)) && shift
# Debian's interpreter: it has the numpy and matplotlib that setup.sh installs.
/usr/bin/python3 "$repo/experiments/real_motion/run_benchmark.py" "$out" \
  --opf "$repo/build/bin/opf" "$@"
