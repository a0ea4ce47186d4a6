#!/usr/bin/env bash
# The scripts that replace parts of an output folder (scripts/make_small_results.sh,
# paper/build_report.sh) leave alone what they did not make: a folder of the user's own with one
# of their names is refused (exit 2, named) and kept byte for byte; after a run of theirs has
# stamped the folder, the same names are replaced. `false` stands in for the programs they run,
# so that no result is computed: a run that passed the check fails at its first step (exit 1).
#   bash keep_what_they_did_not_make.sh REPO
set -euo pipefail
repo="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

expect_refusal() {  # SCRIPT OUT NAME: the user's OUT/NAME/mine.txt survives, and is named
  local script="$1" out="$2" name="$3" rc=0
  mkdir -p "$out/$name"
  echo "the user's own" >"$out/$name/mine.txt"
  OPF=false OPF_RESULTS="$work/none" bash "$repo/$script" "$out" 2>"$work/stderr" || rc=$?
  [ "$rc" -eq 2 ] || { echo "$script over a folder of the user's: exit $rc, not 2" >&2; exit 1; }
  grep -q "'$out/$name' exists and this script did not make it" "$work/stderr" ||
    { echo "$script does not name $out/$name:" >&2; cat "$work/stderr" >&2; exit 1; }
  [ "$(cat "$out/$name/mine.txt")" = "the user's own" ] ||
    { echo "$script changed $out/$name/mine.txt" >&2; exit 1; }
}

# make_small_results.sh: each folder it replaces, and a log it writes over.
for name in results sweeps dynamics_ablation; do
  expect_refusal scripts/make_small_results.sh "$work/small_$name" "$name"
done
mkdir -p "$work/small_log"
echo "the user's own" >"$work/small_log/general_op.log"
rc=0
OPF=false bash "$repo/scripts/make_small_results.sh" "$work/small_log" 2>/dev/null || rc=$?
[ "$rc" -eq 2 ] && [ "$(cat "$work/small_log/general_op.log")" = "the user's own" ] ||
  { echo "make_small_results.sh wrote over a log of the user's (exit $rc)" >&2; exit 1; }

# Stamped by a run of its own, the folder's results/ is replaced: the run gets past the check and
# fails at its first `opf run` (false), with the old results/ gone.
out="$work/stamped"
mkdir -p "$out/results"
echo old >"$out/results/old.txt"
: >"$out/.made-by-make_small_results"
rc=0
OPF=false bash "$repo/scripts/make_small_results.sh" "$out" 2>/dev/null || rc=$?
[ "$rc" -eq 1 ] && [ ! -e "$out/results/old.txt" ] ||
  { echo "make_small_results.sh did not replace its own results/ (exit $rc)" >&2; exit 1; }

# build_report.sh: its generated tables and figures, and the LaTeX source it copies.
expect_refusal paper/build_report.sh "$work/report_generated" generated
mkdir -p "$work/report_tex"
echo "the user's own" >"$work/report_tex/report.tex"
rc=0
bash "$repo/paper/build_report.sh" "$work/report_tex" 2>/dev/null || rc=$?
[ "$rc" -eq 2 ] && [ "$(cat "$work/report_tex/report.tex")" = "the user's own" ] ||
  { echo "build_report.sh wrote over a report.tex of the user's (exit $rc)" >&2; exit 1; }

echo "output folders: the user's own kept, 5 refusals, a stamped folder replaced"
