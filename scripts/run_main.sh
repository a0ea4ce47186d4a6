#!/usr/bin/env bash
# Quick-start command 1: set up, then run the main job: reproduce the paper's simulated
# experiments (every estimator, 5 seeds, 5000 + 5000 particles), print Table I beside the paper's
# numbers and write per-frame CSVs and summary.json under results/. Extra arguments go to
# `opf reproduce` (see `build/bin/opf reproduce --help`).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$repo/scripts/setup.sh"
exec "$repo/build/bin/opf" reproduce --out "$repo/results" "$@"
