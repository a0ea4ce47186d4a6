#!/usr/bin/env bash
# The dynamics module's ablation on the real-motion benchmark: set up (as the quick-start commands
# do), then the OPF with its full bank of motion models and with each model removed in turn, on
# every log of the benchmark, 3 seeds, against the constant-velocity Kalman filter
# (experiments/real_motion/run_ablation.py). Writes ablation.csv, ablation.md and ablation.png
# into OUT_DIR (default results/dynamics_ablation); notebooks/ablations.ipynb plots them.
# Usage: bash scripts/run_dynamics_ablation.sh [OUT_DIR] [run_ablation.py options, e.g. --subset]
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$repo/scripts/setup.sh"
out="${1:-$repo/results/dynamics_ablation}"
(($# > 0)) && shift
/usr/bin/python3 "$repo/experiments/real_motion/run_ablation.py" "$out" \
  --opf "$repo/build/bin/opf" "$@"
