#!/usr/bin/env bash
# Quick-start command 1: set up, then run the main job. Until the paper reproduction lands, the
# main job replays the bundled example log through every estimator and prints the error table.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$repo/scripts/setup.sh"
exec "$repo/build/bin/opf" evaluate \
  --in "$repo/experiments/data/example_log.csv" \
  --truth "$repo/experiments/data/example_truth.csv" "$@"
