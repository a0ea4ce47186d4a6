#!/bin/bash
# Times `opf track` as a user runs it (whole process: start-up, reading the log, tracking, writing
# the estimates) on a 3-object, 2000-frame log at 5000 + 5000 particles, and reports its peak
# memory. The targets: under 1 s and under 100 MB on this kind of machine. The camera is the
# default, straight down, stated so that `opf track` does not warn of its absence.
#   bash bench/time_track.sh [BUILD_DIR]          (default build)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 bench/make_track_log.py "$work/log.csv"
for threads in 1 2; do
  if [ -x /usr/bin/time ]; then
    /usr/bin/time -f "threads=$threads: %e s wall, %M KB peak resident" \
      "$build/bin/opf" track --in "$work/log.csv" --out "$work/est.csv" --particles 5000 \
      --camera 0,0,1,0 --threads "$threads" >/dev/null
  else
    echo "threads=$threads (install the 'time' package for the peak memory):"
    time "$build/bin/opf" track --in "$work/log.csv" --out "$work/est.csv" --particles 5000 \
      --camera 0,0,1,0 --threads "$threads" >/dev/null
  fi
done
