#!/usr/bin/env bash
# The real-video benchmark script on one clip (box.mp4 from opencv-doc), one seed, three
# placements of the dropout windows: the detections, both dropped logs, one phases.csv row per
# dropout, placement and estimator, the first placement equal to the main table's run (same
# windows, same seed), the other placements shifted by period / 3, and the placements' table;
# then the same clip thinned to one frame in three (EVERY=3) with other dropout lengths
# (DROPOUTS), and EVERY=0 and a dropout longer than the period refused; the paper's
# preset (PRESET=paper) and a settings file (CONFIG) passed to every evaluation, bad ones refused.
#   bash tests/real_video/benchmark_script.sh SOURCE_DIR OPF
set -euo pipefail
source_dir="$1"
opf="$2"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
OPF="$opf" CLIPS=box SEEDS=1 ESTIMATORS=opf,cvkf PHASES=3 \
  bash "$source_dir/experiments/real_video/run_real_video.sh" "$out" >"$out/run.log" 2>&1 ||
  { cat "$out/run.log" >&2; exit 1; }
fail() { echo "benchmark script: $*" >&2; exit 1; }
for f in box.csv box_0.3.csv box_0.6.csv phases.csv table.md; do
  [ -s "$out/$f" ] || fail "no $f"
done
rows="$(($(wc -l <"$out/phases.csv") - 1))"
[ "$rows" -eq 12 ] || fail "phases.csv has $rows rows, expected 2 dropouts x 3 placements x 2 estimators"
# The placements start 1 s after the track begins, then every 2 s / 3 later.
starts="$(awk -F, 'NR > 1 && $5 == "opf" && $2 == "0.3" { printf "%s ", $4 }' "$out/phases.csv")"
t0="$(awk -F, 'NR == 2 { print $1; exit }' "$out/box.csv")"
expected="$(awk -v t="$t0" 'BEGIN { for (k = 0; k < 3; k++) printf "%.9g ", t + 1 + k * 2 / 3 }')"
[ "$starts" = "$expected" ] || fail "placements start at '$starts', expected '$expected'"
# The first placement is the main table's run: the same hidden error, printed to 5 decimals.
for estimator in opf cvkf; do
  main="$(awk -v e="$estimator" '$1 == e && NF == 7 { print $2 }' "$out/box_0.3.txt")"
  phase0="$(awk -F, -v e="$estimator" 'NR > 1 && $2 == "0.3" && $3 == 0 && $5 == e {
    printf "%.5f", $6 }' "$out/phases.csv")"
  if [ -z "$main" ] || [ "$main" != "$phase0" ]; then
    fail "$estimator: first placement $phase0, main table $main"
  fi
done
grep -q '^## Hidden translation error \[m\] over 3 placements' "$out/table.md" ||
  fail "no placements table in table.md"
row="$(grep -E '^\| box \| 0\.6 s \| [0-9.]+ \| [0-9.]+ \| [0-3] of 3 \| [-+][0-9.]+ ± [0-9.]+ \(cvkf\) \|$' \
  "$out/table.md")" || fail "no box 0.6 s row in the placements table"
# Its paired difference: the mean over the placements of the OPF's error minus the Kalman
# filter's, in mm.
paired="$(awk -F, 'NR > 1 && $2 == "0.6" { e[$3, $5] = $6; n[$3] = 1 }
  END { for (k in n) { s += e[k, "opf"] - e[k, "cvkf"]; c++ } printf "%+.2f", 1000 * s / c }' \
  "$out/phases.csv")"
[[ "$row" == *"| $paired ± "* ]] || fail "paired difference: row '$row', from phases.csv $paired"
# A slower log of the same motion (EVERY=3): one frame in three of the detections, the first
# kept, so 152 of box.mp4's 455 frames at 3 frame intervals; with the dropout lengths asked for
# (DROPOUTS), and only those.
slow="$out/every3"
OPF="$opf" CLIPS=box SEEDS=1 ESTIMATORS=opf PHASES=0 EVERY=3 DROPOUTS="0.6 1.5" \
  bash "$source_dir/experiments/real_video/run_real_video.sh" "$slow" >"$out/every3.log" 2>&1 ||
  { cat "$out/every3.log" >&2; exit 1; }
kept="$(($(wc -l <"$slow/box.csv") - 1))"
[ "$kept" -eq 152 ] || fail "EVERY=3 kept $kept rows of box.csv, expected 152"
awk -F, 'NR == FNR { if (FNR > 1) full[FNR - 2] = $1; next }
  FNR > 1 && $1 != full[3 * (FNR - 2)] { bad = 1 } END { exit bad }' "$out/box.csv" "$slow/box.csv" ||
  fail "EVERY=3 did not keep frames 0, 3, 6, ..."
grep -q "kept one frame in 3 of the detections" "$slow/table.md" || fail "EVERY=3 not in table.md"
[ -s "$slow/box_0.6.txt" ] || fail "EVERY=3: no evaluation"
[ -s "$slow/box_1.5.txt" ] || fail "DROPOUTS=\"0.6 1.5\": no evaluation of 1.5 s"
[ ! -e "$slow/box_0.3.csv" ] || fail "DROPOUTS=\"0.6 1.5\": 0.3 s ran too"
grep -q "| box | 1.5 s | opf |" "$slow/table.md" || fail "DROPOUTS: no 1.5 s row in table.md"
if DROPOUTS="0.3 2.5" OPF="$opf" bash "$source_dir/experiments/real_video/run_real_video.sh" \
  "$out/bad" 2>"$out/bad.log"; then
  fail "DROPOUTS=2.5 accepted"
fi
grep -q "DROPOUTS: '2.5' is not a length in seconds between 0 and 2" "$out/bad.log" ||
  fail "DROPOUTS=2.5: no clear error"
if EVERY=0 OPF="$opf" bash "$source_dir/experiments/real_video/run_real_video.sh" "$out/bad" \
  2>"$out/bad.log"; then
  fail "EVERY=0 accepted"
fi
grep -q "EVERY must be a positive integer" "$out/bad.log" || fail "EVERY=0: no clear error"
# The paper's literal rules (PRESET=paper) reach every evaluation: the OPF's row differs from the
# defaults' (the baselines have no paper-specific settings), and table.md says which ran.
paper="$out/paper"
OPF="$opf" CLIPS=box SEEDS=1 ESTIMATORS=opf,cvkf PHASES=0 PRESET=paper \
  bash "$source_dir/experiments/real_video/run_real_video.sh" "$paper" >"$out/paper.log" 2>&1 ||
  { cat "$out/paper.log" >&2; exit 1; }
hidden() { awk -v e="$2" '$1 == e && NF == 7 { print $2 }' "$1"; }
for f in "$paper/box_0.3.txt" "$out/box_0.3.txt"; do
  if [ -z "$(hidden "$f" opf)" ] || [ -z "$(hidden "$f" cvkf)" ]; then fail "no hidden errors in $f"; fi
done
[ "$(hidden "$paper/box_0.3.txt" opf)" != "$(hidden "$out/box_0.3.txt" opf)" ] ||
  fail "PRESET=paper: the OPF's hidden error is the defaults' ($(hidden "$out/box_0.3.txt" opf))"
[ "$(hidden "$paper/box_0.3.txt" cvkf)" = "$(hidden "$out/box_0.3.txt" cvkf)" ] ||
  fail "PRESET=paper changed the Kalman filter's row"
grep -qF "Settings: \`--preset paper\`" "$paper/table.md" || fail "PRESET=paper not in table.md"
# A settings file (CONFIG) reaches them too: a misspelt key fails naming the file and the key.
printf 'opf:\n  adaptive_translation_nois: true\n' >"$out/typo.yaml"
if OPF="$opf" CLIPS=box SEEDS=1 ESTIMATORS=opf PHASES=0 CONFIG="$out/typo.yaml" \
  bash "$source_dir/experiments/real_video/run_real_video.sh" "$out/typo" >"$out/typo.log" 2>&1; then
  fail "CONFIG with a misspelt key accepted"
fi
grep -q "typo.yaml:2.*adaptive_translation_nois" "$out/typo.log" ||
  { cat "$out/typo.log" >&2; fail "CONFIG: no error naming the file, line and key"; }
# Bad values of PRESET and CONFIG are refused before anything runs.
for bad in "PRESET=papers" "CONFIG=$out/no_such.yaml"; do
  if env "$bad" OPF="$opf" bash "$source_dir/experiments/real_video/run_real_video.sh" "$out/bad2" \
    2>"$out/bad2.log"; then
    fail "$bad accepted"
  fi
  grep -qE "PRESET must be default or paper|CONFIG: no readable file" "$out/bad2.log" ||
    fail "$bad: no clear error"
  [ ! -e "$out/bad2/box.csv" ] || fail "$bad: ran before refusing"
done
echo "real-video benchmark script: $rows placement rows, first placement = main run; EVERY=3 kept 152 frames; PRESET and CONFIG reach every evaluation"
