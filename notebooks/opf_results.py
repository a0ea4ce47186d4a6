"""Reading the toolkit's result files and drawing the figures, for the notebooks and the report.

Everything here reads files that `opf reproduce`, `opf run`, `opf sweep` and the benchmarks
wrote; nothing is recomputed but means, spreads and errors over frames.
"""

import json
import math
import os

import matplotlib

matplotlib.use("Agg")  # headless: nbconvert and the report script have no display
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

# Table I of the paper: 5 runs, mean and std, metres and radians (PAPER_NOTES.md).
PAPER_TABLE_I = pd.DataFrame(
    [
        ("general_op", "opf", 0.01138, 7.253e-4, 0.06869, 2.947e-3),
        ("general_op", "pf", 0.06289, 6.498e-4, 0.3870, 1.270e-3),
        ("sugar_drop", "opf", 0.02129, 5.872e-4, 0.003411, 4.629e-4),
        ("sugar_drop", "pf", 0.05018, 6.936e-4, 0.01456, 2.274e-3),
    ],
    columns=["experiment", "estimator", "translation_mean", "translation_std",
             "rotation_mean", "rotation_std"],
)

# The object each experiment scores (objects_of_interest in experiments/<name>.yaml).
OBJECT_OF_INTEREST = {"general_op": "ball", "sugar_drop": "mug", "baseball": "baseball",
                      "cups_game": "ball"}

ESTIMATOR_COLOURS = {"opf": "tab:blue", "pf": "tab:red", "cvkf": "tab:green",
                     "oapf": "tab:orange"}

# Two-sided 95% Student t quantiles by degrees of freedom (no scipy on a bare Debian).
_T95 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306,
        9: 2.262, 10: 2.228, 15: 2.131, 20: 2.086, 30: 2.042}


def t95(dof):
    """The 95% two-sided t quantile for `dof` degrees of freedom (1.96 beyond 30)."""
    if dof < 1:
        return float("nan")
    for bound in sorted(_T95):
        if dof <= bound:
            return _T95[bound]
    return 1.96


def directory_from_env(variable, default):
    """A result directory from the environment (how CI points the notebooks at small result
    sets), else `default` relative to the repository."""
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get(variable, os.path.join(here, "..", default))


def load_runs(results, experiment):
    """`<experiment>_runs.csv` of an `opf run`/`reproduce` output: one row per estimator and
    seed."""
    return pd.read_csv(os.path.join(results, experiment + "_runs.csv"))


def load_frames(results, experiment):
    """`<experiment>_frames.csv` with each row's translation and geodesic rotation error."""
    frames = pd.read_csv(os.path.join(results, experiment + "_frames.csv"))
    frames["translation_error"] = (
        (frames.x - frames.true_x) ** 2 + (frames.y - frames.true_y) ** 2
        + (frames.z - frames.true_z) ** 2) ** 0.5
    dot = (frames.qx * frames.true_qx + frames.qy * frames.true_qy + frames.qz * frames.true_qz
           + frames.qw * frames.true_qw).abs().clip(upper=1.0)
    frames["rotation_error"] = 2.0 * dot.apply(math.acos)
    return frames


def table_one(results, experiments=("general_op", "sugar_drop")):
    """Our Table I (mean and std over seeds of the errors of the object of interest) with the
    paper's numbers beside it, for the experiments whose runs CSV is in `results`."""
    rows = []
    for experiment in experiments:
        path = os.path.join(results, experiment + "_runs.csv")
        if not os.path.exists(path):
            continue
        runs = load_runs(results, experiment)
        for estimator, group in runs.groupby("estimator", sort=False):
            rows.append({
                "experiment": experiment, "estimator": estimator, "seeds": len(group),
                "translation_mean": group.translation_error.mean(),
                "translation_std": group.translation_error.std(ddof=0),
                "rotation_mean": group.rotation_error_paper.mean(),
                "rotation_std": group.rotation_error_paper.std(ddof=0),
            })
    ours = pd.DataFrame(rows)
    if ours.empty:
        return ours
    paper = PAPER_TABLE_I.rename(columns={c: "paper_" + c for c in PAPER_TABLE_I.columns
                                          if c not in ("experiment", "estimator")})
    return ours.merge(paper, on=["experiment", "estimator"], how="left")


def plot_over_frames(frames, experiment, column, ylabel, ax, seed=0):
    """`column` of the object of interest over frames, one line per estimator, for one seed (the
    main hypothesis), with the frames the object was unseen shaded."""
    obj = OBJECT_OF_INTEREST.get(experiment)
    mine = frames[(frames.object == obj) & (frames.seed == seed) & (frames.hypothesis == 0)]
    for estimator, rows in mine.groupby("estimator", sort=False):
        ax.plot(rows.frame, rows[column], label=estimator,
                color=ESTIMATOR_COLOURS.get(estimator))
    unseen = mine[mine.visible == 0].frame.unique()
    for frame in unseen:
        ax.axvspan(frame - 0.5, frame + 0.5, color="0.9", lw=0, zorder=0)
    ax.set_xlabel("frame")
    ax.set_ylabel(ylabel)
    ax.set_title(f"{experiment}: {obj}")
    ax.legend()
    return ax


def figure_three(results, experiment="general_op", estimators=("opf", "pf")):
    """The paper's Fig. 3 from our files: translation error and trace of Q~ over frames for the
    OPF and the PF (seed 0; unseen frames shaded)."""
    frames = load_frames(results, experiment)
    frames = frames[frames.estimator.isin(estimators)]
    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    plot_over_frames(frames, experiment, "translation_error", "translation error [m]", axes[0])
    plot_over_frames(frames, experiment, "trace", "trace of Q~ [m^2 + rad^2]", axes[1])
    axes[1].set_yscale("log")
    fig.tight_layout()
    return fig


def load_sweep(table):
    """A sweep's tidy table (`opf sweep`), finished runs only."""
    rows = pd.read_csv(table)
    return rows[rows.status == "ok"]


def summarise(rows, by, metric="translation_error"):
    """Mean, std, seeds and the 95% confidence half-width of the mean of `metric`, per group."""
    grouped = rows.groupby(list(by), sort=False)[metric]
    summary = grouped.agg(["mean", "std", "count"]).reset_index()
    summary["ci95"] = [t95(n - 1) * s / math.sqrt(n) if n > 1 else float("nan")
                       for s, n in zip(summary["std"], summary["count"])]
    return summary


def plot_sweep(rows, parameter, metric, ax, series="estimator", log_x=False):
    """`metric` against `parameter` (a column of the sweep table), one line per `series` value,
    with 95% confidence intervals over seeds."""
    summary = summarise(rows, [series, parameter], metric)
    for name, group in summary.groupby(series, sort=False):
        ax.errorbar(group[parameter].astype(str) if not log_x else group[parameter],
                    group["mean"], yerr=group["ci95"], marker="o", capsize=3, label=str(name),
                    color=ESTIMATOR_COLOURS.get(name))
    if log_x:
        ax.set_xscale("log")
    ax.set_xlabel(parameter)
    ax.set_ylabel(metric.replace("_", " "))
    ax.legend()
    return ax


def load_benchmark(path, prefix="BM_EstimatorStep/"):
    """Medians of a Google Benchmark JSON report (bench/run_benchmarks.sh): name, estimator,
    particles per portion and time per step in microseconds, for the estimator steps."""
    with open(path) as f:
        report = json.load(f)
    rows = []
    for b in report["benchmarks"]:
        if b.get("aggregate_name") != "median" or not b["run_name"].startswith(prefix):
            continue
        _, estimator, n = b["run_name"].split("/")
        scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3}[b["time_unit"]]
        rows.append({"estimator": estimator, "particles": int(n.split(":")[1]),
                     "step_us": b["real_time"] * scale})
    return pd.DataFrame(rows), report.get("context", {})
