#!/usr/bin/env python3
"""The dynamics module's ablation on the real-motion benchmark: the OPF with its full bank of
motion models, then with each model removed in turn (`opf.dynamics.models`, and the rotation
bank's two models of a turning body in `opf.dynamics.rotation_models`), on every log of the
benchmark (run_benchmark.py's logs and protocol), against the constant-velocity Kalman filter.

Writes into OUT:
  ablation.csv  tidy: one row per variant and log (means over seeds), with the ratio of the OPF's
                hidden translation and rotation errors over cvkf's on that log
  ablation.md   per variant: the geometric mean of those ratios, overall and per kind
  ablation.png  the overall ratios as bars

  bash scripts/run_dynamics_ablation.sh [OUT]          (every log, 3 seeds)
  experiments/real_motion/run_ablation.py OUT --subset (one log per kind, 1 seed: the test's)
"""

import argparse
import concurrent.futures
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

MODELS = ("position", "velocity", "damped", "ballistic")
ROTATION_MODELS = ("orientation", "angular_velocity", "damped_angular_velocity")
# (name, translation models, rotation models): the full bank, then one model out at a time.
VARIANTS = [("full bank", MODELS, ROTATION_MODELS)] + \
    [(f"without {m}", tuple(x for x in MODELS if x != m), ROTATION_MODELS) for m in MODELS] + \
    [(f"without {m}", MODELS, tuple(x for x in ROTATION_MODELS if x != m))
     for m in ROTATION_MODELS[1:]]


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", help="output directory")
    parser.add_argument("--subset", action="store_true",
                        help="one log per kind, 1 seed, the full bank and one model removed")
    parser.add_argument("--seeds", type=int, default=None, help="seeds per run (default 3)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="runs in parallel (default: the cores)")
    parser.add_argument("--opf", default=os.environ.get("OPF", os.path.join(
        bench.REPO, "build", "bin", "opf")), help="the opf program")
    parser.add_argument("--no-video", action="store_true", help="leave out the video clips")
    args = parser.parse_args()
    if args.seeds is None:
        args.seeds = 1 if args.subset else 3
    if args.seeds < 1 or args.jobs < 1:
        parser.error("--seeds and --jobs must be at least 1")
    if not os.access(args.opf, os.X_OK):
        parser.error(f"no opf program at {args.opf} (build it, or pass --opf)")
    return args


def write_settings(directory, variant):
    """A settings file holding the variant's model lists (every other option at its default)."""
    name, models, rotation_models = variant
    path = os.path.join(directory, name.replace(" ", "_") + ".yaml")
    with open(path, "w") as f:
        f.write(f"# the real-motion ablation: {name}\n"
                f"opf:\n  dynamics:\n    models: [{', '.join(models)}]\n"
                f"    rotation_models: [{', '.join(rotation_models)}]\n")
    return path


def evaluate(job, args, runs_dir):
    """One `opf evaluate` of one log: the OPF under the variant's settings (and cvkf once)."""
    log, variant, settings = job
    base = os.path.join(runs_dir, "_".join((log["name"], log["rate"], log["gap"],
                                            variant[0].replace(" ", "_"))))
    estimators = "opf,cvkf" if variant is VARIANTS[0] else "opf"
    bench.run([args.opf, "evaluate", "--in", log["log"], "--truth", log["truth"], "--estimators",
               estimators, "--seeds", str(args.seeds), "--config", settings, "--threads", "1",
               "--out", base + ".csv"])
    with open(base + ".csv", newline="") as f:
        return job, list(csv.DictReader(f))


def tidy(results):
    """One row per variant and log, with the ratios over cvkf's errors on that log."""
    cvkf = {}
    for (log, variant, _), table in results:
        for r in table:
            if r["estimator"] == "cvkf":
                cvkf[(log["name"], log["rate"], log["gap"])] = r
    rows = []
    for (log, variant, _), table in results:
        reference = cvkf[(log["name"], log["rate"], log["gap"])]
        for r in table:
            if r["estimator"] != "opf":
                continue
            row = {"variant": variant[0], "sequence": log["name"], "kind": log["kind"],
                   "rate": log["rate"], "gap": log["gap"]}
            for metric in ("hidden_translation", "hidden_rotation"):
                mine, theirs = bench.number(r[metric]), bench.number(reference[metric])
                if log["kind"] == "pedestrian" and "rotation" in metric:
                    mine = theirs = math.nan  # boxes have no orientation
                row[metric] = mine
                row[metric + "_over_cvkf"] = mine / theirs if theirs > 0 else math.nan
            rows.append(row)
    return rows


def summary_table(rows, variants):
    kinds = sorted({r["kind"] for r in rows})
    lines = ["# The dynamics module's ablation on the real-motion benchmark", "",
             "The OPF's hidden translation error over the constant-velocity Kalman filter's on "
             "each log, geometric mean over the logs (lower is better); the rotation's the same "
             "way. Each variant removes one model from the bank (`opf.dynamics.models`, "
             "`rotation_models`).", "",
             "| variant | translation / cvkf | rotation / cvkf | " +
             " | ".join(f"{k} translation" for k in kinds) + " |",
             "|---|---|---|" + "---|" * len(kinds)]
    for name in variants:
        mine = [r for r in rows if r["variant"] == name]
        cells = [bench.geometric_mean([r["hidden_translation_over_cvkf"] for r in mine]),
                 bench.geometric_mean([r["hidden_rotation_over_cvkf"] for r in mine])]
        cells += [bench.geometric_mean([r["hidden_translation_over_cvkf"] for r in mine
                                        if r["kind"] == k]) for k in kinds]
        lines.append(f"| {name} | " + " | ".join(f"{c:.3f}" for c in cells) + " |")
    return "\n".join(lines) + "\n"


def bar_chart(out, rows, variants):
    """Two panels: the hidden translation and rotation errors over cvkf's, per variant."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.6), dpi=150, sharey=True)
    for ax, metric, title in ((axes[0], "hidden_translation_over_cvkf", "translation"),
                              (axes[1], "hidden_rotation_over_cvkf", "rotation")):
        values = [bench.geometric_mean([r[metric] for r in rows if r["variant"] == name])
                  for name in variants]
        ax.barh(range(len(variants)), values, color="#d62728")
        ax.axvline(1.0, color="#2ca02c", linestyle="--")
        ax.text(1.0, -0.95, " cvkf", color="#2ca02c", fontsize=8, va="top")
        for k, v in enumerate(values):  # inside the bar's end, clear of the cvkf line
            ax.text(v - 0.02, k, f"{v:.3f}", va="center", ha="right", color="white", fontsize=8)
        ax.set_xlim(0, max(1.15, max(values) * 1.2))
        ax.set_ylim(len(variants) - 0.5, -1.0)
        ax.set_xlabel(f"hidden {title} error / cvkf")
        ax.set_title(f"{title} (geometric mean over logs)", fontsize=10)
    axes[0].set_yticks(range(len(variants)), labels=variants)
    fig.suptitle("The OPF's motion-model bank, one model removed at a time", fontsize=11)
    fig.tight_layout()
    path = os.path.join(out, "ablation.png")
    fig.savefig(path, dpi=200)
    fig.savefig(os.path.join(out, "ablation.svg"), metadata={"Date": None})  # vector, for print
    plt.close(fig)
    return path


def main():
    args = parse_arguments()
    out, runs_dir, logs = bench.prepare(args)
    variants = VARIANTS[:2] if args.subset else VARIANTS
    settings = {v[0]: write_settings(runs_dir, v) for v in variants}
    jobs = [(log, v, settings[v[0]]) for v in variants for log in logs]
    print(f"run_ablation: {len(logs)} logs, {len(variants)} variants, {args.seeds} seeds",
          flush=True)
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(lambda job: evaluate(job, args, runs_dir), jobs))
    rows = tidy(results)
    with open(os.path.join(out, "ablation.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
        writer.writeheader()
        writer.writerows({k: bench.fmt(v) for k, v in r.items()} for r in rows)
    names = [v[0] for v in variants]
    text = summary_table(rows, names)
    with open(os.path.join(out, "ablation.md"), "w") as f:
        f.write(text)
    print(text)
    print(f"figure: {bar_chart(out, rows, names)}")
    print(f"table: {os.path.join(out, 'ablation.md')}")


if __name__ == "__main__":
    sys.exit(main())
