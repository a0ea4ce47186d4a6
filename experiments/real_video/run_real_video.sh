#!/usr/bin/env bash
# The estimators on real motion with synthetic dropouts: OpenCV's sample clips (package opencv-doc)
# through `opf detect` (box.mp4: a yellow box moved by hand, HSV range, box.yaml; vtest.avi: one
# pedestrian crossing a lawn, background subtraction, vtest.yaml; cup.mp4: a dark tumbler tilted
# by hand, HSV range of dark unsaturated pixels, cup.yaml), the detections removed for
# 0.3 s and 0.6 s every 2 s (`opf dropout`, the first window 1 s after the track begins), then
# `opf evaluate` of the dropped log against the full one.
#
# One placement of the windows holds only a few occlusions (7 on the walker at 0.3 s), and which
# estimator wins a row can turn on which ones: the same runs are then repeated with the windows
# shifted by period / PHASES, PHASES times, one seed each, and the hidden errors averaged over the
# placements (phases.csv, and a table in table.md).
#
# Usage: experiments/real_video/run_real_video.sh OUT_DIR
#   OPF=path/to/opf (default <repo>/build/bin/opf), SEEDS=5, ESTIMATORS=opf,pf,cvkf,imm,oapf,
#   PHASES=10 (0: no phase sweep), CLIPS="box vtest cup" (a subset runs only those),
#   DROPOUTS="0.3 0.6" (the dropout lengths in s, each under the 2 s period: "1.0 1.5" leaves
#   glimpses of 1 s and 0.5 s between long gaps),
#   EVERY=1 (N: keep every Nth frame of each clip's detections, a slower log of the same motion:
#   box.mp4 at 10 Hz with EVERY=3), PRESET=default (paper: the paper's literal rules for every
#   estimator), CONFIG=FILE.yaml (estimator settings on top of the preset, as `opf evaluate
#   --config`: an ablation on real motion)
# Writes into OUT_DIR: clips/ (decompressed clips), <clip>.csv (the detections, the ground truth),
# <clip>_<dropout>.csv (the dropped logs), <clip>_<dropout>.txt (evaluate's output),
# overlay_<clip>/ (every 30th frame with the segmentation drawn), phases/ (the shifted logs and
# evaluate's rows), phases.csv (one row per clip, dropout, placement and estimator), table.md
# (all of it).
set -euo pipefail

if (($# != 1)); then
  echo "usage: $0 OUT_DIR" >&2
  exit 2
fi
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
opf="${OPF:-$repo/build/bin/opf}"
seeds="${SEEDS:-5}"
estimators="${ESTIMATORS:-opf,pf,cvkf,imm,oapf}"
phases="${PHASES:-10}"
every="${EVERY:-1}"
[[ "$every" =~ ^[1-9][0-9]*$ ]] || { echo "$0: EVERY must be a positive integer, not '$every'" >&2; exit 2; }
preset="${PRESET:-default}"
[[ "$preset" == default || "$preset" == paper ]] ||
  { echo "$0: PRESET must be default or paper, not '$preset'" >&2; exit 2; }
settings=(--preset "$preset")
if [ -n "${CONFIG:-}" ]; then
  if [ ! -f "$CONFIG" ] || [ ! -r "$CONFIG" ]; then
    echo "$0: CONFIG: no readable file $CONFIG" >&2
    exit 2
  fi
  settings+=(--config "$(cd "$(dirname "$CONFIG")" && pwd)/$(basename "$CONFIG")")
fi
read -r -a wanted <<<"${CLIPS:-box vtest cup}"
out="$1"
[ -x "$opf" ] || { echo "$0: no opf binary at $opf (build it, or set OPF)" >&2; exit 1; }
mkdir -p "$out/clips"
out="$(cd "$out" && pwd)"

# A clip of opencv-doc by file name, decompressed into OUT_DIR/clips when shipped gzipped.
find_clip() {
  local name="$1" packaged
  if ! packaged="$(dpkg -L opencv-doc 2>/dev/null | grep -E "/$name(\.gz)?\$" | head -n 1)" ||
    [ -z "$packaged" ]; then
    echo "$0: $name not found in package opencv-doc; install it: apt-get install opencv-doc" >&2
    return 1
  fi
  if [[ "$packaged" == *.gz ]]; then
    local cached="$out/clips/$name"
    if [ ! -s "$cached" ] || [ "$packaged" -nt "$cached" ]; then
      gunzip -c "$packaged" >"$cached.tmp" && mv "$cached.tmp" "$cached"
    fi
    echo "$cached"
  else
    echo "$packaged"
  fi
}

# Fails unless the log has at least 100 / EVERY detections and one in >= 90% of the frames between
# its first and last (the frame interval being the smallest step of t).
check_log() {
  awk -F, -v file="$1" -v least=$((100 / every)) '
    NR == 1 { next }
    $3 != "" { t[n++] = $1 + 0 }
    END {
      if (n < least) { printf "%s: only %d detections\n", file, n > "/dev/stderr"; exit 1 }
      dt = 1e9
      for (i = 1; i < n; i++) if (t[i] - t[i-1] > 0 && t[i] - t[i-1] < dt) dt = t[i] - t[i-1]
      span = int((t[n-1] - t[0]) / dt + 0.5) + 1
      printf "%s: detections in %d of %d frames (%.1f%%), t %.3f-%.3f s, %.3f s per frame\n",
             file, n, span, 100 * n / span, t[0], t[n-1], dt
      if (n < 0.9 * span) { print file ": the object is missing from too many frames" > "/dev/stderr"; exit 1 }
    }' "$1"
}

# clip name | video file | spec | extra detect options
clips=(
  "box|box.mp4|box.yaml|"
  "vtest|vtest.avi|vtest.yaml|--first 450 --frames 271"
  "cup|cup.mp4|cup.yaml|"
)
period=2
read -r -a dropouts <<<"${DROPOUTS:-0.3 0.6}"
((${#dropouts[@]} > 0)) || { echo "$0: DROPOUTS lists no length" >&2; exit 2; }
for length in "${dropouts[@]}"; do
  awk -v x="$length" -v p="$period" 'BEGIN { exit !(x ~ /^[0-9]*\.?[0-9]+$/ && x > 0 && x < p) }' ||
    { echo "$0: DROPOUTS: '$length' is not a length in seconds between 0 and $period" >&2; exit 2; }
done
summary="$out/summary.txt"
: >"$summary"
mkdir -p "$out/phases"
echo "clip,dropout,phase,start,estimator,hidden_translation,hidden_rotation,coverage" \
  >"$out/phases.csv"
ran=()
for entry in "${clips[@]}"; do
  IFS='|' read -r clip file spec extra <<<"$entry"
  [[ " ${wanted[*]} " == *" $clip "* ]] || continue
  ran+=("$clip")
  video="$(find_clip "$file")"
  log="$out/$clip.csv"
  echo "== $clip: $video" | tee -a "$summary"
  # shellcheck disable=SC2086  # $extra is a list of options
  "$opf" detect --video "$video" --objects "$here/$spec" --out "$log" $extra \
    --overlay "$out/overlay_$clip" --overlay-every 30 2>"$out/${clip}_detect.log" |
    tee -a "$summary"
  if ((every > 1)); then
    # Every Nth frame of the detections (rows of one frame share its t; the first frame is kept).
    awk -F, -v n="$every" 'NR == 1 { print; next }
      NR == 2 || $1 != last { last = $1; keep = (frames++ % n == 0) } keep' "$log" >"$log.every" &&
      mv "$log.every" "$log"
    echo "kept one frame in $every of the detections" | tee -a "$summary"
  fi
  check_log "$log" | tee -a "$summary"
  t0="$(awk -F, 'NR == 2 { print $1; exit }' "$log")"
  start="$(awk -v t="$t0" 'BEGIN { printf "%.9g", t + 1.0 }')"
  for length in "${dropouts[@]}"; do
    dropped="$out/${clip}_${length}.csv"
    "$opf" dropout --in "$log" --out "$dropped" --length "$length" --period "$period" \
      --start "$start" | tee -a "$summary"
    echo "-- $clip, dropouts of $length s every $period s: opf evaluate"
    "$opf" evaluate --in "$dropped" --truth "$log" --seeds "$seeds" --estimators "$estimators" \
      "${settings[@]}" >"$out/${clip}_${length}.txt"
    cat "$out/${clip}_${length}.txt"
    for ((phase = 0; phase < phases; ++phase)); do
      shifted="$(awk -v s="$start" -v k="$phase" -v p="$period" -v n="$phases" \
        'BEGIN { printf "%.9g", s + k * p / n }')"
      base="$out/phases/${clip}_${length}_$phase"
      "$opf" dropout --in "$log" --out "$base.csv" --length "$length" --period "$period" \
        --start "$shifted" >/dev/null
      "$opf" evaluate --in "$base.csv" --truth "$log" --seeds 1 --estimators "$estimators" \
        "${settings[@]}" --out "$base.eval.csv" >/dev/null
      awk -F, -v c="$clip" -v d="$length" -v k="$phase" -v s="$shifted" '
        NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
        { print c "," d "," k "," s "," $col["estimator"] "," $col["hidden_translation"] "," \
            $col["hidden_rotation"] "," $col["coverage"] }' "$base.eval.csv" >>"$out/phases.csv"
    done
    ((phases == 0)) || echo "-- $clip, $length s: $phases placements of the windows evaluated"
  done
done

# table.md: the clips, then each table of evaluate's output (a header line starting with
# "estimator", then one row per estimator, cells separated by two or more spaces; the header is cut
# where the first row's cells start) with all runs in one markdown table.
((${#ran[@]} > 0)) || { echo "$0: CLIPS names none of: box vtest cup" >&2; exit 2; }
CLIPS_RAN="${ran[*]}" SETTINGS="${settings[*]}" /usr/bin/python3 - "$out" "$seeds" "$phases" "$period" \
  "${dropouts[@]}" <<'EOF'
import collections, csv, math, os, pathlib, re, statistics, sys

out, seeds, phases, period = pathlib.Path(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
dropouts = sys.argv[5:]
clips = os.environ["CLIPS_RAN"].split()
lines = ["# Real-video benchmark", "",
         f"Dropouts every {period} s, the first 1 s after the track begins; {seeds} seeds; "
         "ground truth = the detections themselves (the log before the dropouts). "
         f"Settings: `{os.environ['SETTINGS']}`.", "",
         "```", *out.joinpath("summary.txt").read_text().splitlines(), "```", ""]
cell_start = re.compile(r"(?:^|(?<=\s\s))\S")
tables = []  # per table of evaluate's output: [header cells, rows]
notes = []  # the lines after the tables (of the first run)
for clip in clips:
    for dropout in dropouts:
        text = out.joinpath(f"{clip}_{dropout}.txt").read_text().splitlines()
        index, i = 0, 0
        while i < len(text):
            if not text[i].startswith("estimator"):
                if index > 0 and text[i].strip() and (clip, dropout) == (clips[0], dropouts[0]):
                    notes.append(text[i])
                i += 1
                continue
            header, rows = text[i], []
            i += 1
            while i < len(text) and text[i].strip():
                rows.append(text[i])
                i += 1
            starts = [m.start() for m in cell_start.finditer(rows[0])] if rows else [0]
            cells = [header[a:b].strip() for a, b in zip(starts, starts[1:] + [None])]
            if index == len(tables):
                tables.append([cells, []])
            for row in rows:
                tables[index][1].append([clip, f"{dropout} s"] + re.split(r"\s{2,}", row.strip()))
            index += 1
for cells, rows in tables:
    columns = ["clip", "dropout"] + cells
    lines += ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    lines.append("")
lines += notes

# The placements of the windows: per clip, dropout and estimator, the hidden translation error's
# mean over them, in how many the OPF's was at most every other estimator's, and the OPF's paired
# difference from the best other estimator (mean over the placements and its standard error): a
# row lost or won by less than about two standard errors is a tie at this many placements.
by_row = collections.defaultdict(lambda: collections.defaultdict(dict))
for r in csv.DictReader(out.joinpath("phases.csv").open()):
    by_row[(r["clip"], r["dropout"])][r["phase"]][r["estimator"]] = float(r["hidden_translation"])
if by_row:
    names = list(next(iter(next(iter(by_row.values())).values())))
    lines += ["", f"## Hidden translation error [m] over {phases} placements of the windows", "",
              f"The windows shifted by {period} s / {phases} each time (one seed per placement): "
              "the mean over placements, in how many of them the OPF's error was at most "
              "every other estimator's, and the OPF's error minus the best other estimator's "
              "[mm], paired by placement: mean +- standard error (neighbouring placements "
              "share frames, so it understates the uncertainty somewhat).", "",
              "| clip | dropout | " + " | ".join(names) + " | opf best | opf - best other [mm] |",
              "|" + "---|" * (len(names) + 4)]
    for clip in clips:
        for dropout in dropouts:
            runs = by_row.get((clip, dropout))
            if not runs:
                continue
            means = [sum(p[n] for p in runs.values()) / len(runs) for n in names]
            best = sum(1 for p in runs.values()
                       if "opf" in p and all(p["opf"] <= v for v in p.values()))
            others = [(m, n) for m, n in zip(means, names) if n != "opf"]
            paired = "–"
            if "opf" in names and others:
                rival = min(others)[1]
                d = [1000 * (p["opf"] - p[rival]) for p in runs.values()]
                mean = sum(d) / len(d)
                se = (statistics.stdev(d) / math.sqrt(len(d))) if len(d) > 1 else float("nan")
                paired = f"{mean:+.2f} ± {se:.2f} ({rival})"
            lines.append(f"| {clip} | {dropout} s | " + " | ".join(f"{m:.4f}" for m in means)
                         + f" | {best} of {len(runs)} | {paired} |")
out.joinpath("table.md").write_text("\n".join(lines) + "\n")
EOF
echo "table: $out/table.md"
