"""Reading the toolkit's result files and drawing the figures, for the notebooks and the report.

Everything here reads files that `opf reproduce`, `opf run`, `opf sweep` and the benchmarks
wrote; nothing is recomputed but means, spreads and errors over frames.

The notebooks import it as `import opf_results as results` (`opf` is the toolkit's own Python
module). A result file that is not there is skipped with a note naming it and the command that
makes it: the `*_or_skip` functions return None after showing that note.
"""

import csv
import json
import math
import os
import sys

import matplotlib

if "ipykernel" not in sys.modules:
    matplotlib.use("Agg")  # headless: the report script has no display (notebooks draw inline)
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker as ticker  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

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
                      "cups_game": "ball", "twin_mugs": "ball"}

# How each estimator is drawn, the same as the charts of `opf run`/`reproduce`
# (experiments/drivers/estimator_style.cpp): the paper's colours (OPF red, PF blue; the other
# baselines green, purple and orange), a line style and a marker of its own, so that curves on the
# same values and grey print still tell them apart. Wider lines are drawn first, narrower ones on
# top of them.
# This is the one definition for the notebooks (and paper/make_report.py, which draws with
# plot_sweep and figure_three).
ESTIMATOR_COLOURS = {"opf": "#dc1e1e", "pf": "#1e3cdc", "cvkf": "#1ea03c", "imm": "#8c3cc8",
                     "oapf": "#f08c00"}
OTHER_COLOUR = "#5a5a5a"
ESTIMATOR_STYLES = {
    "opf": dict(linestyle="-", linewidth=1.5, marker="D"),
    "pf": dict(linestyle="--", linewidth=2.6, marker="s"),
    "cvkf": dict(linestyle="-.", linewidth=1.5, marker="^"),
    "imm": dict(linestyle="--", linewidth=1.5, marker="v"),
    "oapf": dict(linestyle=":", linewidth=2.25, marker="X"),
}
UNSEEN_COLOUR = "0.88"  # the shading of the frames in which the object had no measurement
EPSILON_SAFE_DEFAULT = 0.1  # opf.feedback.epsilon_safe in experiments/configs/estimators.yaml
TRACE_LABEL = r"$\mathrm{tr}(\tilde{Q})$ [m$^2$ + rad$^2$]"

# Axis labels of the swept parameters.
PARAMETER_LABELS = {
    "opf.uncertainty.kappa": r"$\kappa$ (covariance inflation)",
    "opf.history_length": r"$H$ (fitted history) [frames]",
    "opf.occluder.epsilon_occ": r"$\epsilon_\mathrm{occ}$ (occluder tie gap) [m]",
    "opf.trajectory.translation_order": "polynomial order of the fit",
    "opf.occluder.plane": "occluder plane",
    "pf.resampling.scheme": "resampler",
    "particles": "particles per portion",
}
METRIC_LABELS = {
    "translation_error": "translation error [m]",
    "rotation_error_geodesic": "rotation error (geodesic) [rad]",
    "rotation_error_paper": "rotation error (paper's) [rad]",
    "translation_error_unobserved": "translation error while hidden [m]",
}

def mean_std(values):
    """The mean, the sample standard deviation (ddof=1: one std over the seeds, NaN for one value)
    and the number of finite values."""
    values = np.asarray([v for v in values if v is not None and math.isfinite(v)], dtype=float)
    if len(values) == 0:
        return float("nan"), float("nan"), 0
    std = float(values.std(ddof=1)) if len(values) > 1 else float("nan")
    return float(values.mean()), std, len(values)


def seeds_text(counts):
    """"5 seeds", or "2-5 seeds" when the groups ran different numbers."""
    counts = sorted({int(c) for c in counts})
    if not counts:
        return "no seeds"
    span = str(counts[0]) if len(counts) == 1 else f"{counts[0]}-{counts[-1]}"
    return f"{span} seed{'' if counts == [1] else 's'}"


def geometric_mean(values):
    """The geometric mean of the finite positive values (NaN when there is none)."""
    values = np.asarray(values, dtype=float)
    values = values[np.isfinite(values) & (values > 0)]
    return float(np.exp(np.log(values).mean())) if len(values) else float("nan")


def directory_from_env(variable, default):
    """A result directory from the environment (how CI points the notebooks at small result
    sets), else `default` relative to the repository."""
    return os.environ.get(variable, os.path.join(REPO, default))


def benchmark_from_env(default="bench/results/amd-epyc-2cpu-2026-12-06.json"):
    """The benchmark report: OPF_BENCH, else the one under bench/results/."""
    return os.environ.get("OPF_BENCH", os.path.join(REPO, default))


# ---------------------------------------------------------------------------------------------
# Load or skip: one place for what a missing input looks like in a notebook.


class Skipped:
    """A note that an input is missing: Markdown in a notebook (and its HTML copy), plain text
    elsewhere."""

    def __init__(self, what, path, command):
        self.what, self.path, self.command = what, path, command

    def _repr_markdown_(self):
        return f"**Skipped {self.what}:** `{self.command}` makes `{self.path}`, not there yet."

    def __repr__(self):
        return f"skipped {self.what}: {self.command} makes {self.path}, not there yet"


def skip(what, path, command):
    """Shows the note that `what` (the file `path`) is missing and `command` makes it; returns
    None."""
    note = Skipped(what, _shown_path(path), command)
    try:
        from IPython import get_ipython
        from IPython.display import display
        if get_ipython() is not None:
            display(note)
            return None
    except ImportError:
        pass
    print(repr(note))
    return None


def load_or_skip(path, what, command, loader=None):
    """`loader(path)` (or `path` itself without a loader) when `path` exists, else None after the
    note that names `what` and the `command` that makes it."""
    if not os.path.exists(path):
        return skip(what, path, command)
    return loader(path) if loader is not None else path


def _shown_path(path):
    """`path` relative to the repository when it lies inside it (shorter notes)."""
    full = os.path.abspath(path)
    return os.path.relpath(full, REPO) if full.startswith(REPO + os.sep) else full


def results_command(results):
    """The command that writes the result files of `opf reproduce` into `results`."""
    if os.path.abspath(results) == os.path.join(REPO, "results"):
        return "bash scripts/run_main.sh"
    return f"build/bin/opf reproduce --out {_shown_path(results)}"


def sweep_command(sweeps, name):
    """The command that runs the sweep `name` into `sweeps/name`."""
    command = f"build/bin/opf sweep experiments/sweeps/{name}.yaml"
    if os.path.abspath(sweeps) != os.path.join(REPO, "results", "sweeps"):
        command += f" --out {_shown_path(os.path.join(sweeps, name))}"
    return command


def runs_or_skip(results, experiment):
    """`<experiment>_runs.csv` (load_runs), or None with a note."""
    return load_or_skip(os.path.join(results, experiment + "_runs.csv"),
                        f"{experiment} (runs)", results_command(results),
                        lambda path: load_runs(results, experiment))


def frames_or_skip(results, experiment):
    """`<experiment>_frames.csv` (load_frames), or None with a note."""
    return load_or_skip(os.path.join(results, experiment + "_frames.csv"),
                        f"{experiment} (per-frame results)", results_command(results),
                        lambda path: load_frames(results, experiment))


def sweep_or_skip(sweeps, name):
    """The finished runs of the sweep `name` (load_sweep), or None with a note (also when no
    run of it has finished)."""
    path = os.path.join(sweeps, name, name + ".csv")
    rows = load_or_skip(path, f"the {name} sweep", sweep_command(sweeps, name), load_sweep)
    if rows is not None and rows.empty:
        return skip(f"the {name} sweep (no finished runs)", path, sweep_command(sweeps, name))
    return rows


def benchmark_or_skip(path):
    """The estimator steps of a benchmark report (load_benchmark), or None with a note."""
    return load_or_skip(path, "the benchmark report", "bash bench/run_benchmarks.sh",
                        load_benchmark)


# ---------------------------------------------------------------------------------------------
# Result files.


def load_runs(results, experiment):
    """`<experiment>_runs.csv` of an `opf run`/`reproduce` output: one row per estimator and
    seed."""
    return pd.read_csv(os.path.join(results, experiment + "_runs.csv"))


def load_frames(results, experiment):
    """`<experiment>_frames.csv` with each row's translation and geodesic rotation error."""
    frames = pd.read_csv(os.path.join(results, experiment + "_frames.csv"), low_memory=False)
    frames["translation_error"] = (
        (frames.x - frames.true_x) ** 2 + (frames.y - frames.true_y) ** 2
        + (frames.z - frames.true_z) ** 2) ** 0.5
    dot = (frames.qx * frames.true_qx + frames.qy * frames.true_qy + frames.qz * frames.true_qz
           + frames.qw * frames.true_qw).abs().clip(upper=1.0)
    frames["rotation_error"] = 2.0 * np.arccos(dot)
    return frames


def epsilon_safe(results, experiment):
    """The OPF's alert threshold epsilon_safe of `experiment` from the settings recorded in
    `results/summary.json` (provenance), else the default 0.1. Returns (value, where from)."""
    path = os.path.join(results, "summary.json")
    try:
        with open(path) as f:
            settings = json.load(f)["provenance"]["settings"]
        settings = settings.get(experiment, settings)  # per experiment, or one run's settings
        return float(settings["opf"]["feedback"]["epsilon_safe"]), "summary.json"
    except (OSError, ValueError, KeyError, TypeError):
        return EPSILON_SAFE_DEFAULT, "default"


def table_one(results, experiments=("general_op", "sugar_drop")):
    """Our Table I (mean and sample std over seeds of the errors of the object of interest) with the
    paper's numbers beside it, for the experiments whose runs CSV is in `results`."""
    rows = []
    for experiment in experiments:
        path = os.path.join(results, experiment + "_runs.csv")
        if not os.path.exists(path):
            continue
        runs = load_runs(results, experiment)
        for estimator, group in runs.groupby("estimator", sort=False):
            translation = mean_std(group.translation_error)
            rotation = mean_std(group.rotation_error_paper)
            rows.append({
                "experiment": experiment, "estimator": estimator, "seeds": len(group),
                "translation_mean": translation[0], "translation_std": translation[1],
                "rotation_mean": rotation[0], "rotation_std": rotation[1],
            })
    ours = pd.DataFrame(rows)
    if ours.empty:
        return ours
    paper = PAPER_TABLE_I.rename(columns={c: "paper_" + c for c in PAPER_TABLE_I.columns
                                          if c not in ("experiment", "estimator")})
    return ours.merge(paper, on=["experiment", "estimator"], how="left")


# ---------------------------------------------------------------------------------------------
# Drawing.


# Markers that tell experiments apart where one figure has an estimator's lines for several
# ("opf general_op", "opf sugar_drop"): the colour and line style stay the estimator's.
EXPERIMENT_MARKERS = {"general_op": "o", "sugar_drop": "s", "baseball": "^", "cups_game": "v",
                      "twin_mugs": "D", "rolling_ball": "P"}


def estimator_style(name, with_marker=False):
    """Keyword arguments for plot/errorbar that draw estimator `name` as everywhere else: its
    colour, line style and width, drawn under narrower lines. "ESTIMATOR EXPERIMENT" names get the
    estimator's style with the experiment's marker. Names that are not estimators get no colour
    (matplotlib's cycle)."""
    estimator, _, experiment = str(name).partition(" ")
    if estimator not in ESTIMATOR_STYLES:
        return {}
    style = dict(ESTIMATOR_STYLES[estimator], color=ESTIMATOR_COLOURS[estimator])
    style["zorder"] = 3 + 1.0 / style["linewidth"]  # narrower on top
    if experiment:
        style["marker"] = EXPERIMENT_MARKERS.get(experiment, "o")
    if not with_marker:
        style.pop("marker")
    return style


def legend(ax, *args, **kwargs):
    """A legend with handles long enough to show each line style's pattern."""
    kwargs.setdefault("fontsize", 8)
    kwargs.setdefault("handlelength", 3.5)
    return ax.legend(*args, **kwargs)


def drawing_order(names):
    """`names` in drawing order: wider lines first."""
    return sorted(names, key=lambda n: -ESTIMATOR_STYLES.get(str(n).partition(" ")[0],
                                                        {"linewidth": 0})["linewidth"])


def _plain_number(value, _position=None):
    """A tick label in plain decimals: 0.01, 0.2, 5, 300, 10000."""
    if value == 0 or not math.isfinite(value):
        return "0"
    if abs(value) >= 1:
        return f"{value:.0f}" if float(value).is_integer() else f"{value:g}"
    return np.format_float_positional(value, precision=6, trim="-")


def plain_log_axis(axis):
    """Log-scale ticks at 1, 2 and 5 (or fewer over many decades) times a power of ten, written
    as plain decimals instead of 2e-01 or 10^3."""
    low, high = sorted(axis.get_view_interval())
    decades = math.log10(high / low) if low > 0 and high > 0 else 3.0
    subs = (1.0, 2.0, 3.0, 5.0) if decades <= 1.2 else (1.0, 2.0, 5.0) if decades <= 3.2 \
        else (1.0,)
    axis.set_major_locator(ticker.LogLocator(base=10.0, subs=subs, numticks=30))
    axis.set_major_formatter(ticker.FuncFormatter(_plain_number))
    axis.set_minor_locator(ticker.LogLocator(base=10.0, subs=np.arange(1, 10), numticks=30))
    axis.set_minor_formatter(ticker.NullFormatter())


def plain_axis(axis):
    """Linear ticks written as plain decimals (no offset or 1e-2 factor)."""
    formatter = ticker.ScalarFormatter(useOffset=False)
    formatter.set_scientific(False)
    axis.set_major_formatter(formatter)


def unseen_intervals(t, visible):
    """Time intervals in which the object had no measurement: each unseen frame's interval
    reaches halfway to its neighbours (as the PNG charts shade them). `t` ascending."""
    t = np.asarray(t, dtype=float)
    visible = np.asarray(visible).astype(bool)
    intervals = []
    for i in np.flatnonzero(~visible):
        start = 0.5 * (t[i - 1] + t[i]) if i > 0 else t[i]
        end = 0.5 * (t[i] + t[i + 1]) if i + 1 < len(t) else t[i]
        if intervals and intervals[-1][1] >= start - 1e-12:
            intervals[-1][1] = end
        else:
            intervals.append([start, end])
    return intervals


def shade_unseen(ax, t, visible, label="object not visible"):
    """Shades the intervals in which the object was not visible; returns a legend handle (None
    when it was always visible)."""
    intervals = unseen_intervals(t, visible)
    for start, end in intervals:
        ax.axvspan(start, end, color=UNSEEN_COLOUR, lw=0, zorder=0)
    return Patch(color=UNSEEN_COLOUR, label=label) if intervals else None


def first_seed(frames):
    """The first seed of a frames table, as its seed column names it."""
    return int(frames.seed.min())


def plot_over_time(frames, experiment, column, ylabel, ax, seed=None, with_legend=True):
    """`column` of the object of interest over time, one line per estimator, for one seed (the
    first by default) and the main hypothesis, with the intervals the object was not visible
    shaded. Returns the legend handles."""
    obj = OBJECT_OF_INTEREST.get(experiment)
    seed = first_seed(frames) if seed is None else seed
    mine = frames[(frames.object == obj) & (frames.seed == seed) & (frames.hypothesis == 0)]
    time = "t" if "t" in mine.columns else "frame"
    handles = []
    estimators = list(mine.estimator.unique())
    for estimator in drawing_order(estimators):
        rows = mine[mine.estimator == estimator].sort_values(time)
        handles.append(ax.plot(rows[time], rows[column], label=estimator,
                               **estimator_style(estimator))[0])
    handles.sort(key=lambda h: estimators.index(h.get_label()))  # legend in the file's order
    if len(mine):
        one = mine[mine.estimator == estimators[0]].sort_values(time)
        shaded = shade_unseen(ax, one[time], one.visible)
        if shaded is not None:
            handles.append(shaded)
        ax.set_xlim(one[time].min(), one[time].max())
    ax.set_xlabel("time [s]" if time == "t" else "frame")
    ax.set_ylabel(ylabel)
    ax.set_title(f"{experiment}: {obj}, seed {seed}")
    if with_legend:
        legend(ax, handles=handles, loc="upper left")
    return handles


def figure_three(results, experiment="general_op", estimators=("opf", "pf"), seed=None,
                 frames=None):
    """The paper's Fig. 3 from our files: translation error and trace of Q~ over time for the
    OPF and the PF (one seed, the first by default; intervals without a measurement of the
    object shaded; the alert threshold epsilon_safe drawn on the trace). `frames` is
    load_frames(results, experiment) when already loaded."""
    frames = load_frames(results, experiment) if frames is None else frames
    frames = frames[frames.estimator.isin(estimators)]
    if seed is None:
        seed = first_seed(frames) if len(frames) else 0
    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    handles = plot_over_time(frames, experiment, "translation_error", "translation error [m]",
                             axes[0], seed=seed)
    axes[0].set_xlabel("")  # the axes share time, labelled below
    axes[0].set_ylim(bottom=0)
    plain_axis(axes[0].yaxis)
    plot_over_time(frames, experiment, "trace", TRACE_LABEL, axes[1], seed=seed,
                   with_legend=False)
    axes[1].set_title("")
    value, _ = epsilon_safe(results, experiment)
    line = axes[1].axhline(value, color="black", lw=1.0, ls=(0, (5, 3)), zorder=2,
                           label=rf"alert: $\epsilon_\mathrm{{safe}}$ = {_plain_number(value)}")
    axes[1].set_yscale("log")
    low, high = axes[1].get_ylim()
    axes[1].set_ylim(min(low, value / 1.5), max(high, value * 1.5))
    plain_log_axis(axes[1].yaxis)
    legend(axes[1], handles=[h for h in handles if not isinstance(h, Patch)] + [line],
           loc="upper left")
    fig.tight_layout()
    return fig


def load_sweep(table):
    """A sweep's tidy table (`opf sweep`), finished runs only."""
    rows = pd.read_csv(table)
    return rows[rows.status == "ok"]


def summarise(rows, by, metric="translation_error"):
    """Mean, sample std (ddof=1) and number of seeds of `metric`, per group."""
    grouped = rows.groupby(list(by), sort=False)[metric]
    return grouped.agg(mean="mean", std=lambda v: v.std(ddof=1), count="count").reset_index()


def plot_sweep(rows, parameter, metric, ax, series="estimator", log_x=False):
    """`metric` against `parameter` (a column of the sweep table), one line per `series` value,
    with error bars of one sample std over seeds (the axis clipped at zero for errors)."""
    summary = summarise(rows, [series, parameter], metric)
    names = list(summary[series].unique())
    # An earlier call on this axis fixed its limits with set_ylim: scale to every line drawn.
    ax.autoscale(enable=True, axis="y")
    for name in drawing_order(names):
        group = summary[summary[series] == name]
        x = group[parameter] if log_x else group[parameter].astype(str)  # one step per value
        ax.errorbar(x, group["mean"], yerr=group["std"], capsize=3, elinewidth=1.2,
                    label=str(name),
                    **(estimator_style(name, with_marker=True) or dict(marker="o")))
    handles, labels = ax.get_legend_handles_labels()
    order = sorted(range(len(labels)), key=lambda i: names.index(labels[i])
                   if labels[i] in names else len(names))
    if log_x:
        ax.set_xscale("log")
        plain_log_axis(ax.xaxis)
    if metric.endswith("error") or "error_" in metric:
        ax.set_ylim(bottom=0)
    plain_axis(ax.yaxis)
    ax.set_xlabel(PARAMETER_LABELS.get(parameter, parameter))
    ax.set_ylabel(METRIC_LABELS.get(metric, metric.replace("_", " ")))
    legend(ax, [handles[i] for i in order], [labels[i] for i in order])
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


# ---------------------------------------------------------------------------------------------
# Recorded motion: the real-motion benchmark, its dynamics ablation and the hand scenes
# (experiments/real_motion, run by scripts/run_main.sh).


def _real_motion_script(name):
    """experiments/real_motion/<name>.py as a module (its own summaries, not copies of them)."""
    import importlib.util
    path = os.path.join(REPO, "experiments", "real_motion", name + ".py")
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def real_motion_seeds(directory):
    """The seeds per run of the real-motion benchmark, as its summary.md states them (None when
    it is not there)."""
    import re
    try:
        with open(os.path.join(directory, "summary.md")) as f:
            found = re.search(r"(\d+) seed\(s\)", f.read())
    except OSError:
        return None
    return int(found.group(1)) if found else None


def load_real_motion(directory):
    """The real-motion benchmark in `directory`: (summary, rows). `summary` holds one dict per
    estimator and preset, as run_benchmark.py summarises results.csv and profile.csv (ratios over
    cvkf with their intervals, calibration pooled over the hidden frames); `rows` the rows of
    results.csv."""
    bench = _real_motion_script("run_benchmark")
    with open(os.path.join(directory, "results.csv"), newline="") as f:
        rows = [{k: bench.number(v) if k in bench.METRICS else v for k, v in r.items()}
                for r in csv.DictReader(f)]
    with open(os.path.join(directory, "profile.csv"), newline="") as f:
        bins = [dict(r, frames=int(r["frames"])) for r in csv.DictReader(f)]
    gaps = []  # the errors per gap, for the worst log's interval (a run before them has none)
    if os.path.exists(os.path.join(directory, "gaps.csv")):
        with open(os.path.join(directory, "gaps.csv"), newline="") as f:
            gaps = [dict(r, frames=int(r["frames"]), gap_start=float(r["gap_start"]),
                         hidden_translation=bench.number(r["hidden_translation"]))
                    for r in csv.DictReader(f)]
    return bench.summarise(rows, bins, gaps), rows


def hidden_ratios(rows, entry=("opf", "default"), reference=("cvkf", "default")):
    """Per log of the real-motion benchmark: ((sequence, rate, gap), the hidden translation error
    of `entry` (estimator, preset) over that of `reference`)."""
    by_log = {}
    for r in rows:
        by_log.setdefault((r["sequence"], r["rate"], r["gap"]), {})[
            (r["estimator"], r["preset"])] = r["hidden_translation"]
    return [(log, runs[entry] / runs[reference]) for log, runs in by_log.items()
            if entry in runs and runs.get(reference, 0) > 0]


def dynamics_ablation_summary(rows):
    """The dynamics ablation (ablation.csv) per variant: the OPF's hidden translation and rotation
    errors over cvkf's, geometric mean over the logs, overall and per kind of motion."""
    variants = list(dict.fromkeys(rows.variant))
    kinds = sorted(rows.kind.unique())

    def ratio(variant, column, kind=None):
        mine = rows[(rows.variant == variant) & ((rows.kind == kind) if kind else True)]
        return geometric_mean(mine[column])

    table = pd.DataFrame({
        "translation / cvkf": [ratio(v, "hidden_translation_over_cvkf") for v in variants],
        "rotation / cvkf": [ratio(v, "hidden_rotation_over_cvkf") for v in variants],
        **{kind: [ratio(v, "hidden_translation_over_cvkf", kind) for v in variants]
           for kind in kinds}}, index=variants)
    table.attrs["logs"] = rows[rows.variant == variants[0]].shape[0] if variants else 0
    return table


def ablation_seeds(ablation, benchmark_rows, benchmark_seeds):
    """The seeds of the dynamics ablation, which ablation.csv does not record: the benchmark's,
    when the ablation's full bank (the OPF's default settings) gives the benchmark's OPF errors
    log for log; else None."""
    if benchmark_seeds is None:
        return None
    ours = {_log_key(r["sequence"], r["rate"], r["gap"]): r["hidden_translation"]
            for r in benchmark_rows if (r["estimator"], r["preset"]) == ("opf", "default")}
    full = ablation[ablation.variant == "full bank"]
    same = [math.isclose(r.hidden_translation,
                         ours.get(_log_key(r.sequence, r.rate, r.gap), math.nan), rel_tol=1e-4)
            for r in full.itertuples()]
    return benchmark_seeds if same and all(same) else None


def _log_key(sequence, rate, gap):
    """A log of the real-motion benchmark, alike whether its gap was read as text or number."""
    try:
        gap = f"{float(gap):g}"
    except ValueError:
        gap = str(gap)
    return str(sequence), str(rate), gap


def load_hand_scenes(directory):
    """hand_scenes.csv with, per scene and estimator, the sample std of the hidden translation
    error over the seeds and their number (from each scene's runs CSV of `opf run`)."""
    table = pd.read_csv(os.path.join(directory, "hand_scenes.csv"))
    spreads = []
    for r in table.itertuples():
        scene = f"{r.recording}_{r.scene}"
        path = os.path.join(directory, scene, scene + "_runs.csv")
        runs = pd.read_csv(path) if os.path.exists(path) else None
        values = [] if runs is None else \
            runs[runs.estimator == r.estimator].translation_error_unobserved
        _, std, n = mean_std(values)
        spreads.append((std, n))
    table["hidden_translation_std"] = [s for s, _ in spreads]
    table["seeds"] = [n for _, n in spreads]
    return table
