"""Writes the report's generated tables, figures and switches from result files.

    /usr/bin/python3 paper/make_report.py OUT_DIR

Inputs (environment, with defaults relative to the repository): OPF_RESULTS (results/, from
`bash scripts/run_main.sh`, with its real_motion/, dynamics_ablation/, hand_scenes/ and
twin_mugs/), OPF_SWEEPS (results/sweeps/, from `opf sweep`) and OPF_BENCH (the benchmark report
under bench/results/). A section whose inputs are missing is left out of the report: values.tex
switches it off and not_run.tex names, in one sentence, the command that makes it (also listed
on stderr). Nothing here is typed in by hand but the paper's own Table I and the targets below.
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "notebooks"))
import opf_results as opf  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import ticker  # noqa: E402
import pandas as pd  # noqa: E402

REPO = os.path.abspath(os.path.join(HERE, ".."))

# What the report checks results against, as (lowest, highest) allowed; None is open. A value
# outside is marked "missed" in bold beside it, one inside "met".
TARGETS = {
    # the project's targets for speed (docs/performance.md): medians of the benchmark report
    "opf_step_us": (None, 50.0),             # one OPF step, 5000 + 5000 particles, one core
    "bank_update_us": (None, 5.0),           # the motion-model banks' update per object
    "frame_64_objects_2_threads_ms": (None, 2.0),
    "render_and_detect_ms": (None, 10.0),    # one 640x480 frame rendered and segmented
    # the project's targets on the real-motion benchmark: the OPF, default preset
    "hidden_over_cvkf": (None, 0.95),        # hidden error over cvkf's, geometric mean over logs
    "log_over_cvkf": (None, 1.10),           # the same ratio on every single log
    "nees_position": (0.5, 2.0),             # NEES / 3, pooled over the hidden frames
    "inside95_position": (0.85, 0.98),       # share of hidden frames inside the 95% ellipsoid
    # the project's targets on the hand scenes: the OPF's errors while hidden [mm] and its
    # reveals (the main hypothesis right when the object is seen again)
    "carry_hidden_mm": (None, 10.0),
    "pass_over_pf_mm": (None, 2.0),          # its error minus the PF's on the same scene
    "cups_nearest_mm": (None, 15.0),         # the hypothesis nearest the ball
    "carry_right_at_reveal": (0.95, None),
    "pass_right_at_reveal": (0.95, None),
    "cups_right_at_reveal": (0.80, None),
}
# Table I: the OPF's errors at most the paper's own (opf.PAPER_TABLE_I, the paper's Table I).
TABLE_ONE_TARGET = "opf"

not_run_here = []  # (what, command) of each part left out
switches = {}      # \ifHave<Name> of report.tex, true for the sections that are in


# ---------------------------------------------------------------------------------------------
# Formatting.


def tex_escape(text):
    return (str(text).replace("\\", r"\textbackslash{}").replace("_", r"\_")
            .replace("%", r"\%").replace("&", r"\&").replace("#", r"\#"))


def absent(value):
    return value is None or (isinstance(value, float) and math.isnan(value))


def number(value, digits=4):
    return "--" if absent(value) else f"{value:.{digits}f}"


def pm(mean, std, digits=4):
    """Mean $\\pm$ std; the mean alone without a std (one seed; the paper gives none)."""
    if absent(mean):
        return "--"
    return number(mean, digits) if absent(std) else \
        f"{number(mean, digits)} $\\pm$ {number(std, digits)}"


def pm_of(values, digits=4):
    """Mean $\\pm$ sample std (ddof=1) of `values`, e.g. [1, 2, 3, 4] -> 2.50 $\\pm$ 1.29."""
    mean, std, _ = opf.mean_std(values)
    return pm(mean, std, digits)


def std_over(counts):
    """The spread's label: "std over 5 seeds" (the sample standard deviation)."""
    return f"std over {opf.seeds_text(counts)}"


def percent(share, digits=0):
    return "--" if absent(share) else f"{100 * share:.{digits}f}\\%"


# ---------------------------------------------------------------------------------------------
# Targets.


def meets(value, bounds):
    """True when `value` lies within `bounds` (lowest, highest; None open), None without one."""
    if absent(value):
        return None
    low, high = bounds
    return (low is None or value >= low) and (high is None or value <= high)


def mark(value, bounds):
    """"met", a bold "missed", or "--" when there is no value."""
    verdict = meets(value, bounds)
    return "--" if verdict is None else "met" if verdict else r"\textbf{missed}"


def bounds_text(bounds, unit="", scale=1.0, spec="g"):
    """The target as it reads in a table: $\\le$ 50 us, $\\ge$ 95%, 0.5--2 (`spec` formats the
    numbers: ".2f" writes 1.10)."""
    low, high = (None if b is None else format(round(b * scale, 9), spec) for b in bounds)
    unit = f" {unit}" if unit else ""
    if low is None:
        return f"$\\le$ {high}{unit}"
    if high is None:
        return f"$\\ge$ {low}{unit}"
    return f"{low}--{high}{unit}"


def telling(value, bounds, digits):
    """`digits` decimals, or more when fewer would round a missed value onto its bound."""
    for more in range(digits, digits + 4):
        shown = round(value, more)
        if meets(shown, bounds) == meets(value, bounds):
            return more
    return digits + 4


# ---------------------------------------------------------------------------------------------
# Output.


def not_run(what, command):
    """Leaves `what` out of the report, with one sentence naming the `command` that makes it."""
    not_run_here.append((what, command))


def writing_into(command, directory, always=False):
    """`command` with its output directory, which may be left out when it is the default
    results/<name> (`always`: the command needs it)."""
    default = os.path.join(REPO, "results", os.path.basename(os.path.normpath(directory)))
    if always or os.path.abspath(directory) != default:
        return f"{command} {opf._shown_path(directory)}"
    return command


def switch_on(name):
    switches[name] = True


def write(out, name, text):
    with open(os.path.join(out, name), "w") as f:
        f.write(text)


def float_env(environment, body, caption, label, placement="t"):
    return (f"\\begin{{{environment}}}[{placement}]\n\\caption{{{caption}}}\n\\label{{{label}}}\n"
            f"\\centering\n{body}\\end{{{environment}}}\n")


def figure_env(environment, body, caption, label):
    """A figure: its caption below the graphics, as IEEEtran sets figures."""
    return (f"\\begin{{{environment}}}[t]\n\\centering\n{body}\\caption{{{caption}}}\n"
            f"\\label{{{label}}}\n\\end{{{environment}}}\n")


def tabular(columns, header, rows):
    lines = [f"\\begin{{tabular}}{{{columns}}}", r"\toprule", *header, r"\midrule",
             *(" & ".join(cells) + r" \\" for cells in rows), r"\bottomrule", r"\end{tabular}"]
    return "\n".join(lines) + "\n"


def fitted(table, size="footnotesize"):
    """`table` in `size`, shrunk to the column's width only when wider."""
    width = r"\ifdim\width>\columnwidth\columnwidth\else\width\fi"
    return f"\\{size}\\setlength{{\\tabcolsep}}{{4pt}}\n\\resizebox{{{width}}}{{!}}{{%\n{table}}}\n"


# ---------------------------------------------------------------------------------------------
# The simulated experiments: Table I, Fig. 3, every estimator.


def simulated(out, results):
    table = opf.table_one(results)
    if table.empty:
        return not_run("the simulated experiments (Table I, Fig. 3, the baselines)",
                       opf.results_command(results))
    switch_on("Simulated")
    write(out, "table_one.tex", table_one(table))
    write(out, "ratios.tex", ratios(table))
    write(out, "figure_three.tex", figure_three(out, results))
    write(out, "baselines.tex", baselines(results))


def table_one_verdict(row):
    """Table I's target for the OPF: its errors at most the paper's."""
    if row.estimator != TABLE_ONE_TARGET or absent(row.paper_translation_mean):
        return "--"
    missed = [name for name, ours, paper in (
        ("translation", row.translation_mean, row.paper_translation_mean),
        ("rotation", row.rotation_mean, row.paper_rotation_mean)) if not ours <= paper]
    return r"\textbf{missed}: " + ", ".join(missed) if missed else "met"


def table_one(table):
    header = [r" & & \multicolumn{2}{c}{translation [m]} & \multicolumn{2}{c}{rotation [rad]} & \\",
              r"\cmidrule(lr){3-4}\cmidrule(lr){5-6}",
              r"experiment & estimator & ours & paper & ours & paper & target \\"]
    rows = [[tex_escape(r.experiment), r.estimator.upper(),
             pm(r.translation_mean, r.translation_std),
             pm(r.paper_translation_mean, r.paper_translation_std),
             pm(r.rotation_mean, r.rotation_std),
             pm(r.paper_rotation_mean, r.paper_rotation_std), table_one_verdict(r)]
            for r in table.itertuples()]
    caption = (f"Errors of the object of interest, ours beside the paper's Table~I: mean "
               f"$\\pm$ {std_over(table.seeds)} (the paper's over its 5 runs). Target: the OPF's "
               f"errors at most the paper's.")
    return float_env("table*", "\\footnotesize\n" + tabular("llccccl", header, rows), caption,
                     "tab:one")


def ratios(table):
    found = []
    for experiment, rows in table.groupby("experiment", sort=False):
        by = rows.set_index("estimator")
        if {"opf", "pf"} <= set(by.index):
            ours = by.translation_mean["opf"] / by.translation_mean["pf"]
            paper = by.paper_translation_mean["opf"] / by.paper_translation_mean["pf"]
            found.append(f"{tex_escape(experiment)}: {ours:.3f} (paper {paper:.3f})")
    return ("; ".join(found) or "not computed (no OPF and PF on the same experiment)") + \
        f", means over {opf.seeds_text(table.seeds)}.\n"


def figure_three(out, results):
    made = []
    for experiment in ("general_op", "sugar_drop"):
        if os.path.exists(os.path.join(results, experiment + "_frames.csv")):
            fig = opf.figure_three(results, experiment)
            fig.savefig(os.path.join(out, f"fig3_{experiment}.pdf"))
            plt.close(fig)
            made.append(experiment)
    if not made:
        not_run("the Fig. 3 curves", opf.results_command(results))
        return ""
    body = "".join(
        f"\\includegraphics[width=\\columnwidth]{{fig3_{e}.pdf}}\\\\[2pt]\n" for e in made)
    caption = (r"Translation error and $\mathrm{trace}(\tilde Q)$ of the object of interest over "
               r"time, as in the paper's Fig.~3 (the first seed of the CSV; hidden frames shaded; "
               r"dashed: the alert threshold $\epsilon_{safe}$).")
    return figure_env("figure", body, caption, "fig:three")


BASELINE_EXPERIMENTS = (("general_op", ""), ("sugar_drop", ""), ("baseball", ""),
                        ("twin_mugs", "twin_mugs"))  # (name, folder under the results)


def baselines(results):
    rows, seeds = [], []
    for experiment, folder in BASELINE_EXPERIMENTS:
        directory = os.path.join(results, folder)
        if not os.path.exists(os.path.join(directory, experiment + "_runs.csv")):
            continue
        for estimator, g in opf.load_runs(directory, experiment).groupby("estimator", sort=False):
            seeds.append(len(g))
            rows.append([tex_escape(experiment), estimator.upper(), pm_of(g.translation_error),
                         pm_of(g.rotation_error_geodesic), pm_of(g.translation_error_unobserved)])
    header = [r"experiment & estimator & translation [m] & rotation [rad] & hidden [m] \\"]
    caption = (f"All estimators: translation and geodesic rotation error, and the translation "
               f"error over the frames without a measurement; mean $\\pm$ {std_over(seeds)}.")
    return float_env("table", fitted(tabular("llccc", header, rows)), caption, "tab:baselines")


# ---------------------------------------------------------------------------------------------
# Recorded motion: the real-motion benchmark, the dynamics ablation, the hand scenes.


def real_motion(out, directory):
    """The real-motion benchmark's tables; returns its rows and seeds for the dynamics ablation."""
    files = [os.path.join(directory, name) for name in ("results.csv", "profile.csv")]
    summary, rows = opf.load_real_motion(directory) if all(map(os.path.exists, files)) \
        else ([], [])
    if not summary:
        return not_run("the real-motion benchmark",
                       writing_into("bash scripts/run_real_motion.sh", directory))
    switch_on("RealMotion")
    seeds = opf.real_motion_seeds(directory)
    logs = max(s["rows"] for s in summary)
    over = f"{seeds} seeds" if seeds else "the seeds"
    write(out, "real_motion.tex", real_motion_table(summary, logs, over) +
          real_motion_targets(summary, rows, logs, over))
    return rows, seeds


def ratio_interval(s):
    """The geometric mean's 95% interval over resampled recordings; none for the reference."""
    low, high = s.get("hidden_ratio_interval", (None, None))
    if absent(low) or (s["estimator"], s["preset"]) == ("cvkf", "default"):
        return "--"
    return f"{low:.3f}--{high:.3f}"


def real_motion_table(summary, logs, over):
    header = [r"estimator & preset & hidden / cvkf & 95\% interval & worst log & rotation / cvkf & "
              r"NEES/3 & inside 95\% \\"]
    rows = [[s["estimator"].upper(), s["preset"], number(s["hidden_ratio"], 3), ratio_interval(s),
             number(s["worst"], 2), number(s["rotation_ratio"], 3),
             f"{s['nees_translation']:.3g}", inside_percent(s["inside95_translation"])]
            for s in summary]
    caption = (f"The real-motion benchmark, every estimator under the default and the paper "
               f"preset: its error while hidden over the constant-velocity Kalman filter's "
               f"(cvkf, default preset) on the same log, geometric mean over the {logs} logs and "
               f"its 95\\% interval over resampled recordings (a cluster bootstrap: a drawn "
               f"recording brings all its logs), and the worst log; the rotation's the same way; "
               f"the position's calibration (NEES/3 "
               f"and the share of hidden frames inside the 95\\% ellipsoid) pooled over the "
               f"hidden frames. Each log's errors are means over {over}.")
    return float_env("table", fitted(tabular("llcccccc", header, rows)), caption, "tab:realmotion")


def inside_percent(share):
    """The share inside the 95% ellipsoid with one decimal, more where that would round a miss of
    its target onto the bound."""
    if absent(share):
        return "--"
    bounds = [None if b is None else 100 * b for b in TARGETS["inside95_position"]]
    return percent(share, telling(100 * share, bounds, 1))


def log_name(log):
    """A log of the real-motion benchmark as the text names it: cup (native rate, 0.3 s gaps)."""
    sequence, rate, gap = log
    rate = "native rate" if rate == "native" else rate.replace("hz", " Hz")
    gap = "annotated occlusions" if gap == "occluded" else f"{gap} s gaps"
    return f"{tex_escape(sequence)} ({rate}, {gap})"


def real_motion_targets(summary, rows, logs, over):
    opf_default = next((s for s in summary if (s["estimator"], s["preset"]) == ("opf", "default")),
                       None)
    ratios = opf.hidden_ratios(rows)
    if opf_default is None or not ratios:
        return ""  # no OPF or no cvkf: nothing to check
    above = [(log, r) for log, r in ratios if not meets(r, TARGETS["log_over_cvkf"])]
    worst_log, worst = max(ratios, key=lambda item: item[1])
    inside = opf_default["inside95_translation"]
    mean_interval = ratio_interval(opf_default)
    low, high, gaps = opf_default.get("worst_gaps", (None, None, 0))
    worst_interval = "" if absent(low) else f" (worst {low:.2f}--{high:.2f} over its {gaps} gaps)"
    checks = [
        ("hidden / cvkf, geometric mean", TARGETS["hidden_over_cvkf"],
         number(opf_default["hidden_ratio"], 3) +
         ("" if mean_interval == "--" else f" ({mean_interval})"),
         meets(opf_default["hidden_ratio"], TARGETS["hidden_over_cvkf"])),
        ("hidden / cvkf, every log", TARGETS["log_over_cvkf"],
         f"{len(above)} of {len(ratios)} above{worst_interval}", not above),
        ("NEES/3, position", TARGETS["nees_position"], number(opf_default["nees_translation"], 2),
         meets(opf_default["nees_translation"], TARGETS["nees_position"])),
        ("inside the 95\\% ellipsoid", TARGETS["inside95_position"], inside_percent(inside),
         meets(inside, TARGETS["inside95_position"])),
    ]
    header = [r"OPF, default preset & target & value & \\"]
    table_rows = [[what, bounds_text(bounds, scale=100) + r"\%" if "95" in what
                   else bounds_text(bounds, spec=".2f" if "cvkf" in what else "g"), value,
                   "met" if ok else r"\textbf{missed}"]
                  for what, bounds, value, ok in checks]
    caption = (f"The project's targets on the real-motion benchmark: the OPF (default preset) "
               f"over {logs} logs, each a mean over {over}, with the 95\\% intervals over "
               f"resampled recordings and over the worst log's gaps; its worst log: "
               f"{log_name(worst_log)}, {worst:.2f} times cvkf's error.")
    return float_env("table", fitted(tabular("llll", header, table_rows)), caption,
                     "tab:realmotiontargets")


DYNAMICS_COLUMNS = ("translation / cvkf", "rotation / cvkf")


def dynamics_ablation(out, directory, benchmark):
    path = os.path.join(directory, "ablation.csv")
    if not os.path.exists(path):
        return not_run("the dynamics module's ablation",
                       writing_into("bash scripts/run_dynamics_ablation.sh", directory))
    switch_on("DynamicsAblation")
    rows = pd.read_csv(path)
    table = opf.dynamics_ablation_summary(rows)
    seeds = opf.ablation_seeds(rows, *benchmark) if benchmark else None
    over = f"{seeds} seeds" if seeds else "its seeds (ablation.csv does not record how many)"
    kinds = [c for c in table.columns if c not in DYNAMICS_COLUMNS]
    header = [r" & \multicolumn{2}{c}{all logs} & \multicolumn{" + str(len(kinds)) +
              r"}{c}{translation, per kind of motion} \\",
              r"\cmidrule(lr){2-3}\cmidrule(lr){4-" + str(3 + len(kinds)) + "}",
              "variant & translation & rotation & " + " & ".join(kinds) + r" \\"]
    body = [[tex_escape(variant)] + [number(v, 3) for v in values]
            for variant, values in zip(table.index, table.values)]
    caption = (f"The dynamics module's ablation on the real-motion benchmark: the OPF (default "
               f"preset) with its whole bank of motion models and with each model removed in "
               f"turn; its error while hidden over cvkf's on the same log, geometric mean over "
               f"the {table.attrs['logs']} logs (lower is better). Each log's errors are means "
               f"over {over}.")
    write(out, "dynamics_ablation.tex", float_env(
        "table", fitted(tabular("l" + "c" * (2 + len(kinds)), header, body)), caption,
        "tab:dynamics"))


HAND_ESTIMATORS = ("opf", "pf", "cvkf", "imm", "oapf")


def hand_scenes(out, directory):
    if not os.path.exists(os.path.join(directory, "hand_scenes.csv")):
        return not_run("the hand scenes", writing_into(
            "/usr/bin/python3 experiments/real_motion/hand_scenes.py", directory, always=True))
    switch_on("HandScenes")
    table = opf.load_hand_scenes(directory)
    header = [r"recording & scene & " + " & ".join(e.upper() for e in HAND_ESTIMATORS) +
              r" & OPF nearest & error target & right at reveal \\"]
    rows = [hand_scene_row(table, scene) for scene in
            table[["recording", "scene"]].drop_duplicates().itertuples(index=False)]
    caption = (f"The hand scenes (a hand on a recorded TUM VI path carries a cube, passes over "
               f"it, or moves a cup over a ball in the cups game; default preset): the hidden "
               f"object's translation error while hidden [mm], mean $\\pm$ "
               f"{std_over(table.seeds)}; the OPF's hypothesis nearest the truth, over the "
               f"seeds' hidden frames; the reveals at which its main hypothesis, then its most "
               f"probable one, was right (the target judges the most probable). A carry's "
               f"floor: the error of an estimator that knows where each hypothesis puts the cube "
               f"and takes the camera's evidence the first frame it is plain (the centre of the "
               f"place it left out from under the hand; the cube seen again after a put-down). "
               f"Targets (the project's): carried {bounds_text(TARGETS['carry_hidden_mm'], 'mm')}, "
               f"passed over at most the PF's + {TARGETS['pass_over_pf_mm'][1]:g} mm, cups' "
               f"nearest {bounds_text(TARGETS['cups_nearest_mm'], 'mm')}; right at reveal "
               f"{bounds_text(TARGETS['carry_right_at_reveal'], scale=100)}\\% carried and passed "
               f"over, {bounds_text(TARGETS['cups_right_at_reveal'], scale=100)}\\% in the cups "
               f"game.")
    write(out, "hand_scenes.tex", float_env(
        "table*", "\\footnotesize\n" + tabular("ll" + "c" * (len(HAND_ESTIMATORS) + 1) + "ll",
                                               header, rows), caption, "tab:hands"))


def hand_scene_row(table, scene):
    mine = table[(table.recording == scene.recording) & (table.scene == scene.scene)]
    by = mine.set_index("estimator")
    cells = [pm(1000 * by.hidden_translation.get(e, math.nan),
                1000 * by.hidden_translation_std.get(e, math.nan), 1) for e in HAND_ESTIMATORS]
    nearest = 1000 * by.nearest_hidden_translation["opf"]
    return ([tex_escape(scene.recording), scene.scene] + cells + [f"{nearest:.1f}"] +
            [hand_error_verdict(scene.scene, by), hand_reveal_verdict(scene.scene, by)])


def hand_error_verdict(scene, by):
    """The scene's error target: the carried cube's error, the passed-over cube's over the PF's,
    the cups' nearest hypothesis; a carry's floor beside it, where the table has one."""
    opf_mm = 1000 * by.hidden_translation["opf"]
    value, bounds = {
        "carry": (opf_mm, TARGETS["carry_hidden_mm"]),
        "pass": (opf_mm - 1000 * by.hidden_translation.get("pf", math.nan),
                 TARGETS["pass_over_pf_mm"]),
        "cups": (1000 * by.nearest_hidden_translation["opf"], TARGETS["cups_nearest_mm"]),
    }.get(scene, (math.nan, (None, None)))
    floor = by.get("floor_hidden_translation", {}).get("opf", math.nan)
    return mark(value, bounds) + ("" if absent(floor) else f" (floor {1000 * floor:.1f})")


def hand_reveal_verdict(scene, by):
    """The reveals at which the main hypothesis was right, then those at which the most probable
    one was, which the target judges."""
    right, reveals = by.right_at_reveal["opf"], by.reveals["opf"]
    likeliest = by.get("most_probable_right_at_reveal", {}).get("opf", math.nan)
    bounds = TARGETS.get(f"{scene}_right_at_reveal")
    if absent(reveals) or not reveals or bounds is None:
        return "--"
    if absent(likeliest):
        return f"{right:.0f}/{reveals:.0f} {mark(right / reveals, bounds)}"
    return (f"{right:.0f}/{reveals:.0f}, {likeliest:.0f}/{reveals:.0f} "
            f"{mark(likeliest / reveals, bounds)}")


# ---------------------------------------------------------------------------------------------
# Sweeps: the module ablation, the parameters, the particle count.


def sweep_rows(sweeps, name):
    path = os.path.join(sweeps, name, name + ".csv")
    rows = opf.load_sweep(path) if os.path.exists(path) else None
    return rows if rows is not None and not rows.empty else None


def module_ablation(out, sweeps):
    rows = sweep_rows(sweeps, "module_ablation")
    if rows is None:
        return not_run("the module ablation", opf.sweep_command(sweeps, "module_ablation"))
    switch_on("ModuleAblation")
    summary = opf.summarise(rows, ["experiment", "variant"])
    experiments = list(summary.experiment.unique())
    body = []
    for variant in summary.variant.unique():
        cells = []
        for experiment in experiments:
            r = summary[(summary.experiment == experiment) & (summary.variant == variant)]
            cells.append(pm(r["mean"].iloc[0], r["std"].iloc[0]) if len(r) else "--")
        body.append([tex_escape(variant)] + cells)
    header = ["variant & " + " & ".join(tex_escape(e) for e in experiments) + r" \\"]
    caption = (f"Module ablation: translation error [m] of the object of interest, mean $\\pm$ "
               f"{std_over(summary['count'])}.")
    write(out, "module_ablation.tex", float_env(
        "table", fitted(tabular("l" + "c" * len(experiments), header, body)), caption,
        "tab:ablation"))


SWEEPS = [("kappa", "opf.uncertainty.kappa", r"$\kappa$"),
          ("history_length", "opf.history_length", r"$H$"),
          ("epsilon_occ", "opf.occluder.epsilon_occ", r"$\epsilon_{occ}$"),
          ("trajectory_order", "opf.trajectory.translation_order", "fit order"),
          ("occluder_plane", "opf.occluder.plane", "occluder plane"),
          ("occluder_offset", "variant", "carry rule"),
          ("resampler", "pf.resampling.scheme", "resampler")]


def parameter_sweeps(out, sweeps):
    present = [(n, p, label, sweep_rows(sweeps, n)) for n, p, label in SWEEPS]
    present = [s for s in present if s[3] is not None]
    absent_names = [n for n, _, _ in SWEEPS if n not in {s[0] for s in present}]
    if absent_names:
        not_run(f"the parameter sweep{'s' if len(absent_names) > 1 else ''} "
                f"{', '.join(absent_names)}", opf.sweep_command(sweeps, "NAME"))
    if not present:
        return
    switch_on("Sweeps")
    write(out, "sweeps.tex", sweeps_figure(out, present))


def sweeps_figure(out, present):
    columns = 2 if len(present) > 1 else 1  # one sweep fits a column
    rows_n = math.ceil(len(present) / columns)
    fig, axes = plt.subplots(rows_n, columns, figsize=(3.5 * columns, 2.6 * rows_n), squeeze=False)
    seeds = []
    for ax, (name, parameter, label, rows) in zip(axes.flat, present):
        for experiment in rows.experiment.unique():
            mine = rows[rows.experiment == experiment].copy()
            mine["series"] = mine.estimator + " " + experiment
            opf.plot_sweep(mine, parameter, "translation_error", ax, series="series")
            seeds += list(opf.summarise(mine, ["series", parameter])["count"])
        ax.set_xlabel(label.replace("$", "").replace("\\", ""))
        ax.set_ylabel("translation [m]")
        ax.legend(fontsize=6)
    for ax in list(axes.flat)[len(present):]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "sweeps.pdf"))
    plt.close(fig)
    wide = columns > 1
    return figure_env("figure*" if wide else "figure",
                      f"\\includegraphics[width=\\{'textwidth' if wide else 'columnwidth'}]{{sweeps.pdf}}\n",
                      f"Parameter sweeps: translation error of the object of interest against each "
                      f"parameter; error bars: one {std_over(seeds)}.", "fig:sweeps")


def particle_counts(out, sweeps, bench):
    rows = sweep_rows(sweeps, "particle_counts")
    if rows is None:
        return not_run("the particle-count sweep", opf.sweep_command(sweeps, "particle_counts"))
    switch_on("ParticleCounts")
    steps = opf.load_benchmark(bench)[0] if bench and os.path.exists(bench) else None
    summary = opf.summarise(rows, ["estimator", "particles"])
    rotation = opf.summarise(rows, ["estimator", "particles"], "rotation_error_geodesic")
    fig, axes = plt.subplots(1, 2, figsize=(7, 2.6))
    opf.plot_sweep(rows, "particles", "translation_error", axes[0], log_x=True)
    opf.plot_sweep(rows, "particles", "rotation_error_geodesic", axes[1], log_x=True)
    axes[0].set_ylabel("translation [m]")
    axes[1].set_ylabel("rotation [rad]")
    for ax in axes:  # half a column each: a label per decade, or they run into each other
        ax.xaxis.set_major_locator(ticker.LogLocator(base=10.0, subs=(1.0,), numticks=10))
    fig.tight_layout()
    fig.savefig(os.path.join(out, "particles.pdf"))
    plt.close(fig)
    header = [r"N & OPF translation [m] & OPF rotation [rad] & PF translation [m] & "
              r"OPF step [$\mu$s] \\"]
    body = [[str(n), cell(summary, "opf", n), cell(rotation, "opf", n), cell(summary, "pf", n),
             step_time(steps, n)] for n in sorted(summary.particles.unique())]
    figure = ("\\includegraphics[width=\\columnwidth]{particles.pdf}\n\n" +
              fitted(tabular("rcccc", header, body)))
    write(out, "particles.tex", figure_env(
        "figure", figure, f"Accuracy against the particle count, mean $\\pm$ "
        f"{std_over(summary['count'])} (error bars the same), and the OPF's time per step from "
        f"the benchmark report.", "fig:particles"))


def cell(summary, estimator, n):
    r = summary[(summary.estimator == estimator) & (summary.particles == n)]
    return pm(r["mean"].iloc[0], r["std"].iloc[0]) if len(r) else "--"


def step_time(steps, n):
    if steps is None or steps.empty:
        return "--"
    s = steps[(steps.estimator == "opf") & (steps.particles == n)]
    return f"{s.step_us.iloc[0]:.1f}" if len(s) else "--"


# ---------------------------------------------------------------------------------------------
# Speed.


BENCHMARKS = [  # (label, benchmark or a tuple of them summed, unit, target)
    ("OPF step, 5000 + 5000 particles", "BM_EstimatorStep/opf/n:5000", "us", "opf_step_us"),
    ("PF step, 5000 + 5000", "BM_EstimatorStep/pf/n:5000", "us", None),
    ("OPF step while hidden", "BM_OpfHiddenStep/n:5000", "us", "opf_step_us"),
    ("random-walk OAPF step", "BM_EstimatorStep/oapf/n:5000", "us", None),
    ("CV Kalman step", "BM_CvKalmanStep", "us", None),
    ("IMM Kalman step", "BM_ImmStep", "us", None),
    ("translation bank's update per object", "BM_BankUpdate", "us", None),
    ("rotation bank's update per object", "BM_RotationBankUpdate/damped:1", "us", None),
    ("both banks' update per object", ("BM_BankUpdate", "BM_RotationBankUpdate/damped:1"), "us",
     "bank_update_us"),
    ("both banks, a camera's clock (1/30 s $\\pm$ 1 ms)", "BM_BanksUpdateJitteredClock", "us",
     "bank_update_us"),
    ("64 objects, 1 thread", "BM_EnsembleFrame/objects:64/threads:1/real_time", "ms", None),
    ("64 objects, 2 threads", "BM_EnsembleFrame/objects:64/threads:2/real_time", "ms",
     "frame_64_objects_2_threads_ms"),
    ("render + detect 640$\\times$480", "BM_RenderAndDetectFrame", "ms", "render_and_detect_ms"),
]
UNITS = {"us": r"$\mu$s", "ms": "ms"}


def benchmarks(out, bench):
    if not bench or not os.path.exists(bench):
        return not_run("the benchmarks", "bash bench/run_benchmarks.sh")
    switch_on("Benchmarks")
    import json
    with open(bench) as f:
        report = json.load(f)
    medians = {b["run_name"]: b for b in report["benchmarks"] if b.get("aggregate_name") == "median"}
    body = []
    for label, names, unit, target in BENCHMARKS:
        # A tuple of benchmarks is their sum (both banks update every frame of an object).
        parts = [median_time(medians.get(n), unit) for n in
                 (names if isinstance(names, tuple) else (names,))]
        value = None if None in parts else sum(parts)
        if value is not None:
            bounds = TARGETS[target] if target else None
            body.append([label, f"{value:.3g} {UNITS[unit]}",
                         bounds_text(bounds, UNITS[unit]) if bounds else "",
                         mark(value, bounds) if bounds else ""])
    header = [r"benchmark (median) & time & target & \\"]
    write(out, "benchmarks.tex", float_env(
        "table", "\\footnotesize\n" + tabular("lrll", header, body),
        "Benchmark medians and the project's targets", "tab:bench", "!htbp"))
    write(out, "machine.tex", machine(report.get("context", {}), bench) + "\n")


def median_time(benchmark, unit):
    if benchmark is None:
        return None
    scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3}[benchmark["time_unit"]]
    return benchmark["real_time"] * scale / (1e3 if unit == "ms" else 1.0)


def machine(c, bench):
    return (f"{c.get('num_cpus', '?')} CPUs at {c.get('mhz_per_cpu', '?')} MHz "
            f"(host \\texttt{{{tex_escape(c.get('host_name', '?'))}}}), "
            f"{tex_escape(c.get('compiler', '?'))}, {tex_escape(c.get('build_type', '?'))} "
            f"\\texttt{{{tex_escape(c.get('cxx_flags', '').strip())}}}, kernels "
            f"{tex_escape(c.get('particle_kernels', '?'))}, measured "
            f"{tex_escape(c.get('date', '?')[:10])}; report "
            f"\\path{{{os.path.relpath(bench, REPO)}}}.")  # \\path breaks at / and -


# ---------------------------------------------------------------------------------------------
# What is in and what is not.


SWITCHES = ("Simulated", "RealMotion", "DynamicsAblation", "HandScenes", "ModuleAblation",
            "Sweeps", "ParticleCounts", "Benchmarks")
CONTENTS = (("Simulated", "the reproduced Table~I beside the paper's and the baselines"),
            ("RealMotion", "a benchmark on recorded motion with its targets"),
            ("DynamicsAblation", "an ablation of the dynamics module's motion models"),
            ("HandScenes", "scenes of a hand moving along recorded human motion"),
            ("ModuleAblation", "a module ablation"),
            ("Sweeps", "parameter sweeps"),
            ("ParticleCounts", "the particle-count trade-off"),
            ("Benchmarks", "the speed of the implementation against its targets"))


def values_tex():
    """The switches of report.tex: \\ifHave<Name>, true for the sections that are in."""
    return "".join(f"\\newif\\ifHave{name}\\Have{name}{'true' if switches.get(name) else 'false'}\n"
                   for name in SWITCHES)


def contents_tex():
    parts = [text for name, text in CONTENTS if switches.get(name)]
    if not parts:
        return "no results yet (the last section names the commands that make them)"
    return ", ".join(parts[:-1]) + (" and " if len(parts) > 1 else "") + parts[-1]


def not_run_tex():
    """One sentence per part left out, naming the command that makes it."""
    if not not_run_here:
        return ""
    sentences = " ".join(f"{what[0].upper()}{tex_escape(what[1:])}: \\path{{{command}}}."
                         for what, command in not_run_here)
    return f"\\medskip\\noindent\\textbf{{Not run here.}} {sentences}\n"


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_report.py OUT_DIR")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    results = opf.directory_from_env("OPF_RESULTS", "results")
    sweeps = opf.directory_from_env("OPF_SWEEPS", "results/sweeps")
    bench = opf.benchmark_from_env()
    simulated(out, results)
    benchmark = real_motion(out, os.path.join(results, "real_motion"))
    dynamics_ablation(out, os.environ.get("OPF_DYNAMICS_ABLATION",
                                          os.path.join(results, "dynamics_ablation")), benchmark)
    hand_scenes(out, os.path.join(results, "hand_scenes"))
    module_ablation(out, sweeps)
    parameter_sweeps(out, sweeps)
    particle_counts(out, sweeps, bench)
    benchmarks(out, bench)
    write(out, "values.tex", values_tex())
    write(out, "contents.tex", contents_tex() + "\n")
    write(out, "not_run.tex", not_run_tex())
    for what, command in not_run_here:
        print(f"not run here: {what}: {command}", file=sys.stderr)
    print(f"generated tables and figures in {out}")


if __name__ == "__main__":
    main()
