#!/usr/bin/env python3
"""Two runs of the real-motion benchmark side by side: is a change better, or better somewhere?

Reads results.csv and profile.csv of two run_benchmark.py output directories (a base and a
change, the same logs and seeds) and prints, for one estimator and preset:

  - each run's summary (hidden error over cvkf's, geometric mean; worst row; rotation; the
    calibration pooled over the hidden frames), as run_benchmark.py computes it;
  - the geometric mean per kind of motion, base and change;
  - every row whose ratio moved by more than --moved (default 5%), largest first;
  - the change's factor on the geometric mean, log by log, with its 95% interval over resampled
    recordings (run_benchmark.py's cluster bootstrap): an interval that spans 1 says the change
    is within what the choice of recordings moves;
  - the verdict: the change is taken only when the mean improves, no row goes above the worst
    allowed (1.10x cvkf) that was not there before, and the calibration stays within its bounds
    (NEES / 3 in [0.5, 2], 85-98% of hidden frames inside the 95% ellipsoid). A change that helps
    some logs and hurts the mean is not taken.

Exit status: 0 when the change is taken, 1 when it is not, 2 on bad input.

Usage: compare_runs.py BASE_DIR CHANGE_DIR [--estimator opf] [--preset default] [--moved 0.05]
"""

import argparse
import csv
import importlib.util
import math
import os
import sys
from collections import defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location("run_benchmark",
                                               os.path.join(HERE, "run_benchmark.py"))
bench = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(bench)

WORST_ALLOWED = 1.10  # x cvkf, on any row
NEES_BOUNDS = (0.5, 2.0)  # NEES / dimension, pooled
INSIDE_BOUNDS = (0.85, 0.98)  # share of hidden frames inside the 95% ellipsoid, pooled
TEXT_COLUMNS = ("sequence", "kind", "rate", "gap", "preset", "estimator")


def read_table(path):
    """The rows of a benchmark CSV, numbers as floats; ValueError naming the file and line."""
    if not os.path.isfile(path):
        raise ValueError(f"{path}: no such file (a run_benchmark.py output directory holds "
                         "results.csv and profile.csv)")
    rows = []
    with open(path, newline="") as f:
        for line, raw in enumerate(csv.DictReader(f), start=2):
            row = {}
            for key, text in raw.items():
                if key in TEXT_COLUMNS:
                    row[key] = text
                    continue
                try:
                    row[key] = int(text) if key == "frames" else bench.number(text)
                except (TypeError, ValueError):
                    raise ValueError(f"{path}:{line}: column {key}: not a number: {text!r}")
            rows.append(row)
    return rows


def load(directory):
    rows = read_table(os.path.join(directory, "results.csv"))
    bins = read_table(os.path.join(directory, "profile.csv"))
    return rows, bins


def ratios(rows, estimator, preset):
    """Per log (sequence, rate, gap): (kind, hidden error over the reference's)."""
    by_log = defaultdict(dict)
    for r in rows:
        by_log[(r["sequence"], r["rate"], r["gap"])][(r["estimator"], r["preset"])] = r
    out = {}
    for log, runs in by_log.items():
        mine, ref = runs.get((estimator, preset)), runs.get(bench.REFERENCE)
        if mine and ref and ref["hidden_translation"] > 0:
            out[log] = (mine["kind"], mine["hidden_translation"] / ref["hidden_translation"])
    return out


def summary_of(rows, bins, estimator, preset):
    for s in bench.summarise(rows, bins):
        if (s["estimator"], s["preset"]) == (estimator, preset):
            return s
    return None


def calibrated(s):
    return (NEES_BOUNDS[0] <= s["nees_translation"] <= NEES_BOUNDS[1]
            and INSIDE_BOUNDS[0] <= s["inside95_translation"] <= INSIDE_BOUNDS[1])


def summary_line(name, s):
    return (f"{name}: hidden error / cvkf {s['hidden_ratio']:.3f} (geometric mean over "
            f"{s['rows']} logs), worst {s['worst']:.3f} ({s['worst_row']}), rotation "
            f"{s['rotation_ratio']:.3f}, position NEES/3 {s['nees_translation']:.3g} with "
            f"{bench.percent(s['inside95_translation'])} inside 95%")


def change_factor_line(rb, rc, common):
    """The change's factor on the geometric mean, with its interval over resampled recordings:
    paired, log by log, so what the logs share (their difficulty) cancels out."""
    factors = {log: rc[log][1] / rb[log][1] for log in common}
    draws = bench.bootstrap_draws({bench.recording(log[0]) for log in common})
    low, high = bench.geometric_mean_interval(factors, draws)
    factor = bench.geometric_mean(factors.values())
    if math.isnan(low):
        return f"change / base: {factor:.3f}"
    holds = ("below 1: better on resampled suites" if high < 1.0 else
             "above 1: worse on resampled suites" if low > 1.0 else
             "it spans 1: within what the choice of recordings moves")
    return (f"change / base: {factor:.3f} (geometric mean over {len(common)} logs; "
            f"{100 * bench.INTERVAL_LEVEL:.0f}% interval over resampled recordings "
            f"{low:.3f}-{high:.3f}, {holds})")


def compare(base, change, estimator, preset, moved):
    """The report's lines and whether the change is taken."""
    sb, sc = summary_of(*base, estimator, preset), summary_of(*change, estimator, preset)
    if sb is None or sc is None:
        missing = "base" if sb is None else "change"
        raise ValueError(f"the {missing} run has no rows of {estimator} ({preset}) beside "
                         f"{bench.REFERENCE[0]} ({bench.REFERENCE[1]})")
    rb, rc = ratios(base[0], estimator, preset), ratios(change[0], estimator, preset)
    common = sorted(set(rb) & set(rc))
    if not common:
        raise ValueError("the two runs share no log")
    lines = [summary_line("base  ", sb), summary_line("change", sc), "",
             "kind        base    change"]
    kinds = sorted({rb[log][0] for log in common})
    for kind in kinds:
        logs = [log for log in common if rb[log][0] == kind]
        lines.append(f"{kind:<10} {bench.geometric_mean([rb[l][1] for l in logs]):6.3f}  "
                     f"{bench.geometric_mean([rc[l][1] for l in logs]):6.3f}")
    shifts = sorted(((rc[l][1] / rb[l][1], l) for l in common), key=lambda x: -abs(math.log(x[0])))
    shifted = [(s, l) for s, l in shifts if abs(s - 1.0) > moved]
    lines += ["", f"rows moved by more than {100 * moved:.0f}%: {len(shifted)} of {len(common)}"]
    lines += [f"  {'/'.join(l)}: {rb[l][1]:.3f} -> {rc[l][1]:.3f}" for s, l in shifted]
    lines += ["", change_factor_line(rb, rc, common)]
    new_over = [l for l in common if rc[l][1] > WORST_ALLOWED >= rb[l][1]]
    mean_better = (bench.geometric_mean([rc[l][1] for l in common])
                   < bench.geometric_mean([rb[l][1] for l in common]))
    reasons = []
    if not mean_better:
        reasons.append("the mean is not better")
    if new_over:
        reasons.append(f"{len(new_over)} row(s) newly above {WORST_ALLOWED:.2f}x cvkf: " +
                       ", ".join(f"{'/'.join(l)} {rc[l][1]:.3f}" for l in new_over))
    if calibrated(sb) and not calibrated(sc):
        reasons.append("the calibration leaves its bounds (NEES/3 0.5-2, 85-98% inside)")
    taken = not reasons
    lines += ["", "verdict: taken" if taken else "verdict: not taken: " + "; ".join(reasons)]
    return lines, taken


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("base", help="run_benchmark.py output directory of the base")
    parser.add_argument("change", help="run_benchmark.py output directory of the change")
    parser.add_argument("--estimator", default="opf")
    parser.add_argument("--preset", default="default", choices=bench.PRESETS)
    parser.add_argument("--moved", type=float, default=0.05,
                        help="list rows whose ratio moved by more than this share (default 0.05)")
    args = parser.parse_args()
    try:
        lines, taken = compare(load(args.base), load(args.change), args.estimator, args.preset,
                               args.moved)
    except ValueError as error:
        print(f"compare_runs: {error}", file=sys.stderr)
        return 2
    print("\n".join(lines))
    return 0 if taken else 1


if __name__ == "__main__":
    sys.exit(main())
