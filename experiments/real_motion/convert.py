#!/usr/bin/env python3
"""Real-motion benchmark: turns the shipped raw excerpts into measurement logs and truth files.

The raw files keep their datasets' own formats (TUM, EuRoC/ASL, KITTI, MOTChallenge) so that
they can be checked against the originals; this converter applies one fixed protocol (README.md)
so that every machine produces the same logs, byte for byte, from the same inputs and seed.

    python3 experiments/real_motion/convert.py --out DIR [--seed N] [--gaps 0.3,0.6,1 | --missed P]
"""

import argparse
import configparser
import csv
import sys
import zlib
from pathlib import Path

import numpy as np

HEADER = "t,object,x,y,z,qx,qy,qz,qw"
RESAMPLED_HZ = 30.0
GAP_LENGTHS = (0.3, 0.6, 1.0)  # s, one log per length
GAP_FIRST = 2.0  # s after the start: the first gap begins here
GAP_PERIOD = 2.5  # s between gap starts, for gaps up to 1 s
GAP_VISIBLE = 1.5  # s seen between longer gaps: their period is the length plus this
MAX_GAP = 30.0  # s: a longer gap leaves a recording excerpt (about a minute) nothing to track


def gap_period(length):
    """Seconds between gap starts: 2.5, or the gap plus 1.5 s seen where that is longer."""
    return max(GAP_PERIOD, length + GAP_VISIBLE)


def parse_missed(text):
    """'0.3' -> 0.3: the probability that the detector misses a frame, above 0 and below 1."""
    try:
        probability = float(text)
    except ValueError:
        probability = float("nan")
    if not 0.0 < probability < 1.0:
        raise ConvertError(f"--missed {text!r}: expected a probability above 0 and below 1, "
                           "as 0.3")
    return probability


MISSED = "missed"


def missed_label(probability):
    """The gap column's word for logs with missed frames: 'missed0.3'."""
    return f"{MISSED}{probability:g}"


def missed_probability(label):
    """missed_label's probability back from the gap column's word, or None for another word."""
    return float(label[len(MISSED):]) if label.startswith(MISSED) else None


def parse_gaps(text):
    """'0.3,0.6,1' -> (0.3, 0.6, 1.0): gap lengths in seconds, each in (0, 30], none twice."""
    try:
        gaps = tuple(float(g) for g in text.split(","))
    except ValueError:
        raise ConvertError(f"--gaps {text!r}: expected seconds separated by commas, as 0.3,0.6,1")
    if not all(0.0 < g <= MAX_GAP for g in gaps) or len(set(gaps)) != len(gaps):
        raise ConvertError(f"--gaps {text!r}: expected gap lengths in seconds, each above 0 and "
                           f"at most {MAX_GAP:g}, none twice")
    return gaps
POSITION_SIGMA = 0.002  # m per axis
ROTATION_SIGMA = 0.01  # rad per axis of the rotation-vector noise
PIXEL = 0.001  # protocol unit: 1 px -> 1 mm, so image motion stays in plausible metres
MOT_HIDDEN_BELOW = 0.25  # annotated visibility under which a pedestrian counts as hidden
MOT_MIN_OCCLUSION = 5  # frames: shorter dips are annotation noise, not an occlusion
MOT_VISIBLE_BEFORE = 1.0  # s visible before the first occlusion: the filter needs a track to hold
HERE = Path(__file__).resolve().parent


class ConvertError(ValueError):
    """A raw file the protocol cannot read; the message names the file, line and field."""


def _number(text, where, field):
    """Parses one field, so that a bad value is reported where it is rather than as a traceback."""
    try:
        value = float(text)
    except ValueError:
        raise ConvertError(f"{where}: field {field}: not a number: {text.strip()!r}") from None
    if not np.isfinite(value):
        raise ConvertError(f"{where}: field {field}: not finite: {text.strip()!r}")
    return value


def _rows(path, label, sep, fields, minimum=False):
    """Yields (line number, location, values, cells) of a text table, skipping `#` comments and blank lines."""
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            cells = line.strip().split(sep)
            where = f"{label}:{number}"
            if len(cells) < len(fields) or (not minimum and len(cells) != len(fields)):
                raise ConvertError(f"{where}: expected {len(fields)} fields, found {len(cells)}")
            yield number, where, [_number(c, where, n) for c, n in zip(cells, fields)], cells


def _increasing(t, lines, label):
    """Refuses repeated or backward times: interpolation and gap windows assume a clock."""
    bad = np.nonzero(np.diff(t) <= 0)[0]
    if bad.size:
        raise ConvertError(f"{label}:{lines[bad[0] + 1]}: field timestamp: time not increasing")


def read_tum(path, label=None):
    """TUM trajectory (`timestamp tx ty tz qx qy qz qw`, seconds) -> times, positions, xyzw."""
    label = label or str(path)
    fields = ("timestamp", "tx", "ty", "tz", "qx", "qy", "qz", "qw")
    lines, values = [], []
    for number, _, row, _ in _rows(path, label, None, fields):
        lines.append(number)
        values.append(row)
    if not values:
        raise ConvertError(f"{label}: no data rows")
    a = np.array(values)
    _increasing(a[:, 0], lines, label)
    return a[:, 0], a[:, 1:4], a[:, 4:8]


def read_euroc(path, label=None):
    """EuRoC/ASL ground truth CSV (ns, p xyz, q wxyz, extra columns ignored) -> s from the
    first row, m, xyzw."""
    label = label or str(path)
    fields = ("timestamp", "p_x", "p_y", "p_z", "q_w", "q_x", "q_y", "q_z")
    lines, values, stamps = [], [], []
    for number, _, row, cells in _rows(path, label, ",", fields, minimum=True):
        lines.append(number)
        values.append(row)
        # Integer nanoseconds: as a double, an epoch in ns would lose ~0.1 us per row.
        stamps.append(int(cells[0]) if cells[0].strip().isdigit() else round(row[0]))
    if not values:
        raise ConvertError(f"{label}: no data rows")
    a = np.array(values)
    _increasing(np.array(stamps, dtype=float), lines, label)
    t = np.array([s - stamps[0] for s in stamps], dtype=float) * 1e-9
    # w comes first in the ASL format; the toolkit writes x, y, z, w.
    return t, a[:, 1:4], a[:, [5, 6, 7, 4]]


def matrix_to_quaternion(r):
    """Rotation matrix -> unit quaternion (x, y, z, w), branching on the largest component so the
    division stays well conditioned for every rotation."""
    trace = np.trace(r)
    if trace > 0:
        s = 2.0 * np.sqrt(trace + 1.0)
        q = [(r[2, 1] - r[1, 2]) / s, (r[0, 2] - r[2, 0]) / s, (r[1, 0] - r[0, 1]) / s, s / 4]
    else:
        i = int(np.argmax(np.diag(r)))
        j, k = (i + 1) % 3, (i + 2) % 3
        s = 2.0 * np.sqrt(1.0 + r[i, i] - r[j, j] - r[k, k])
        q = [0.0, 0.0, 0.0, (r[k, j] - r[j, k]) / s]
        q[i] = s / 4
        q[j] = (r[j, i] + r[i, j]) / s
        q[k] = (r[k, i] + r[i, k]) / s
    q = np.array(q)
    return q / np.linalg.norm(q)


def read_kitti(path, times_path=None, label=None, times_label=None):
    """KITTI odometry poses (row-major 3x4 per line); times from a times.txt or 10 Hz from 0."""
    label = label or str(path)
    fields = tuple(f"r{i}{j}" if j < 3 else f"t{i}" for i in range(3) for j in range(4))
    values = [row for _, _, row, _ in _rows(path, label, None, fields)]
    if not values:
        raise ConvertError(f"{label}: no data rows")
    m = np.array(values).reshape(-1, 3, 4)
    if times_path is None:
        t = np.arange(len(m)) / 10.0  # KITTI odometry is recorded at 10 Hz
    else:
        times_label = times_label or str(times_path)
        rows = list(_rows(times_path, times_label, None, ("time",)))
        if len(rows) != len(m):
            raise ConvertError(f"{times_label}: {len(rows)} times for {len(m)} poses in {label}")
        t = np.array([row[0] for _, _, row, _ in rows])
        _increasing(t, [n for n, _, _, _ in rows], times_label)
    q = np.array([matrix_to_quaternion(r[:, :3]) for r in m])
    return t, m[:, :, 3].copy(), q


def read_mot(path, label=None):
    """MOTChallenge gt.txt -> {track id: (frames, boxes [left, top, width, height], visibility)},
    pedestrians only (class 1) and only rows the benchmark scores (conf flag 1)."""
    label = label or str(path)
    fields = ("frame", "id", "left", "top", "width", "height", "conf", "class", "visibility")
    tracks = {}
    for _, where, row, _ in _rows(path, label, ",", fields, minimum=True):
        if row[6] != 1 or row[7] != 1:
            continue
        tracks.setdefault(int(row[1]), []).append((where, row))
    out = {}
    for track, rows in sorted(tracks.items()):
        rows.sort(key=lambda r: r[1][0])
        frames = np.array([r[0] for _, r in rows], dtype=int)
        step = np.nonzero(np.diff(frames) != 1)[0]
        if step.size:
            raise ConvertError(f"{rows[step[0] + 1][0]}: field frame: track {track} skips or "
                               "repeats a frame (annotations are interpolated, so one frame each)")
        out[track] = (frames, np.array([r[2:6] for _, r in rows]),
                      np.array([r[8] for _, r in rows]))
    return out


def mot_frame_rate(seqinfo):
    """The sequence's frame rate from its seqinfo.ini (MOT17-05 is 14 fps, -13 is 25 fps)."""
    parser = configparser.ConfigParser()
    parser.read(seqinfo, encoding="utf-8")
    try:
        return float(parser["Sequence"]["frameRate"])
    except (KeyError, ValueError):
        raise ConvertError(f"{seqinfo}: field frameRate: missing or not a number") from None


def continuous(q):
    """Normalises quaternions and picks, row by row, the sign closer to the previous row: q and -q
    are one rotation, and a flip would read as a half-turn jump to a filter."""
    q = q / np.linalg.norm(q, axis=1, keepdims=True)
    for i in range(1, len(q)):
        if np.dot(q[i], q[i - 1]) < 0:
            q[i] = -q[i]
    return q


def slerp(q0, q1, u):
    """Spherical interpolation between rows of unit quaternions q0, q1 at fractions u."""
    dot = np.clip(np.sum(q0 * q1, axis=1), -1.0, 1.0)
    q1 = np.where(dot[:, None] < 0, -q1, q1)
    dot = np.abs(dot)
    angle = np.arccos(dot)
    small = angle < 1e-9  # nearly equal: linear interpolation is exact to rounding
    sin = np.where(small, 1.0, np.sin(angle))
    w0 = np.where(small, 1 - u, np.sin((1 - u) * angle) / sin)
    w1 = np.where(small, u, np.sin(u * angle) / sin)
    q = w0[:, None] * q0 + w1[:, None] * q1
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def resample(t, p, q, hz=RESAMPLED_HZ):
    """Poses at t0 + k/hz up to the last recorded time: positions linearly, orientations by slerp
    between the two recorded rows around each new time."""
    if len(t) < 2:
        raise ConvertError("resampling needs at least two recorded rows")
    k = np.arange(int(np.floor((t[-1] - t[0]) * hz + 1e-9)) + 1)
    tk = t[0] + k / hz
    i = np.clip(np.searchsorted(t, tk, side="right") - 1, 0, len(t) - 2)
    u = np.clip((tk - t[i]) / (t[i + 1] - t[i]), 0.0, 1.0)
    pk = p[i] + u[:, None] * (p[i + 1] - p[i])
    return k / hz, pk, slerp(q[i], q[i + 1], u)


def gap_mask(t, length):
    """Frames hidden by the synthetic gaps: t (from 0) in [2.0 + P n, 2.0 + P n + length), P the
    gap_period (2.5 s up to 1 s gaps)."""
    hidden = np.zeros(len(t), dtype=bool)
    start = GAP_FIRST
    while start <= t[-1]:
        hidden |= (t >= start) & (t < start + length)
        start += gap_period(length)
    return hidden


def missed_mask(count, probability, rng):
    """Frames a detector misses: each after the first independently with the given probability
    (the first is seen: a track starts at a detection)."""
    missed = rng.random(count) < probability
    missed[0] = False
    return missed


def quaternion_multiply(a, b):
    """Hamilton products of rows of (x, y, z, w) quaternions."""
    ax, ay, az, aw = a.T
    bx, by, bz, bw = b.T
    return np.stack([aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw,
                     aw * bw - ax * bx - ay * by - az * bz], axis=1)


def rotation_vector_to_quaternion(v):
    """exp of rotation vectors (rows) as (x, y, z, w) quaternions."""
    angle = np.linalg.norm(v, axis=1)
    scale = np.where(angle < 1e-12, 0.5, np.sin(angle / 2) / np.where(angle < 1e-12, 1, angle))
    return np.column_stack([v * scale[:, None], np.cos(angle / 2)])


def seed_for(*parts):
    """A stable per-log seed: CRC-32 of the '|'-joined parts, the same on every machine and
    Python (hash() is salted per process)."""
    return zlib.crc32("|".join(str(p) for p in parts).encode("utf-8"))


def add_noise(p, q, rng, position_sigma=POSITION_SIGMA, rotation_sigma=ROTATION_SIGMA):
    """Measurement noise on the given rows: Gaussian on position, q * exp(rotation vector)."""
    p = p + rng.normal(0.0, position_sigma, p.shape) if position_sigma else p.copy()
    if rotation_sigma:
        q = quaternion_multiply(q, rotation_vector_to_quaternion(rng.normal(0.0, rotation_sigma,
                                                                            (len(q), 3))))
    return p, q


def write_log(path, obj, t, p, q):
    """Writes rows in the toolkit's log format with 9 significant digits (sub-micrometre here)."""
    q = continuous(q)
    with open(path, "w", encoding="utf-8", newline="\n") as f:
        f.write(HEADER + "\n")
        for ti, pi, qi in zip(t, p, q):
            f.write(",".join(["%.9g" % ti, obj] + ["%.9g" % v for v in (*pi, *qi)]) + "\n")


def convert_trajectory(name, kind, t, p, q, rates, out, seed, gaps=GAP_LENGTHS, missed=None):
    """One sequence: a truth file per rate and a noisy log per rate and gap length, or, with
    `missed`, one per rate whose frames are each missed with that probability."""
    entries = []
    q = continuous(q)
    for rate in rates:
        if rate == "native":
            tr, pr, qr = t - t[0], p, q
        elif rate == "30hz":
            tr, pr, qr = resample(t, p, q)
        else:
            raise ConvertError(f"sequence {name}: field rates: unknown rate {rate!r}")
        truth = f"{name}_{rate}_truth.csv"
        write_log(out / truth, name, tr, pr, qr)
        hidings = ([(f"{g:g}", g) for g in gaps] if missed is None else
                   [(missed_label(missed), None)])
        for label, length in hidings:
            if length is None:
                rng = np.random.default_rng(seed_for(name, rate, label, seed))
                visible = ~missed_mask(len(tr), missed, rng)
            else:
                rng = np.random.default_rng(seed_for(name, rate, length, seed))
                visible = ~gap_mask(tr, length)
            pn, qn = add_noise(pr[visible], qr[visible], rng)
            log = f"{name}_{rate}_{label}.csv"
            write_log(out / log, name, tr[visible], pn, qn)
            entries.append((name, kind, rate, label, log, truth, len(tr),
                            int((~visible).sum()), tr[-1]))
    return entries


def occluded_tracks(tracks, fps):
    """Tracks that are visible first, for MOT_VISIBLE_BEFORE s, and later hidden for at least
    MOT_MIN_OCCLUSION consecutive frames: the cases the filter is meant for."""
    chosen = {}
    for track, (frames, boxes, vis) in tracks.items():
        hidden = vis < MOT_HIDDEN_BELOW
        if hidden[0] or not hidden.any() or np.argmax(hidden) < MOT_VISIBLE_BEFORE * fps:
            continue
        padded = np.concatenate([[0], hidden.astype(int), [0]])
        edges = np.nonzero(np.diff(padded))[0].reshape(-1, 2)
        runs = edges[:, 1] - edges[:, 0]
        if runs.max() >= MOT_MIN_OCCLUSION:
            chosen[track] = (frames, boxes, vis, len(runs))
    return chosen


def convert_pedestrians(name, kind, tracks, fps, out, seed):
    """One log per selected track: hidden where the annotated visibility is below the threshold,
    truth at every frame of the track's own span (so no estimate outlives its truth)."""
    entries = []
    for track, (frames, boxes, vis, _) in occluded_tracks(tracks, fps).items():
        obj = f"p{track}"
        t = (frames - frames[0]) / fps
        p = np.column_stack([(boxes[:, 0] + boxes[:, 2] / 2) * PIXEL,
                             (boxes[:, 1] + boxes[:, 3]) * PIXEL, np.zeros(len(t))])
        q = np.tile([0.0, 0.0, 0.0, 1.0], (len(t), 1))
        visible = vis >= MOT_HIDDEN_BELOW
        rng = np.random.default_rng(seed_for(name, obj, "native", "occluded", seed))
        pn = p[visible].copy()
        pn[:, :2] += rng.normal(0.0, 2 * PIXEL, (int(visible.sum()), 2))
        truth, log = f"{name}_{obj}_native_truth.csv", f"{name}_{obj}_native_occluded.csv"
        write_log(out / truth, obj, t, p, q)
        write_log(out / log, obj, t[visible], pn, q[visible])
        entries.append((name, kind, "native", "occluded", log, truth, len(t),
                        int((~visible).sum()), t[-1]))
    return entries


def load_manifest(path):
    """The sequences to convert: name, kind, format, file, aux (KITTI times.txt or MOT
    seqinfo.ini), rates (native and/or 30hz, separated by ;)."""
    with open(path, encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    for number, row in enumerate(rows, 2):
        for field in ("name", "kind", "format", "file", "rates"):
            if not (row.get(field) or "").strip():
                raise ConvertError(f"{path}:{number}: field {field}: empty")
        if row["kind"] not in ("handheld", "flying", "driving", "pedestrian"):
            raise ConvertError(f"{path}:{number}: field kind: unknown kind {row['kind']!r}")
    return rows


def convert_all(out, seed=0, manifest=HERE / "sequences.csv", gaps=GAP_LENGTHS, missed=None):
    """Converts every manifest row into `out` and writes out/index.csv; returns the index rows.
    The pedestrians keep their annotated occlusions whatever the gaps or `missed`."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    base = Path(manifest).resolve().parent
    entries = []
    for row in load_manifest(manifest):
        name, kind, fmt = row["name"], row["kind"], row["format"]
        path, label = base / row["file"], row["file"]
        rates = row["rates"].split(";")
        if fmt == "mot":
            if not (row.get("aux") or "").strip():
                raise ConvertError(f"{manifest}: sequence {name}: field aux: no seqinfo.ini")
            fps = mot_frame_rate(base / row["aux"])
            entries += convert_pedestrians(name, kind, read_mot(path, label), fps, out, seed)
            continue
        if fmt == "tum":
            t, p, q = read_tum(path, label)
        elif fmt == "euroc":
            t, p, q = read_euroc(path, label)
        elif fmt == "kitti":
            aux = row.get("aux") or None
            t, p, q = read_kitti(path, base / aux if aux else None, label, aux)
        else:
            raise ConvertError(f"{manifest}: sequence {name}: field format: unknown {fmt!r}")
        entries += convert_trajectory(name, kind, t, p, q, rates, out, seed, gaps, missed)
    with open(out / "index.csv", "w", encoding="utf-8", newline="\n") as f:
        f.write("name,kind,rate,gap,log,truth,frames,hidden_frames,duration\n")
        for e in entries:
            f.write(",".join(str(v) for v in e[:8]) + ",%.9g\n" % e[8])
    return entries


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="directory for the logs, truths and index.csv")
    parser.add_argument("--seed", type=int, default=0, help="base seed of the noise (default 0)")
    parser.add_argument("--manifest", default=HERE / "sequences.csv", type=Path)
    parser.add_argument("--gaps", default=None,
                        help="gap lengths in seconds, a log per length (default 0.3,0.6,1); gaps "
                             "over 1 s are 1.5 s apart")
    parser.add_argument("--missed", default=None,
                        help="instead of gaps, each frame after the first missed with this "
                             "probability (a detector's dropouts), a log per recording and rate")
    args = parser.parse_args(argv)
    if args.gaps is not None and args.missed is not None:
        parser.error("--gaps and --missed are two ways to hide frames: give one")
    try:
        missed = None if args.missed is None else parse_missed(args.missed)
        gaps = GAP_LENGTHS if args.gaps is None else parse_gaps(args.gaps)
        entries = convert_all(args.out, args.seed, args.manifest, gaps, missed)
    except (ConvertError, OSError) as error:
        print(f"convert.py: {error}", file=sys.stderr)
        return 1
    print(f"convert.py: {len(entries)} logs in {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
