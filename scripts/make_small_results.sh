#!/usr/bin/env bash
# Small result sets for executing the notebooks and building the report in the tests (about 30 s
# on 2 cores): OUT/results holds `opf run` outputs for the first 150 frames of general_op and
# sugar_drop (OPF and PF, 2 seeds, 300 particles; the ball is covered and carried), OUT/sweeps
# the sweeps of notebooks/small_sweeps/, OUT/dynamics_ablation the real-motion ablation's subset
# (experiments/real_motion/run_ablation.py --subset). All are replaced, with their logs in OUT,
# if an earlier run of this script made them; anything else of those names is left alone (exit 2).
#   bash scripts/make_small_results.sh OUT        (OPF=path/to/opf overrides build/bin/opf)
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: $0 OUT" >&2; exit 2; }
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
opf="${OPF:-$repo/build/bin/opf}"
out="$(mkdir -p "$1" && cd "$1" && pwd)"
source "$repo/scripts/output_folder_guard.sh"
sweep_logs=()
for sweep in "$repo"/notebooks/small_sweeps/*.yaml; do
  sweep_logs+=("sweep_$(basename "$sweep" .yaml).log")
done
refuse_unless_made_here "$out" .made-by-make_small_results results sweeps dynamics_ablation \
  general_op.log sugar_drop.log dynamics_ablation.log "${sweep_logs[@]}"
rm -rf "$out/results" "$out/sweeps" "$out/dynamics_ablation"  # sweeps resume: start from nothing
for experiment in general_op sugar_drop; do
  "$opf" run "$repo/experiments/$experiment.yaml" --estimators opf,pf --seeds 2 --particles 300 \
    --frames 150 --out "$out/results" >"$out/$experiment.log" 2>&1
done
for sweep in "$repo"/notebooks/small_sweeps/*.yaml; do
  name="$(basename "$sweep" .yaml)"
  "$opf" sweep "$sweep" --out "$out/sweeps/$name" >"$out/sweep_$name.log" 2>&1
done
# The dynamics ablation's subset (one log per kind, the full bank and one model removed).
/usr/bin/python3 "$repo/experiments/real_motion/run_ablation.py" "$out/dynamics_ablation" --subset \
  --no-video --opf "$opf" >"$out/dynamics_ablation.log" 2>&1
echo "small results in $out/results, $out/sweeps and $out/dynamics_ablation"
