#!/usr/bin/env bash
# The dynamics ablation's subset end to end: the full bank and one model removed on one log per
# kind; every log scored under both variants, the ratios over cvkf finite, the table and the
# figure written.
# Usage: ablation_subset.sh REPO OPF WORK_DIR
set -euo pipefail
repo="$1" opf="$2" work="$3"
rm -rf "$work"
/usr/bin/python3 "$repo/experiments/real_motion/run_ablation.py" "$work" --subset --opf "$opf" \
  >"$work.log" 2>&1 || { cat "$work.log"; exit 1; }
cat "$work.log"
/usr/bin/python3 - "$work" <<'PY'
import csv, math, os, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "ablation.csv"))))
variants = sorted({r["variant"] for r in rows})
assert variants == ["full bank", "without position"], variants
logs = {(r["sequence"], r["rate"], r["gap"]) for r in rows}
assert len(rows) == 2 * len(logs) and len(logs) >= 4, (len(rows), len(logs))
for r in rows:
    ratio = float(r["hidden_translation_over_cvkf"])
    assert ratio > 0 and math.isfinite(ratio), (r["variant"], r["sequence"], ratio)
table = open(os.path.join(out, "ablation.md")).read()
assert "| full bank |" in table and "| without position |" in table, table
assert os.path.getsize(os.path.join(out, "ablation.png")) > 10000
assert "<svg" in open(os.path.join(out, "ablation.svg")).read(2000)
print(f"ablation subset: {len(logs)} logs, variants {', '.join(variants)}")
PY
