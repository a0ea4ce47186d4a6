#!/usr/bin/env bash
# Table I and the baseball throw with the toolkit's defaults (the embedded experiment files, 5
# runs each, 5000 + 5000 particles), as the main job runs them with --seed 1 and with three more
# seeds. Each seed's mean translation error of the OPF is bounded: baseball within the paper's
# 0.01 m; general_op (paper 0.0114 m) within 0.7x of the paper's (measured 0.42-0.48x over these
# seeds; 1.17-1.18x with the detections' stated extra noise ignored, opf.detector_noise: false);
# sugar_drop (paper 0.0213 m, the cube landing in the moving mug) within 0.5x (measured
# 0.38-0.44x; 1.22-3.28x with it ignored), with the cube in the mug in at least 4 of 5 runs
# (measured 5).
#   bash table_one_defaults.sh OPF_BINARY WORK_DIR
set -euo pipefail
opf="$1"
out="$2"
rm -rf "$out"
for seed in 1 2 3 4; do
  "$opf" reproduce --estimators opf --seed "$seed" --quiet --out "$out/seed_$seed" >/dev/null
done
/usr/bin/python3 - "$out" <<'PY'
import csv, pathlib, sys
out = pathlib.Path(sys.argv[1])
bounds = {"general_op": 0.7 * 0.0114, "sugar_drop": 0.5 * 0.0213, "baseball": 0.01}
failed = []
for seed in (1, 2, 3, 4):
    for experiment, bound in bounds.items():
        path = out / f"seed_{seed}" / f"{experiment}_runs.csv"
        runs = [r for r in csv.DictReader(path.open()) if r["estimator"] == "opf"]
        if len(runs) != 5:
            failed.append(f"seed {seed}, {experiment}: {len(runs)} runs of the OPF, expected 5")
            continue
        mean = sum(float(r["translation_error"]) for r in runs) / len(runs)
        line = f"seed {seed}, {experiment}: OPF translation error {mean:.4f} m (bound {bound:.4f})"
        if not mean <= bound:
            failed.append(f"seed {seed}, {experiment}: {mean:.4f} m > {bound:.4f} m")
        if experiment == "sugar_drop":
            landed = sum(int(r["payload_landed"]) for r in runs)
            line += f", cube in the mug in {landed} of 5"
            if landed < 4:
                failed.append(f"seed {seed}, sugar_drop: the cube in the mug in {landed} of 5")
        print(line)
if failed:
    sys.exit("table I with defaults: " + "; ".join(failed))
print("table I with defaults: baseball within the paper's error, general_op within 0.7x, "
      "sugar_drop within 0.5x with the cube in the mug")
PY
