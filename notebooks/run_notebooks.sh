#!/usr/bin/env bash
# Executes the notebooks headless with Debian's Jupyter against result files and writes the
# executed copies to OUT (the notebooks in the repository stay without outputs).
#   bash notebooks/run_notebooks.sh [OUT]          # reads results/ (scripts/run_main.sh) and
#                                                  # results/sweeps/ (opf sweep); OUT defaults to
#                                                  # results/notebooks
#   bash notebooks/run_notebooks.sh --small OUT    # first writes small result sets to OUT: the
#                                                  # first 150 frames of general_op and sugar_drop
#                                                  # and notebooks/small_sweeps/ (CI; about a minute;
#                                                  # OUT/results and OUT/sweeps are replaced)
# OPF=path/to/opf overrides build/bin/opf; OPF_RESULTS, OPF_SWEEPS and OPF_BENCH the inputs.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
opf="${OPF:-$repo/build/bin/opf}"
if [ "${1:-}" = "--small" ]; then
  [ $# -eq 2 ] || { echo "usage: $0 --small OUT" >&2; exit 2; }
  out="$(mkdir -p "$2" && cd "$2" && pwd)"
  export OPF_RESULTS="$out/results" OPF_SWEEPS="$out/sweeps"
  rm -rf "$OPF_RESULTS" "$OPF_SWEEPS"  # sweeps resume: start from nothing
  for experiment in general_op sugar_drop; do
    "$opf" run "$repo/experiments/$experiment.yaml" --estimators opf,pf --seeds 2 \
      --particles 300 --frames 150 --out "$OPF_RESULTS" >"$out/$experiment.log" 2>&1
  done
  for sweep in "$repo"/notebooks/small_sweeps/*.yaml; do
    name="$(basename "$sweep" .yaml)"
    "$opf" sweep "$sweep" --out "$OPF_SWEEPS/$name" >"$out/sweep_$name.log" 2>&1
  done
else
  out="${1:-$repo/results/notebooks}"
  mkdir -p "$out"
fi
export PYDEVD_DISABLE_FILE_VALIDATION=1  # the kernel's debugger notes about frozen modules
for notebook in reproduce_paper ablations particle_counts; do
  /usr/bin/jupyter nbconvert --to notebook --execute --ExecutePreprocessor.timeout=600 \
    --output-dir "$out" "$repo/notebooks/$notebook.ipynb"
done
echo "executed notebooks in $out"
