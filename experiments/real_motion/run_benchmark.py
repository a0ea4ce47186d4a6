#!/usr/bin/env python3
"""The real-motion benchmark: every estimator, under both presets, on recorded motion.

Converts the shipped recordings (convert.py, sequences.csv) and OpenCV's three sample clips
(segmented by `opf detect`) into measurement logs with gaps, runs `opf evaluate` on each log
with every estimator and seed, in parallel across the cores, and writes into OUT_DIR:

  results.csv   tidy: one row per log, preset and estimator (means over seeds)
  profile.csv   the error against time hidden, per log, preset, estimator and 0.1 s bin
  gaps.csv      the errors per gap of each log, per preset and estimator
  summary.md    per estimator and preset: the geometric mean of its hidden error over the
                constant-velocity Kalman filter's, the worst row, the share of rows where it is
                best, the calibration pooled over every hidden frame; the geometric mean's
                95% interval over resampled recordings, the worst row's over its gaps; then
                every row
  hidden_error_<kind>.png   error against time hidden, one figure per kind of motion

Same inputs and seeds give the same bytes. Metrics: docs/metrics.md; the protocol:
experiments/real_motion/README.md.

Usage: run_benchmark.py OUT_DIR [--subset] [--seeds N] [--estimators A,B] [--jobs N]
                        [--config FILE.yaml] [--gaps 0.3,0.6,1 | --missed P]
"""

import argparse
import concurrent.futures
import csv
import math
import os
import random
import re
import shutil
import subprocess
import sys
from collections import defaultdict

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
import convert  # noqa: E402  (the protocol's gap lengths and periods)
sys.path.insert(0, os.path.join(REPO, "notebooks"))

ESTIMATORS = "opf,pf,cvkf,imm,oapf"
PRESETS = ("default", "paper")
# The paper preset is the paper's own rules for its own filter and its baseline (Table I compares
# the OPF and the PF); the Kalman filters have no paper rules, and the occlusion-aware PF is ours.
PAPER_ESTIMATORS = ("opf", "pf")
REFERENCE = ("cvkf", "default")  # every ratio is over this estimator's hidden error
# The video clips: OpenCV's samples (package opencv-doc) through `opf detect`, as the
# real-video benchmark segments them (experiments/real_video/*.yaml).
CLIPS = (("box", "box.mp4", ()), ("vtest", "vtest.avi", ("--first", "450", "--frames", "271")),
         ("cup", "cup.mp4", ()))
GAP_START = 2.0  # s, as convert.py cuts the recorded trajectories
METRICS = ("hidden_translation", "hidden_rotation", "visible_translation", "visible_rotation",
           "nees_translation", "nees_rotation", "inside95_translation", "inside95_rotation",
           "coverage", "reacquisition_error", "reacquisition_frames", "alert_precision",
           "alert_recall")


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", help="output directory")
    parser.add_argument("--subset", action="store_true",
                        help="one log per kind, 0.6 s gaps, the default preset, 1 seed "
                             "(the tests' run)")
    parser.add_argument("--seeds", type=int, default=None, help="seeds per run (default 3)")
    parser.add_argument("--estimators", default=ESTIMATORS, help=f"default {ESTIMATORS}")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="runs in parallel (default: the cores)")
    parser.add_argument("--opf", default=os.environ.get("OPF",
                                                        os.path.join(REPO, "build/bin/opf")),
                        help="the opf program (default build/bin/opf, or $OPF)")
    parser.add_argument("--no-video", action="store_true",
                        help="leave out the video clips (no opencv-doc)")
    parser.add_argument("--config", default=None,
                        help="estimator settings (FILE.yaml) for every `opf evaluate`, on top "
                             "of each preset: a sensitivity study; the summary names the file")
    parser.add_argument("--gaps", default=None,
                        help="gap lengths in seconds, a log per recording, rate and length "
                             "(default 0.3,0.6,1); gaps over 1 s are 1.5 s apart")
    parser.add_argument("--missed", default=None,
                        help="instead of gaps, each frame after the first missed with this "
                             "probability (a detector's dropouts), a log per recording and rate; "
                             "the pedestrians keep their annotated occlusions")
    args = parser.parse_args()
    if args.subset and (args.gaps is not None or args.missed is not None):
        parser.error("--subset runs the 0.6 s gaps only: leave out --gaps and --missed")
    if args.gaps is not None and args.missed is not None:
        parser.error("--gaps and --missed are two ways to hide frames: give one")
    try:
        args.gaps = convert.parse_gaps(args.gaps) if args.gaps else convert.GAP_LENGTHS
        if args.missed is not None:
            args.missed = convert.parse_missed(args.missed)
    except convert.ConvertError as error:
        parser.error(str(error))
    if args.seeds is None:
        args.seeds = 1 if args.subset else 3
    if args.seeds < 1 or args.jobs < 1:
        parser.error("--seeds and --jobs must be at least 1")
    if not os.access(args.opf, os.X_OK):
        parser.error(f"no opf program at {args.opf} (build it, or pass --opf)")
    if args.config is not None and not os.path.isfile(args.config):
        parser.error(f"--config {args.config}: no such settings file")
    return args


def run(command, **kwargs):
    """Runs a command, failing with its own words when it fails."""
    done = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if done.returncode != 0:
        sys.exit(f"run_benchmark: {' '.join(command)} failed ({done.returncode}):\n"
                 f"{done.stderr.strip()}")
    return done.stdout


def recorded_logs(out, subset, gaps, missed=None):
    """The recordings converted by convert.py with gaps of the given lengths (or frames missed
    with probability `missed`): rows of its index.csv."""
    logs_dir = os.path.join(out, "logs")
    hiding = (["--gaps", ",".join(f"{g:g}" for g in gaps)] if missed is None else
              ["--missed", f"{missed:g}"])
    run([sys.executable, os.path.join(HERE, "convert.py"), "--out", logs_dir, *hiding])
    with open(os.path.join(logs_dir, "index.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        # A sequence's pedestrians are logs of their own: the track names the row.
        if row["kind"] == "pedestrian":
            row["name"] = os.path.basename(row["log"]).split("_native_")[0]
        for key in ("log", "truth"):
            row[key] = os.path.join(logs_dir, row[key])
    return pick_subset(rows) if subset else rows


def pick_subset(rows):
    """One log per kind: its first sequence at 30 Hz (or its own rate) with 0.6 s gaps (or its
    real occlusions)."""
    chosen = {}
    for row in rows:
        if row["gap"] not in ("0.6", "occluded"):
            continue
        best = chosen.get(row["kind"])
        if best is None or (best["name"] == row["name"] and row["rate"] == "30hz"):
            chosen[row["kind"]] = row
    return list(chosen.values())


def find_clip(name):
    """A clip of opencv-doc by file name (None when the package is not there)."""
    listing = subprocess.run(["dpkg", "-L", "opencv-doc"], capture_output=True, text=True)
    for path in listing.stdout.splitlines():
        if path.endswith("/" + name) or path.endswith("/" + name + ".gz"):
            return path
    return None


def drop_detections(truth, log, probability, seed):
    """Copies a clip's detections, each row after the first emptied with the given probability
    (seeded): the frame stays, the object unobserved there, as `opf dropout` leaves it."""
    rng = np.random.default_rng(seed)
    with open(truth, newline="") as f:
        rows = list(csv.reader(f))
    missed = convert.missed_mask(len(rows) - 1, probability, rng)
    with open(log, "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(rows[0])
        for row, gone in zip(rows[1:], missed):
            writer.writerow(row[:2] + [""] * 7 + row[9:] if gone else row)


def video_logs(out, opf, subset, gaps, missed=None):
    """OpenCV's three sample clips through `opf detect`, with gaps of the recordings' protocol
    (or frames missed with probability `missed`)."""
    rows = []
    clips = CLIPS[:1] if subset else CLIPS
    for clip, file, extra in clips:
        packaged = find_clip(file)
        if packaged is None:
            sys.exit(f"run_benchmark: {file} not found in package opencv-doc; install it "
                     "(apt-get install opencv-doc) or pass --no-video")
        video_dir = os.path.join(out, "video")
        os.makedirs(video_dir, exist_ok=True)
        video = os.path.join(video_dir, file)
        if packaged.endswith(".gz"):
            with open(video, "wb") as f:
                f.write(subprocess.run(["gunzip", "-c", packaged], capture_output=True,
                                       check=True).stdout)
        else:
            shutil.copyfile(packaged, video)
        truth = os.path.join(video_dir, f"{clip}.csv")
        run([opf, "detect", "--video", video, "--objects",
             os.path.join(REPO, "experiments/real_video", f"{clip}.yaml"), "--out", truth,
             *extra])
        with open(truth, newline="") as f:
            first_t = float(next(csv.DictReader(f))["t"])
        if missed is not None:
            gap = convert.missed_label(missed)
            log = os.path.join(video_dir, f"{clip}_{gap}.csv")
            drop_detections(truth, log, missed, convert.seed_for(clip, gap))
            rows.append({"name": clip, "kind": "video", "rate": "native", "gap": gap,
                         "log": log, "truth": truth})
            continue
        for length in ((0.6,) if subset else gaps):
            gap = f"{length:g}"
            log = os.path.join(video_dir, f"{clip}_{gap}.csv")
            run([opf, "dropout", "--in", truth, "--out", log, "--length", gap, "--period",
                 str(convert.gap_period(length)), "--start", repr(first_t + GAP_START)])
            rows.append({"name": clip, "kind": "video", "rate": "native", "gap": gap,
                         "log": log, "truth": truth})
    return rows


def evaluate_command(job, opf, estimators, seeds, base, config=None):
    """The `opf evaluate` of one log under one preset (and the settings file, if any), writing
    base.csv and base_profile.csv."""
    if job["preset"] == "paper":
        estimators = ",".join(e for e in estimators.split(",") if e in PAPER_ESTIMATORS)
    command = [opf, "evaluate", "--in", job["log"], "--truth", job["truth"], "--estimators",
               estimators, "--seeds", str(seeds), "--preset", job["preset"]]
    if config is not None:
        command += ["--config", config]
    return command + ["--threads", "1", "--out", base + ".csv",
                      "--hidden-profile", base + "_profile.csv", "--gap-errors", base + "_gaps.csv"]


def evaluate(job, opf, estimators, seeds, runs_dir, config=None):
    """One `opf evaluate` of one log under one preset: its table and time-hidden profile."""
    base = os.path.join(runs_dir, f"{job['name']}_{job['rate']}_{job['gap']}_{job['preset']}")
    run(evaluate_command(job, opf, estimators, seeds, base, config))
    with open(base + ".csv", newline="") as f:
        table = list(csv.DictReader(f))
    with open(base + "_profile.csv", newline="") as f:
        profile = list(csv.DictReader(f))
    with open(base + "_gaps.csv", newline="") as f:
        gaps = list(csv.DictReader(f))
    return job, table, profile, gaps


def run_all(jobs, args, runs_dir):
    """Every job across the cores, with a progress bar on a terminal."""
    results = [None] * len(jobs)
    show = sys.stderr.isatty()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {pool.submit(evaluate, job, args.opf, args.estimators, args.seeds, runs_dir,
                               args.config): k
                   for k, job in enumerate(jobs)}
        for done, future in enumerate(concurrent.futures.as_completed(futures), 1):
            results[futures[future]] = future.result()
            if show:
                bar = "#" * (30 * done // len(jobs))
                sys.stderr.write(f"\r[{bar:<30}] {done}/{len(jobs)} runs")
                sys.stderr.flush()
    if show:
        sys.stderr.write("\n")
    return results


def number(text):
    return float(text) if text not in ("", None) else math.nan


def write_tidy(out, results):
    """results.csv, profile.csv and gaps.csv: one row per log, preset and estimator (and bin, or
    gap)."""
    keys = ("sequence", "kind", "rate", "gap", "preset", "estimator")
    rows, bins, gaps = [], [], []
    for job, table, profile, gap_rows in results:
        ident = (job["name"], job["kind"], job["rate"], job["gap"], job["preset"])
        for r in table:
            row = dict(zip(keys, ident + (r["estimator"],)), **{m: number(r[m]) for m in METRICS})
            if job["kind"] == "pedestrian":  # boxes have no orientation: nothing to score
                row.update({m: math.nan for m in METRICS if "rotation" in m})
            rows.append(row)
        for b in profile:
            bins.append(dict(zip(keys, ident + (b["estimator"],)),
                             time_hidden_from=number(b["time_hidden_from"]),
                             time_hidden_to=number(b["time_hidden_to"]),
                             frames=int(b["frames"]),
                             hidden_translation=number(b["hidden_translation"]),
                             hidden_rotation=number(b["hidden_rotation"])))
        for g in gap_rows:
            gaps.append(dict(zip(keys, ident + (g["estimator"],)), object=g["object"],
                             gap_start=number(g["gap_start"]),
                             gap_end=number(g["gap_end"]), frames=int(g["frames"]),
                             hidden_translation=number(g["hidden_translation"]),
                             hidden_rotation=number(g["hidden_rotation"])))
    for name, data in (("results.csv", rows), ("profile.csv", bins), ("gaps.csv", gaps)):
        with open(os.path.join(out, name), "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(data[0]), lineterminator="\n")
            writer.writeheader()
            writer.writerows({k: fmt(v) for k, v in r.items()} for r in data)
    return rows, bins, gaps


def fmt(value):
    return f"{value:.6g}" if isinstance(value, float) else value


def percent(share, bounds=(0.85, 0.98)):
    """A share as a percentage: whole percent, or two decimals where rounding would put a share
    outside the calibration bounds onto one of them (84.98% is not 85%)."""
    text = f"{100 * share:.0f}%"
    if math.isfinite(share) and any(round(100 * share) == round(100 * b) and share != b for b in bounds):
        text = f"{100 * share:.2f}%"
    return text


def geometric_mean(values):
    values = [v for v in values if v > 0 and math.isfinite(v)]
    return math.exp(sum(map(math.log, values)) / len(values)) if values else math.nan


# The interval of a geometric mean over logs: a cluster bootstrap over the recordings the logs were
# cut from (Davison & Hinkley, Bootstrap Methods and their Application, 1997, Sec. 3.8). A
# recording's logs at other rates and gaps, and a MOT sequence's pedestrians, are not independent
# draws: resampling logs would count one recording's motion as several.
BOOTSTRAP_RESAMPLES = 10000
BOOTSTRAP_SEED = 0  # the same logs give the same interval
INTERVAL_LEVEL = 0.95


def recording(sequence):
    """The recording a log was cut from: a pedestrian's track (mot17_02_p38) is its sequence's."""
    return re.sub(r"_p\d+$", "", sequence)


def bootstrap_draws(recordings, resamples=BOOTSTRAP_RESAMPLES, seed=BOOTSTRAP_SEED):
    """`resamples` draws of len(recordings) recordings (or gaps) with replacement, seeded: the same
    draws serve every estimator, so their intervals are comparable."""
    rng = random.Random(seed)
    names = sorted(recordings)
    return [[names[rng.randrange(len(names))] for _ in names] for _ in range(resamples)]


def geometric_mean_interval(ratios_by_log, draws, level=INTERVAL_LEVEL):
    """The percentile interval (low, high) of the geometric mean of the per-log ratios over the
    recordings of each draw (a drawn recording brings all its logs); ratios_by_log maps
    (sequence, ...) to a ratio. (nan, nan) when no log has a positive finite ratio."""
    sums = defaultdict(lambda: [0.0, 0])  # per recording: sum of log ratios, logs
    for log, ratio in ratios_by_log.items():
        if ratio > 0 and math.isfinite(ratio):
            cell = sums[recording(log[0])]
            cell[0] += math.log(ratio)
            cell[1] += 1
    means = []
    for draw in draws:
        total = count = 0
        for name in draw:
            if name in sums:
                total += sums[name][0]
                count += sums[name][1]
        if count:
            means.append(math.exp(total / count))
    return percentile_interval(means, level)


def percentile_interval(values, level=INTERVAL_LEVEL):
    """(low, high): the (1 - level) / 2 and (1 + level) / 2 quantiles of the values; (nan, nan)
    for none."""
    if not values:
        return math.nan, math.nan
    values = sorted(values)
    tail = (1.0 - level) / 2.0
    low = values[int(math.floor(tail * len(values)))]
    high = values[min(len(values) - 1, int(math.ceil((1.0 - tail) * len(values))) - 1)]
    return low, high


def gap_ratio_interval(mine, reference, resamples=BOOTSTRAP_RESAMPLES, seed=BOOTSTRAP_SEED,
                       level=INTERVAL_LEVEL):
    """A log's hidden error over the reference's, with its interval over the log's gaps resampled
    (seeded): how much the ratio rests on a few of them. mine and reference map a gap (object,
    start) to (frames, mean error); the gaps both have count. (ratio, low, high, gaps); the
    interval is (nan, nan) with fewer than two gaps."""
    sums = [(mine[g][0] * mine[g][1], reference[g][0] * reference[g][1])
            for g in sorted(set(mine) & set(reference))]
    total = sum(b for _, b in sums)
    ratio = sum(a for a, _ in sums) / total if total > 0 else math.nan
    if len(sums) < 2:
        return ratio, math.nan, math.nan, len(sums)
    ratios = []
    for draw in bootstrap_draws(range(len(sums)), resamples, seed):
        reference_sum = sum(sums[k][1] for k in draw)
        if reference_sum > 0:
            ratios.append(sum(sums[k][0] for k in draw) / reference_sum)
    return (ratio, *percentile_interval(ratios, level), len(sums))


FRAME_KEYS = ("sequence", "rate", "gap", "preset", "estimator")  # a log, preset and estimator


def pooled(rows, frames, metric):
    """A per-log mean over hidden frames, pooled over every hidden frame of the logs: each log
    weighed by its number of hidden frames (NaN logs, with nothing to score, left out)."""
    total = weight = 0.0
    for r in rows:
        n = frames.get(tuple(r[k] for k in FRAME_KEYS), 0)
        if n > 0 and not math.isnan(r[metric]):
            total += n * r[metric]
            weight += n
    return total / weight if weight > 0 else math.nan


def gaps_by_run(gaps):
    """(sequence, rate, gap, estimator, preset) -> {(object, gap start): (frames, mean error)}."""
    runs = defaultdict(dict)
    for g in gaps:
        runs[(g["sequence"], g["rate"], g["gap"], g["estimator"], g["preset"])][
            (g["object"], g["gap_start"])] = (g["frames"], g["hidden_translation"])
    return runs


def summarise(rows, bins, gaps=()):
    """Per estimator and preset: ratios over the reference, wins, calibration; with the gaps, the
    worst row's interval over its gaps."""
    frames = defaultdict(int)  # hidden frames per log, preset and estimator (over the seeds)
    for b in bins:
        frames[tuple(b[k] for k in FRAME_KEYS)] += b["frames"]
    by_log = defaultdict(dict)
    for r in rows:
        by_log[(r["sequence"], r["rate"], r["gap"])][(r["estimator"], r["preset"])] = r
    entries = sorted({(r["estimator"], r["preset"]) for r in rows},
                     key=lambda e: (PRESETS.index(e[1]), ESTIMATORS.split(",").index(e[0])
                                    if e[0] in ESTIMATORS.split(",") else 99, e[0]))
    draws = bootstrap_draws({recording(log[0]) for log in by_log})
    gap_runs = gaps_by_run(gaps)
    summary = []
    for entry in entries:
        ratios, rot_ratios, wins, logs, worst, worst_log = {}, [], 0, 0, (0.0, ""), None
        for log, runs in by_log.items():
            if entry not in runs or REFERENCE not in runs:
                continue
            logs += 1
            mine, ref = runs[entry], runs[REFERENCE]
            ratio = mine["hidden_translation"] / ref["hidden_translation"]
            ratios[log] = ratio
            rot_ratios.append(mine["hidden_rotation"] / ref["hidden_rotation"]
                              if ref["hidden_rotation"] > 0 else math.nan)
            if ratio > worst[0]:
                worst, worst_log = (ratio, "/".join(log)), log
            wins += mine["hidden_translation"] <= min(r["hidden_translation"]
                                                      for r in runs.values())
        worst_gaps = (math.nan, math.nan, 0)
        if worst_log is not None:
            _, low, high, count = gap_ratio_interval(gap_runs.get(worst_log + entry, {}),
                                                     gap_runs.get(worst_log + REFERENCE, {}))
            worst_gaps = (low, high, count)
        mine_rows = [r for r in rows if (r["estimator"], r["preset"]) == entry]
        summary.append({
            "estimator": entry[0], "preset": entry[1], "rows": logs,
            "hidden_ratio": geometric_mean(ratios.values()),
            "hidden_ratio_interval": geometric_mean_interval(ratios, draws),
            "rotation_ratio": geometric_mean(rot_ratios),
            "worst": worst[0], "worst_row": worst[1], "worst_gaps": worst_gaps,
            "best_share": wins / logs if logs else 0,
            **{m: pooled(mine_rows, frames, m) for m in (
                "nees_translation", "inside95_translation", "nees_rotation", "inside95_rotation")},
        })
    return summary


def gaps_text(s):
    """The worst row's interval over its gaps, as the table's worst cell adds it."""
    low, high, count = s.get("worst_gaps", (math.nan, math.nan, 0))
    return "" if math.isnan(low) else f"; {low:.2f}-{high:.2f} over its {count} gaps"


def hiding_text(gap):
    """The gap column as the table prints it: '0.6 s', 'annotated', '30% missed'."""
    if gap == "occluded":
        return "annotated"
    missed = convert.missed_probability(gap)
    if missed is not None:
        return f"{100 * missed:g}% missed"
    return f"{gap} s"


def interval_text(low, high):
    """An interval as the tables print it: 0.791-0.893, or a dash where there is none."""
    return "–" if math.isnan(low) else f"{low:.3f}-{high:.3f}"


def markdown(summary, rows, args):
    """summary.md: the summary table, then every row."""
    lines = ["# Real-motion benchmark", "",
             f"{'The subset: ' if args.subset else ''}{args.seeds} seed(s), estimators "
             f"`{args.estimators}` (the paper preset: {', '.join(PAPER_ESTIMATORS)}); "
             "hidden errors are means over "
             "the frames without a measurement; ratios are over the constant-velocity Kalman "
             "filter's (`cvkf`, default preset) on the same log; calibration by the NEES / 3 "
             "and the share of hidden frames inside the 95% ellipsoid, pooled over the hidden "
             "frames of every log "
             "(docs/metrics.md). The 95% interval of the geometric mean resamples the "
             f"recordings the logs were cut from, the worst log's its gaps ({BOOTSTRAP_RESAMPLES} "
             "draws each, seeded)." +
             (f" Estimator settings `{args.config}` on top of each preset." if args.config
              else ""), "",
             "| estimator | preset | logs | hidden error / cvkf (geo. mean) | 95% interval | worst "
             "| best on | rotation / cvkf | NEES/3 position | inside 95% | NEES/3 rotation | "
             "inside 95% |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for s in summary:
        reference = (s["estimator"], s["preset"]) == REFERENCE
        worst = "–" if reference else f"{s['worst']:.2f} ({s['worst_row']}{gaps_text(s)})"
        interval = "–" if reference else interval_text(*s["hidden_ratio_interval"])
        lines.append(f"| {s['estimator']} | {s['preset']} | {s['rows']} | "
                     f"{s['hidden_ratio']:.3f} | {interval} | {worst} | "
                     f"{100 * s['best_share']:.0f}% | {s['rotation_ratio']:.3f} | "
                     f"{s['nees_translation']:.3g} | {percent(s['inside95_translation'])} | "
                     f"{s['nees_rotation']:.3g} | {percent(s['inside95_rotation'])} |")
    lines += ["", "## Every log", "",
              "Hidden translation error [m] (NEES/3 of the position in brackets).", ""]
    entries = [(s["estimator"], s["preset"]) for s in summary]
    lines.append("| sequence | kind | rate | gap | "
                 + " | ".join(f"{e} ({p})" for e, p in entries) + " |")
    lines.append("|" + "---|" * (4 + len(entries)))
    by_log = defaultdict(dict)
    for r in rows:
        by_log[(r["sequence"], r["kind"], r["rate"], r["gap"])][(r["estimator"], r["preset"])] = r
    for log, runs in by_log.items():
        cells = [f"{runs[e]['hidden_translation']:.4f} ({runs[e]['nees_translation']:.2g})"
                 if e in runs else "–" for e in entries]
        sequence, kind, rate, gap = log
        gap = hiding_text(gap)
        lines.append(f"| {sequence} | {kind} | {rate} | {gap} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def draw_curves(ax, curves, styles):
    """One kind's curves: wider lines first, so that a curve on the same values as another still
    shows; the paper preset dotted and pale in its estimator's colour."""
    def drawing_order(curve):
        (estimator, preset), _ = curve
        return (preset == "paper", -styles.ESTIMATOR_STYLES.get(estimator, {}).get("linewidth",
                                                                                   1.5), estimator)

    for (estimator, preset), points in sorted(curves.items(), key=drawing_order):
        times = sorted(points)
        values = [points[t][1] / points[t][0] for t in times]
        style = dict(styles.ESTIMATOR_STYLES.get(estimator, {}))
        style.update(color=styles.ESTIMATOR_COLOURS.get(estimator, styles.OTHER_COLOUR),
                     markevery=max(1, len(times) // 8), markersize=4)
        label = estimator
        if preset == "paper":
            style.update(linestyle=(0, (1, 1)), alpha=0.6, marker=None)
            label = f"{estimator}, paper preset"
        ax.plot(times, values, label=label, **style)


def figures(out, bins):
    """Error against time hidden per kind: the frame-weighted mean over its logs, per estimator."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import opf_results  # the colours and line styles of every other figure

    by_kind = defaultdict(lambda: defaultdict(lambda: defaultdict(lambda: [0, 0.0])))
    for b in bins:
        cell = by_kind[b["kind"]][(b["estimator"], b["preset"])][b["time_hidden_to"]]
        cell[0] += b["frames"]
        cell[1] += b["frames"] * b["hidden_translation"]
    written = []
    for kind, curves in sorted(by_kind.items()):
        fig, ax = plt.subplots(figsize=(6.4, 4.0), dpi=150)
        draw_curves(ax, curves, opf_results)
        ax.set_yscale("log")
        ax.set_xlabel("time hidden [s] (end of each 0.1 s bin)")
        # The pedestrians' positions are image positions at the protocol's 1 px = 1 mm.
        unit = "[m; here 1 px = 1 mm]" if kind == "pedestrian" else "[m]"
        ax.set_ylabel(f"hidden translation error {unit}")
        ax.set_title(f"Real motion, {kind}: error against time hidden")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
        fig.tight_layout()
        path = os.path.join(out, f"hidden_error_{kind}.png")
        fig.savefig(path, dpi=200)
        fig.savefig(path[:-len(".png")] + ".svg", metadata={"Date": None})  # vector, for print
        plt.close(fig)
        written.append(path)
    return written


def prepare(args, gaps=convert.GAP_LENGTHS, missed=None):
    """The output directory, its runs/ folder and the logs with gaps of the given lengths (s) or
    frames missed with probability `missed` (the clips too, unless --no-video)."""
    out = os.path.abspath(args.out)
    runs_dir = os.path.join(out, "runs")
    os.makedirs(runs_dir, exist_ok=True)
    logs = recorded_logs(out, args.subset, gaps, missed)
    if not args.no_video:
        logs += video_logs(out, args.opf, args.subset, gaps, missed)
    return out, runs_dir, logs


def main():
    args = parse_arguments()
    out, runs_dir, logs = prepare(args, args.gaps, args.missed)
    presets = PRESETS[:1] if args.subset else PRESETS
    if not any(e in PAPER_ESTIMATORS for e in args.estimators.split(",")):
        presets = PRESETS[:1]
    jobs = [dict(log, preset=p) for log in logs for p in presets]
    print(f"run_benchmark: {len(logs)} logs, {len(args.estimators.split(','))} estimators "
          f"(the paper preset: {', '.join(PAPER_ESTIMATORS)}), {args.seeds} seeds", flush=True)
    results = run_all(jobs, args, runs_dir)
    rows, bins, gaps = write_tidy(out, results)
    summary = summarise(rows, bins, gaps)
    text = markdown(summary, rows, args)
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write(text)
    print(text.split("\n## Every log")[0])
    for path in figures(out, bins):
        print(f"figure: {path}")
    print(f"table: {os.path.join(out, 'summary.md')}")


if __name__ == "__main__":
    main()
