"""Writes the report's generated tables (LaTeX) and figures (PDF) from result files.

    /usr/bin/python3 paper/make_report.py OUT_DIR

Inputs (environment, with defaults relative to the repository): OPF_RESULTS (results/, from
`bash scripts/run_main.sh`), OPF_SWEEPS (results/sweeps/, from `opf sweep`) and OPF_BENCH (the
benchmark report under bench/results/). A missing input leaves a note in the PDF saying which
command makes it, and is listed on stderr. Nothing here is typed in by hand but the paper's own
Table I numbers.
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "notebooks"))
import opf_results as opf  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

REPO = os.path.abspath(os.path.join(HERE, ".."))
missing = []
values = {"AblationSeeds": "--"}  # macros for values.tex, for places \input cannot go (captions)


def tex_escape(text):
    return (str(text).replace("\\", r"\textbackslash{}").replace("_", r"\_")
            .replace("%", r"\%").replace("&", r"\&").replace("#", r"\#"))


def number(value, digits=4):
    return "--" if value is None or (isinstance(value, float) and math.isnan(value)) \
        else f"{value:.{digits}f}"


def absent(value):
    return value is None or (isinstance(value, float) and math.isnan(value))


def pm(mean, spread, digits=4):
    """Mean and spread; a single dash where there is no value (the paper gives none)."""
    if absent(mean):
        return "--"
    return number(mean, digits) if absent(spread) else \
        f"{number(mean, digits)} $\\pm$ {number(spread, digits)}"


def not_run(what, command):
    missing.append(f"{what}: {command}")
    return f"\\emph{{Not in this build: {tex_escape(what)}. Run \\texttt{{{tex_escape(command)}}}.}}\n"


def figure(environment, body, caption, label):
    """A float holding `body`; absent results get a one-line note in the text instead (an empty
    float would leave a near-blank page)."""
    return (f"\\begin{{{environment}}}[t]\n\\centering\n{body}"
            f"\\caption{{{caption}}}\n\\label{{{label}}}\n\\end{{{environment}}}\n")


def write(out, name, text):
    with open(os.path.join(out, name), "w") as f:
        f.write(text)


def table_one(out, results):
    table = opf.table_one(results)
    if table.empty:
        return write(out, "table_one.tex", not_run("Table I", "bash scripts/run_main.sh"))
    lines = [r"\begin{tabular}{llcccc}", r"\toprule",
             r" & & \multicolumn{2}{c}{translation [m]} & \multicolumn{2}{c}{rotation [rad]} \\",
             r"\cmidrule(lr){3-4}\cmidrule(lr){5-6}",
             r"experiment & estimator & ours & paper & ours & paper \\", r"\midrule"]
    for _, r in table.iterrows():
        lines.append(f"{tex_escape(r.experiment)} & {r.estimator.upper()} & "
                     f"{pm(r.translation_mean, r.translation_std)} & "
                     f"{pm(r.paper_translation_mean, r.paper_translation_std)} & "
                     f"{pm(r.rotation_mean, r.rotation_std)} & "
                     f"{pm(r.paper_rotation_mean, r.paper_rotation_std)} \\\\")
    seeds = sorted(set(table.seeds))
    lines += [r"\bottomrule", r"\end{tabular}", "",
              f"% seeds per estimator: {seeds}"]
    write(out, "table_one.tex", "\n".join(lines) + "\n")
    ratios = []
    for experiment, rows in table.groupby("experiment", sort=False):
        by = rows.set_index("estimator")
        if {"opf", "pf"} <= set(by.index):
            ours = by.translation_mean["opf"] / by.translation_mean["pf"]
            paper = by.paper_translation_mean["opf"] / by.paper_translation_mean["pf"]
            ratios.append(f"{tex_escape(experiment)}: {ours:.3f} (paper {paper:.3f})")
    write(out, "ratios.tex", "; ".join(ratios) + f" over {', '.join(map(str, seeds))} seeds.\n")


def baselines(out, results):
    rows = []
    for experiment in ("general_op", "sugar_drop", "baseball"):
        path = os.path.join(results, experiment + "_runs.csv")
        if not os.path.exists(path):
            continue
        runs = opf.load_runs(results, experiment)
        for estimator, g in runs.groupby("estimator", sort=False):
            rows.append((experiment, estimator, g))
    if not rows:
        return write(out, "baselines.tex", not_run("the baselines", "bash scripts/run_main.sh"))
    lines = [r"\begin{tabular}{llccc}", r"\toprule",
             r"experiment & estimator & translation [m] & rotation [rad] & hidden [m] \\",
             r"\midrule"]
    for experiment, estimator, g in rows:
        lines.append(f"{tex_escape(experiment)} & {estimator.upper()} & "
                     f"{pm(g.translation_error.mean(), g.translation_error.std(ddof=1))} & "
                     f"{pm(g.rotation_error_geodesic.mean(), g.rotation_error_geodesic.std(ddof=1))} & "
                     f"{number(g.translation_error_unobserved.mean())} \\\\")
    lines += [r"\bottomrule", r"\end{tabular}"]
    write(out, "baselines.tex", "\n".join(lines) + "\n")


def figure_three(out, results):
    made = []
    for experiment in ("general_op", "sugar_drop"):
        if os.path.exists(os.path.join(results, experiment + "_frames.csv")):
            fig = opf.figure_three(results, experiment)
            fig.savefig(os.path.join(out, f"fig3_{experiment}.pdf"))
            plt.close(fig)
            made.append(experiment)
    body = "".join(
        f"\\includegraphics[width=\\columnwidth]{{fig3_{e}.pdf}}\\\\[2pt]\n" for e in made)
    caption = (r"Translation error and $\mathrm{trace}(\tilde Q)$ of the object of interest over "
               r"time, as in the paper's Fig.~3 (seed 0, as in the CSV; hidden frames shaded; "
               r"dashed: the alert threshold $\epsilon_{safe}$).")
    write(out, "figure_three.tex", figure("figure", body, caption, "fig:three") if made
          else not_run("the Fig. 3 curves", "bash scripts/run_main.sh"))


def sweep_rows(sweeps, name):
    path = os.path.join(sweeps, name, name + ".csv")
    return opf.load_sweep(path) if os.path.exists(path) else None


def ablation(out, sweeps):
    rows = sweep_rows(sweeps, "module_ablation")
    if rows is None:
        return write(out, "ablation.tex", not_run(
            "the module ablation", "build/bin/opf sweep experiments/sweeps/module_ablation.yaml"))
    summary = opf.summarise(rows, ["experiment", "variant"])
    experiments = list(summary.experiment.unique())
    variants = list(summary.variant.unique())
    lines = [r"\begin{tabular}{l" + "c" * len(experiments) + "}", r"\toprule",
             "variant & " + " & ".join(tex_escape(e) for e in experiments) + r" \\", r"\midrule"]
    for variant in variants:
        cells = []
        for experiment in experiments:
            r = summary[(summary.experiment == experiment) & (summary.variant == variant)]
            cells.append(pm(r["mean"].iloc[0], r["ci95"].iloc[0]) if len(r) else "--")
        lines.append(tex_escape(variant) + " & " + " & ".join(cells) + r" \\")
    n = int(summary["count"].min())
    lines += [r"\bottomrule", r"\end{tabular}", "",
              f"% translation error [m], mean and 95\\% interval over {n} seeds"]
    write(out, "ablation.tex", "\n".join(lines) + "\n")
    values["AblationSeeds"] = str(n)


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
    missing_sweeps = [n for n, _, _ in SWEEPS if n not in {s[0] for s in present}]
    text = ""
    if present:
        columns = 2 if len(present) > 1 else 1  # one sweep fits a column
        rows_n = math.ceil(len(present) / columns)
        fig, axes = plt.subplots(rows_n, columns, figsize=(3.5 * columns, 2.6 * rows_n),
                                 squeeze=False)
        for ax, (name, parameter, label, rows) in zip(axes.flat, present):
            for experiment in rows.experiment.unique():
                mine = rows[rows.experiment == experiment].copy()
                mine["series"] = mine.estimator + " " + experiment
                opf.plot_sweep(mine, parameter, "translation_error", ax, series="series")
            ax.set_xlabel(label.replace("$", "").replace("\\", ""))
            ax.set_ylabel("translation [m]")
            ax.legend(fontsize=6)
        for ax in list(axes.flat)[len(present):]:
            ax.axis("off")
        fig.tight_layout()
        fig.savefig(os.path.join(out, "sweeps.pdf"))
        plt.close(fig)
        wide = columns > 1
        text = figure("figure*" if wide else "figure",
                      f"\\includegraphics[width=\\{'textwidth' if wide else 'columnwidth'}]{{sweeps.pdf}}\n",
                      "Parameter sweeps: translation error of the object of interest against each "
                      "parameter (95\\% intervals over seeds).", "fig:sweeps")
    if missing_sweeps:
        names = ", ".join(missing_sweeps)
        text += not_run(f"the {names} sweep{'s' if len(missing_sweeps) > 1 else ''}",
                        "build/bin/opf sweep experiments/sweeps/NAME.yaml")
    write(out, "sweeps.tex", text)


def particle_counts(out, sweeps, bench):
    rows = sweep_rows(sweeps, "particle_counts")
    steps, context = opf.load_benchmark(bench) if bench and os.path.exists(bench) else (None, {})
    if rows is None:
        write(out, "particles.tex", not_run(
            "the particle-count sweep", "build/bin/opf sweep experiments/sweeps/particle_counts.yaml"))
    else:
        summary = opf.summarise(rows, ["estimator", "particles"])
        rotation = opf.summarise(rows, ["estimator", "particles"], "rotation_error_geodesic")
        fig, axes = plt.subplots(1, 2, figsize=(7, 2.6))
        opf.plot_sweep(rows, "particles", "translation_error", axes[0], log_x=True)
        opf.plot_sweep(rows, "particles", "rotation_error_geodesic", axes[1], log_x=True)
        axes[0].set_ylabel("translation [m]")
        axes[1].set_ylabel("rotation [rad]")
        fig.tight_layout()
        fig.savefig(os.path.join(out, "particles.pdf"))
        plt.close(fig)
        lines = [r"\begin{tabular}{rcccc}", r"\toprule",
                 r"N & OPF translation [m] & OPF rotation [rad] & PF translation [m] & OPF step [$\mu$s] \\",
                 r"\midrule"]
        for n in sorted(summary.particles.unique()):
            def cell(frame, estimator):
                r = frame[(frame.estimator == estimator) & (frame.particles == n)]
                return pm(r["mean"].iloc[0], r["ci95"].iloc[0]) if len(r) else "--"
            step = "--"
            if steps is not None:
                s = steps[(steps.estimator == "opf") & (steps.particles == n)]
                step = f"{s.step_us.iloc[0]:.1f}" if len(s) else "--"
            lines.append(f"{n} & {cell(summary, 'opf')} & {cell(rotation, 'opf')} & "
                         f"{cell(summary, 'pf')} & {step} \\\\")
        lines += [r"\bottomrule", r"\end{tabular}"]
        body = ("\\includegraphics[width=\\columnwidth]{particles.pdf}\n\n"
                "\\resizebox{\\columnwidth}{!}{" + "\n".join(lines) + "}\n")
        write(out, "particles.tex", figure(
            "figure", body, "Accuracy against the particle count (95\\% intervals over seeds) "
            "and the OPF's time per step from the benchmark report.", "fig:particles"))


def benchmarks(out, bench):
    if not bench or not os.path.exists(bench):
        return write(out, "benchmarks.tex", not_run("the benchmarks", "bash bench/run_benchmarks.sh"))
    import json
    with open(bench) as f:
        report = json.load(f)
    medians = {b["run_name"]: b for b in report["benchmarks"] if b.get("aggregate_name") == "median"}

    def time_of(name, unit="us"):
        b = medians.get(name)
        if b is None:
            return None
        scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3}[b["time_unit"]]
        return b["real_time"] * scale / (1e3 if unit == "ms" else 1.0)

    items = [("OPF step, 5000 + 5000 particles", time_of("BM_EstimatorStep/opf/n:5000"), r"$\mu$s", r"$\le$ 50"),
             ("PF step, 5000 + 5000", time_of("BM_EstimatorStep/pf/n:5000"), r"$\mu$s", ""),
             ("OPF step while hidden", time_of("BM_OpfHiddenStep/n:5000"), r"$\mu$s", ""),
             ("random-walk OAPF step", time_of("BM_EstimatorStep/oapf/n:5000"), r"$\mu$s", ""),
             ("CV Kalman step", time_of("BM_CvKalmanStep"), r"$\mu$s", ""),
             ("IMM Kalman step", time_of("BM_ImmStep"), r"$\mu$s", ""),
             ("motion-model banks' update per object", time_of("BM_BankUpdate"), r"$\mu$s", r"$\le$ 5"),
             ("64 objects, 1 thread", time_of("BM_EnsembleFrame/objects:64/threads:1/real_time", "ms"), "ms", ""),
             ("64 objects, 2 threads", time_of("BM_EnsembleFrame/objects:64/threads:2/real_time", "ms"), "ms", r"$\le$ 2"),
             ("render + detect 640$\\times$480", time_of("BM_RenderAndDetectFrame", "ms"), "ms", r"$\le$ 10")]
    lines = [r"\begin{tabular}{lrl}", r"\toprule", r"benchmark (median) & time & target \\",
             r"\midrule"]
    for label, value, unit, target in items:
        if value is not None:
            lines.append(f"{label} & {value:.3g} {unit} & {target} {unit if target else ''} \\\\")
    lines += [r"\bottomrule", r"\end{tabular}"]
    c = report.get("context", {})
    machine = (f"{c.get('num_cpus', '?')} CPUs at {c.get('mhz_per_cpu', '?')} MHz "
               f"(host \\texttt{{{tex_escape(c.get('host_name', '?'))}}}), "
               f"{tex_escape(c.get('compiler', '?'))}, {tex_escape(c.get('build_type', '?'))} "
               f"\\texttt{{{tex_escape(c.get('cxx_flags', '').strip())}}}, kernels "
               f"{tex_escape(c.get('particle_kernels', '?'))}, measured "
               f"{tex_escape(c.get('date', '?')[:10])}; report "
               f"\\texttt{{{tex_escape(os.path.relpath(bench, REPO))}}}.")
    write(out, "benchmarks.tex", "\n".join(lines) + "\n")
    write(out, "machine.tex", machine + "\n")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_report.py OUT_DIR")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    results = opf.directory_from_env("OPF_RESULTS", "results")
    sweeps = opf.directory_from_env("OPF_SWEEPS", "results/sweeps")
    bench = os.environ.get("OPF_BENCH", os.path.join(
        REPO, "bench", "results", "intel-xeon-2cpu-2026-11-26.json"))
    table_one(out, results)
    baselines(out, results)
    figure_three(out, results)
    ablation(out, sweeps)
    parameter_sweeps(out, sweeps)
    particle_counts(out, sweeps, bench)
    benchmarks(out, bench)
    if not os.path.exists(os.path.join(out, "ratios.tex")):
        write(out, "ratios.tex", "not available in this build.\n")
    if not os.path.exists(os.path.join(out, "machine.tex")):
        write(out, "machine.tex", "not available in this build.\n")
    write(out, "values.tex", "".join(f"\\newcommand{{\\{k}}}{{{v}}}\n" for k, v in values.items()))
    for item in missing:
        print("not in this build:", item, file=sys.stderr)
    print(f"generated tables and figures in {out}")


if __name__ == "__main__":
    main()
