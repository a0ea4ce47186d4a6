#!/usr/bin/env bash
# Quick-start command 2: set up, then run the whole test suite with ctest.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$repo/scripts/setup.sh"
cd "$repo/build"
ctest --output-on-failure -j 2 "$@"
