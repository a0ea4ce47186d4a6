#!/bin/bash
# The cost-versus-accuracy trade-off over particle counts: general_op's translation and geodesic
# rotation errors (mean over frames and 5 seeds, objects of interest) for the OPF and the PF at
# each N, beside the step time the benchmark measured for that N (pass the JSON of
# bench/run_benchmarks.sh).
#   bash bench/accuracy_vs_particles.sh [BENCH.json]   (writes a Markdown table to stdout)
set -euo pipefail
cd "$(dirname "$0")/.."
bench_json="${1:-}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
counts=(100 300 1000 3000 5000 10000 30000)
for n in "${counts[@]}"; do
  build/bin/opf run experiments/general_op.yaml --estimators opf,pf --particles "$n" --seeds 5 \
    --out "$work/$n" >/dev/null 2>&1
done
/usr/bin/python3 - "$work" "$bench_json" "${counts[@]}" <<'PY'
import json, sys
work, bench, counts = sys.argv[1], sys.argv[2], sys.argv[3:]
steps = {}
if bench:
    for b in json.load(open(bench))["benchmarks"]:
        if b.get("aggregate_name") == "median" and b["run_name"].startswith("BM_EstimatorStep/opf/n:"):
            steps[b["run_name"].split(":")[-1]] = b["real_time"] * {"us": 1, "ms": 1e3, "ns": 1e-3}[b["time_unit"]]
print("| particles per portion | OPF translation [m] | PF translation [m] | OPF rotation [rad] "
      "| PF rotation [rad] | OPF step [us] |")
print("|---:|---:|---:|---:|---:|---:|")
cell = lambda v: f"{v['mean']:.4f} +- {v['std']:.4f}"
for n in counts:
    e = json.load(open(f"{work}/{n}/summary.json"))["experiments"]["general_op"]
    o, p = e["opf"], e["pf"]
    step = f"{steps[n]:.1f}" if n in steps else "-"
    print(f"| {n} | {cell(o['translation_error'])} | {cell(p['translation_error'])} "
          f"| {cell(o['rotation_error_geodesic'])} | {cell(p['rotation_error_geodesic'])} | {step} |")
PY
