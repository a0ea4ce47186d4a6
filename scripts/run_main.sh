#!/usr/bin/env bash
# Quick-start command 1: set up, then run the main job: reproduce the paper's simulated
# experiments (every estimator, 5 seeds, 5000 + 5000 particles), print Table I beside the paper's
# numbers and write per-frame CSVs, summary.json and figures under results/; then the real-video
# benchmark (OpenCV's sample clips through `opf detect`, with dropouts) into results/real_video/;
# then the real-motion benchmark (public recordings and the clips, every estimator under both
# presets, 3 seeds: about two minutes on 2 cores) into results/real_motion/; the dynamics
# module's ablation on it (each motion model removed in turn, about two minutes) into
# results/dynamics_ablation/; the hand scenes (a hand on recorded human motion carries a cube or
# passes over it, and two such hands play the cups game, every estimator, 5 seeds, about 75 s)
# into results/hand_scenes/; then the
# notebooks executed against these results into results/notebooks/ (.ipynb and .html; about
# 30 s; the sweeps, not run here, are skipped there with the command that runs them); last, the
# reproduction report from these results, results/report/report.pdf (paper/build_report.sh;
# what has not run, such as the sweeps, is left out of it with the command that makes it).
# Extra arguments go to `opf reproduce` (see `build/bin/opf reproduce --help`).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$repo/scripts/setup.sh"
"$repo/build/bin/opf" reproduce --out "$repo/results" "$@"
echo
# The tie (two equally likely occluders, one hypothesis each): hypothesis rows and a top view.
"$repo/build/bin/opf" run "$repo/experiments/twin_mugs.yaml" --estimators opf,pf,cvkf \
  --out "$repo/results/twin_mugs" "$@"
echo
OPF="$repo/build/bin/opf" bash "$repo/experiments/real_video/run_real_video.sh" \
  "$repo/results/real_video"
cat "$repo/results/real_video/table.md"
echo
/usr/bin/python3 "$repo/experiments/real_motion/run_benchmark.py" "$repo/results/real_motion" \
  --opf "$repo/build/bin/opf"
echo
/usr/bin/python3 "$repo/experiments/real_motion/run_ablation.py" \
  "$repo/results/dynamics_ablation" --opf "$repo/build/bin/opf"
echo
/usr/bin/python3 "$repo/experiments/real_motion/hand_scenes.py" "$repo/results/hand_scenes" \
  --opf "$repo/build/bin/opf"
echo
bash "$repo/notebooks/run_notebooks.sh" "$repo/results/notebooks"
echo
bash "$repo/paper/build_report.sh" "$repo/results/report"
