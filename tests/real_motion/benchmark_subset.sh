#!/usr/bin/env bash
# The real-motion benchmark's subset end to end, twice: it must write its table, figures and tidy
# CSV, score every estimator with calibration, and give the same bytes both times.
# Usage: benchmark_subset.sh REPO OPF WORK_DIR
set -euo pipefail
repo="$1" opf="$2" work="$3"
rm -rf "$work"
for run in a b; do
  /usr/bin/python3 "$repo/experiments/real_motion/run_benchmark.py" "$work/$run" --subset --opf "$opf" \
    >"$work.$run.log" 2>&1 || { cat "$work.$run.log"; exit 1; }
done
cat "$work.a.log"
for file in results.csv profile.csv summary.md; do
  cmp "$work/a/$file" "$work/b/$file" || { echo "benchmark subset: $file differs between runs"; exit 1; }
done
/usr/bin/python3 - "$work/a" <<'PY'
import csv, math, os, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "results.csv"))))
kinds = sorted({r["kind"] for r in rows})
estimators = sorted({r["estimator"] for r in rows})
assert set(estimators) == {"opf", "pf", "cvkf", "imm", "oapf"}, estimators
for r in rows:
    for metric in ("hidden_translation", "nees_translation", "inside95_translation"):
        value = float(r[metric])
        assert value >= 0 and not math.isnan(value), (r["sequence"], r["estimator"], metric, value)
for kind in kinds:
    assert os.path.getsize(os.path.join(out, f"hidden_error_{kind}.png")) > 10000, kind
    assert "<svg" in open(os.path.join(out, f"hidden_error_{kind}.svg")).read(2000), kind
print(f"benchmark subset: {len(rows)} rows, kinds {' '.join(kinds)}, identical twice")
PY
