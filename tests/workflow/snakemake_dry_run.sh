#!/usr/bin/env bash
# Dry runs of the Snakemake workflow (workflow/Snakefile) from the repository root, with each of
# its profiles (no sbatch needed: a dry run submits nothing):
#   1. workflow/profiles/slurm on the config's default sweep (workflow/config.yaml: smoke);
#   2. workflow/profiles/local on another sweep, given with --config (kappa).
# Each must plan one `run` job per run of `opf sweep SWEEP --plan`, one `table` and one `all`,
# every job but `all` with its mem_mb and runtime.
#   bash tests/workflow/snakemake_dry_run.sh REPO_ROOT OPF
set -euo pipefail
shopt -s inherit_errexit  # a failed check inside $(...) fails the script too

fail() {
  echo "snakemake dry run: $*" >&2
  exit 1
}

[ $# -eq 2 ] || { echo "usage: $0 REPO_ROOT OPF" >&2; exit 2; }
[ -f "$1/workflow/Snakefile" ] || fail "no $1/workflow/Snakefile"
[ -x "$2" ] || fail "$2 is not an executable opf"
repo="$(cd "$1" && pwd)"
opf="$(realpath "$2")"
cd "$repo"
scratch="$(mktemp -d "${TMPDIR:-/tmp}/opf_snakemake_dry_run.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT

# The number of runs in SWEEP's plan.
planned_runs() {
  "$opf" sweep "$1" --plan --out "$scratch/plan" >"$scratch/plan.json" ||
    fail "opf sweep $1 --plan failed"
  python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["runs"]))' \
    "$scratch/plan.json"
}

# The count of rule $2 in the "Job stats" table of dry-run output $1 (empty when absent).
job_count() {
  awk -v rule="$2" '/^Job stats:/ { stats = 1 } stats && $1 == rule { print $2; exit }' "$1"
}

# dry_run NAME PROFILE SWEEP_FILE [--config arguments]: checks the planned jobs; prints the total.
dry_run() {
  local name="$1" profile="$2" sweep="$3" log="$scratch/$1.log"
  shift 3
  local runs
  runs="$(planned_runs "$sweep")"
  [ "$runs" -gt 0 ] || fail "$name: $sweep plans no runs"
  # A failed check shows Snakemake's output, then why.
  fail_showing_log() {
    cat "$log" >&2
    fail "$@"
  }
  snakemake -n --nolock --profile "$profile" \
    --config opf="$opf" out="$scratch/$name" "$@" >"$log" 2>&1 ||
    fail_showing_log "$name: snakemake -n --profile $profile failed"
  grep -q "This was a dry-run" "$log" || fail_showing_log "$name: not a dry run"
  [ "$(job_count "$log" run)" = "$runs" ] ||
    fail_showing_log "$name: $(job_count "$log" run) run jobs, expected $runs (the plan's runs)"
  [ "$(job_count "$log" table)" = 1 ] || fail_showing_log "$name: expected one table job"
  [ "$(job_count "$log" all)" = 1 ] || fail_showing_log "$name: expected one all job"
  local total=$((runs + 2))
  [ "$(job_count "$log" total)" = "$total" ] ||
    fail_showing_log "$name: $(job_count "$log" total) jobs in all, expected $total"
  local with_resources
  with_resources="$(awk '/^ +resources:/ && /mem_mb=[0-9]/ && /runtime=[0-9]/ { n++ }
                         END { print n + 0 }' "$log")"
  [ "$with_resources" = $((runs + 1)) ] ||
    fail_showing_log "$name: $with_resources jobs with mem_mb and runtime, expected $((runs + 1))"
  echo "$total"
}

slurm_jobs="$(dry_run slurm workflow/profiles/slurm experiments/sweeps/smoke.yaml)"
local_jobs="$(dry_run local workflow/profiles/local experiments/sweeps/kappa.yaml \
  sweep=experiments/sweeps/kappa.yaml)"
echo "snakemake dry runs: slurm $slurm_jobs jobs, local $local_jobs jobs"
