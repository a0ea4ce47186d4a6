#!/usr/bin/env bash
# Builds the reproduction report: generates its tables and figures from result files
# (paper/make_report.py), then the PDF with latexmk (IEEEtran, Debian's TeX Live).
#   bash paper/build_report.sh [OUT]          # from results/ (with its real_motion/,
#                                             # dynamics_ablation/, hand_scenes/ and twin_mugs/),
#                                             # results/sweeps/ and the benchmark report; OUT
#                                             # defaults to results/report
# OPF_RESULTS, OPF_SWEEPS, OPF_DYNAMICS_ABLATION and OPF_BENCH override the inputs (the tests point
# them at the small result sets of scripts/make_small_results.sh). A section whose results are
# not there is left out, and a last paragraph names the command that makes it. Writes
# OUT/report.pdf; replaces OUT/generated, report.tex and LaTeX's files if an earlier run made them
# (anything else of those names is left alone: exit 2).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$repo/results/report}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
source "$repo/scripts/output_folder_guard.sh"
# A report folder made before the stamp existed (results/report of an earlier main job) is known
# by the table of contents make_report.py always writes.
[ -f "$out/generated/contents.tex" ] && : >>"$out/.made-by-build_report"
refuse_unless_made_here "$out" .made-by-build_report generated report.tex report.pdf report.aux \
  report.log report.fls report.fdb_latexmk latexmk.log
rm -rf "$out/generated"
/usr/bin/python3 "$repo/paper/make_report.py" "$out/generated"
cp "$repo/paper/report.tex" "$out/report.tex"
cd "$out"
if ! latexmk -pdf -interaction=nonstopmode -halt-on-error report.tex >latexmk.log 2>&1; then
  tail -n 30 latexmk.log >&2
  echo "latexmk failed; the whole log is $out/latexmk.log" >&2
  exit 1
fi
echo "report: $out/report.pdf"
