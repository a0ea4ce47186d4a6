#!/usr/bin/env python3
"""Scenes driven by real human motion: a hand whose path is a recorded hand-held camera's.

The hand (a 14 cm plate, as a gripper seen from above) moves along the horizontal path and the
turn about the vertical of a TUM VI hand-held recording (the shipped excerpts, raw/handheld),
scaled by 0.25 into a table's workspace and held 0.12 m above the table, under a top-down camera
at 30 Hz; a 2 cm cube rests on the table. Three scenes per recording:

  carry  the cube lies where the hand is 2.5 s in; the hand picks it up there, carries it for
         4 s along the recording and puts it down;
  pass   the cube lies where the hand is 4 s in; the hand passes over it and moves on.

and the cups game: cup B, moved by a hand (a 6 cm grip 0.2 m up) along the recording, slides over a
ball 2.5 s in, carries it and is lifted off it at 6.5 s; cup A is moved by another hand along the
next recording, and cup C rests 12 cm beside the ball.

Occlusion comes from the rendered geometry; the truth is the scene's. Each scene is written as an
experiment file and run by `opf run` with every estimator; the table gives, per scene and
estimator, the hidden object's error while hidden (the main estimate's, and for the OPF the
hypothesis nearest the truth), and how often the OPF's main hypothesis, and its most probable
one, was the right one when it was seen again. Under it, each carry's floor: the error left to an
estimator that waits for the camera's plain evidence (carry_floor).

Writes the scenes and their runs into OUT_DIR, with hand_scenes.csv (tidy) and hand_scenes.md. A
scene that no window of its recording fits from --window-start on is not run: it is named, with
the reason, on stderr and under the table in hand_scenes.md.

With --unseen it runs instead the scenes on motion they were not built on: every room and two
EuRoC flights' paths (MH_01, V1_01) as the hands', from 2, 6 and 12 s, leaving out any scene
identical to a shipped one or to one already run; rows are named recording@start.

With --unsized the detector states no body's size (the experiments' `state_sizes: false`), as
most pose detectors do: the occluder module then measures how far each cover reaches.

Usage: hand_scenes.py OUT_DIR [--opf build/bin/opf] [--seeds 5] [--recordings N]
                       [--window-start S | --unseen] [--unsized]
"""

import argparse
import csv
import json
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
import convert  # noqa: E402

RECORDINGS = (("tumvi_room1", convert.read_euroc, "raw/handheld/tumvi_room1.csv"),
              ("tumvi_room2", convert.read_tum, "raw/handheld/tumvi_room2.txt"),
              ("tumvi_room4", convert.read_euroc, "raw/handheld/tumvi_room4.csv"),
              ("tumvi_room5", convert.read_tum, "raw/handheld/tumvi_room5.txt"))
# --unseen: two EuRoC flights' paths as the hands' as well, every recording from each of these
# starts (s): motion the shipped scenes (the rooms from WINDOW_START) were not built on.
FLIGHTS = (("euroc_mh01", convert.read_tum, "raw/flying/euroc_mh01.txt"),
           ("euroc_v101", convert.read_euroc, "raw/flying/euroc_v101.csv"))
UNSEEN_STARTS = (2.0, 6.0, 12.0)
RATE = 30.0
DURATION = 10.0        # s of each scene
WINDOW_START = 2.0     # s into the recording: the earliest window's start (--window-start)
SCALE = 0.25           # the recording's horizontal motion into the workspace
HOVER = 0.12           # m above the table, the hand's centre
PLATE = (0.14, 0.14, 0.04)  # m, the hand's size
CAMERA_HEIGHT = 0.8    # m above the table, looking straight down at the workspace's centre
FIELD_OF_VIEW = 75     # degrees, vertical (along the table's x)
WORKSPACE = (0.55, 0.0)  # m, the table's centre under the camera
PICK, PLACE, PASS = 2.5, 6.5, 4.0  # s
COVER, LIFT = 2.5, 6.5  # s: in the cups game, cup B over the ball, and lifted off it
ESTIMATORS = "opf,pf,cvkf,imm,oapf"
# m: the hand's centre this far from the cube's leaves it in view (the plate's half-diagonal 9.9 cm
# plus the cube's half-width).
CLEAR = 0.11
# m: the largest offset of a path from the workspace's centre along either table axis that keeps
# the plate wholly in the camera's view: at the plate's top (0.66 m below the camera) the field
# spans +-0.506 m along the image's vertical (x), less the plate's half-diagonal 9.9 cm: 0.41 m. A
# window whose path leaves the view would hide the hand itself and say nothing of the hypotheses.
IN_VIEW = ((CAMERA_HEIGHT - HOVER - PLATE[2] / 2) * np.tan(np.radians(FIELD_OF_VIEW / 2)) -
           np.hypot(PLATE[0], PLATE[1]) / 2)


class NoWindow(Exception):
    """No stretch of a recording from the requested start makes the scene (see hand_path)."""


def windows(read, path, start=WINDOW_START):
    """(t, x, y, yaw) at 30 Hz over the scene for each window of the recording whose path stays in
    view (in_view), from `start` s on in steps of 0.5 s: the horizontal path scaled into the
    workspace, the turn about the vertical."""
    t, p, q = read(os.path.join(HERE, path))
    t = t - t[0]
    # Yaw about the vertical from the quaternion (x, y, z, w), unwrapped.
    yaw_all = np.unwrap(np.arctan2(2 * (q[:, 3] * q[:, 2] + q[:, 0] * q[:, 1]),
                                   1 - 2 * (q[:, 1] ** 2 + q[:, 2] ** 2)))
    times = np.arange(0.0, DURATION + 1e-9, 1.0 / RATE)
    for first in np.arange(start, t[-1] - DURATION, 0.5):
        xs = np.interp(times + first, t, p[:, 0])
        ys = np.interp(times + first, t, p[:, 1])
        x = WORKSPACE[0] + SCALE * (xs - xs.mean())
        y = WORKSPACE[1] + SCALE * (ys - ys.mean())
        yaw = np.interp(times + first, t, yaw_all)
        if in_view(x, y):
            yield times, x, y, yaw - yaw[0]


def in_view(x, y):
    """Whether a path stays within IN_VIEW of the workspace's centre along both table axes."""
    return bool(np.all(np.abs(np.asarray(x) - WORKSPACE[0]) <= IN_VIEW) and
                np.all(np.abs(np.asarray(y) - WORKSPACE[1]) <= IN_VIEW))


def hand_path(read, path, cube_time, left_at, start=WINDOW_START):
    """The first window from `start` on in which the cube, lying where the hand is at cube_time,
    is seen before the hand reaches it, and after the hand leaves where it is at left_at."""
    for times, x, y, yaw in windows(read, path, start):
        cube = (at(times, x, cube_time), at(times, y, cube_time))
        left = (at(times, x, left_at), at(times, y, left_at))
        if clear_at_both_ends(times, x, y, cube, left):
            return times, x, y, yaw
    raise NoWindow(f"no window of {path} from {start:g} s stays in the camera's view and leaves "
                   "the cube in view at both ends")


def clear_at_both_ends(times, x, y, cube, left):
    """The path is at least CLEAR from where the cube lies over the first second, and from where
    it is left over the last second."""
    def distance(t0, t1, place):
        span = (times >= t0) & (times <= t1)
        return np.hypot(x[span] - place[0], y[span] - place[1]).min()
    return distance(0.0, 1.0, cube) >= CLEAR and distance(DURATION - 1.0, DURATION, left) >= CLEAR


def cups_paths(moving_b, moving_a, start=WINDOW_START):
    """Cup B's path (the first window of its recording that leaves the ball in view before B
    covers it and after B is lifted off it) and cup A's (the first window of the other recording
    that leaves it in view then too)."""
    times, bx, by, _ = hand_path(moving_b[1], moving_b[2], COVER, LIFT, start)
    ball = (at(times, bx, COVER), at(times, by, COVER))
    left = (at(times, bx, LIFT), at(times, by, LIFT))
    for _, ax, ay, _ in windows(moving_a[1], moving_a[2], start):
        if clear_at_both_ends(times, ax, ay, ball, left):
            return times, (bx, by), (ax, ay)
    raise NoWindow(f"no window of {moving_a[2]} from {start:g} s stays in the camera's view and "
                   "leaves the ball in view")


def at(times, values, t):
    return float(np.interp(t, times, values))


def scene_header(comment, experiment, frames, target, table_z):
    """The lines every scene starts with: the top-down camera over the workspace, the detector's
    noise and threshold, the object of interest and the table (its centre at table_z)."""
    return [f"# {comment}; hand_scenes.py",
            f"name: {experiment}", f"rate: {int(RATE)}", f"frames: {frames}",
            "camera:", f"  position: [0.55, 0.0, {CAMERA_HEIGHT}]", "  look_at: [0.55, 0.0, 0.0]",
            "  up: [1, 0, 0]", f"  vertical_fov_deg: {FIELD_OF_VIEW}",
            "measurement:", "  position_noise: 0.002", "  orientation_noise: 0.01",
            "  min_visible_fraction: 0.3", "  min_area_pixels: 30",
            f"objects_of_interest: {target}", "bodies:",
            "  - name: table", "    shape: box", "    size: [1.4, 1.4, 0.02]",
            "    colour: [150, 150, 150]", "    tracked: false",
            f"    waypoints: [{{t: 0, position: [0.55, 0.0, {table_z}]}}]"]


def without_sizes(text):
    """The experiment file `text` with a detector that states no body's size: its measurement
    section says `state_sizes: false`."""
    if "\nmeasurement:\n" not in text:
        raise ValueError("the experiment file has no measurement section")
    return text.replace("\nmeasurement:\n", "\nmeasurement:\n  state_sizes: false\n", 1)


def scene_yaml(name, kind, times, x, y, yaw):
    """The experiment file: camera, table, hand on its recorded path, the cube."""
    resting_t = PICK if kind == "carry" else PASS
    cube = (at(times, x, resting_t), at(times, y, resting_t))
    lines = scene_header(f"{kind} of a 2 cm cube by a hand on a recorded path ({name})",
                         f"{name}_{kind}", len(times), "cube", -0.01)
    lines += ["  - name: hand", "    shape: box", f"    size: [{PLATE[0]}, {PLATE[1]}, {PLATE[2]}]",
             "    colour: [0, 255, 255]", "    waypoints:"]
    for t, xi, yi, a in zip(times, x, y, yaw):
        lines.append(f"      - {{t: {t:.6f}, position: [{xi:.6f}, {yi:.6f}, {HOVER}], "
                     f"yaw_pitch_roll: [{a:.6f}, 0, 0]}}")
    lines += ["  - name: cube", "    shape: box", "    size: [0.02, 0.02, 0.02]",
              "    colour: [255, 0, 255]",
              f"    waypoints: [{{t: 0, position: [{cube[0]:.6f}, {cube[1]:.6f}, 0.01]}}]"]
    if kind == "carry":
        lines += ["    carried:", f"      - {{from: {PICK}, to: {PLACE}, by: hand}}"]
    return "\n".join(lines) + "\n"


def cups_yaml(name, times, b, a):
    """The cups game on recorded paths: cups A and B each moved by a hand (a 6 cm grip 0.2 m up,
    leaving the cup's rim in view) along a recording, a third cup C resting 12 cm beside the ball
    (clear of where it is left); the ball lies where B is at COVER, B slides over it and carries
    it until LIFT, then is lifted off it and moves on."""
    ball = (at(times, b[0], COVER), at(times, b[1], COVER))
    lines = scene_header(f"the cups game on recorded paths ({name})", f"{name}_cups",
                         len(times), "ball", -0.035)
    lines += ["  - name: ball", "    shape: sphere", "    size: [0.025]",
              "    colour: [255, 0, 0]",
             f"    waypoints: [{{t: 0, position: [{ball[0]:.6f}, {ball[1]:.6f}, 0.0]}}]",
             "    carried:", f"      - {{from: {COVER}, to: {LIFT}, by: cup_b}}"]
    left = (at(times, b[0], LIFT), at(times, b[1], LIFT))
    c = next(p for p in ((ball[0] + dx, ball[1] + dy) for dx, dy in
                         ((0.12, 0), (-0.12, 0), (0, 0.12), (0, -0.12)))
             if np.hypot(p[0] - left[0], p[1] - left[1]) >= CLEAR)
    lines += ["  - name: cup_c", "    shape: cylinder", "    size: [0.045, 0.1]",
              "    colour: [255, 0, 255]",
              f"    waypoints: [{{t: 0, position: [{c[0]:.6f}, {c[1]:.6f}, 0.03]}}]"]
    for cup, hand, (x, y), colours in (("cup_a", "hand_a", a, ("[0, 255, 0]", "[0, 255, 255]")),
                                       ("cup_b", "hand_b", b, ("[0, 0, 255]", "[255, 255, 0]"))):
        for body, shape, size, z, tint in ((cup, "cylinder", "[0.045, 0.1]", 0.03, colours[0]),
                                           (hand, "box", "[0.06, 0.06, 0.03]", 0.2, colours[1])):
            lines += [f"  - name: {body}", f"    shape: {shape}", f"    size: {size}",
                      f"    colour: {tint}", "    waypoints:"]
            lines += [f"      - {{t: {t:.6f}, position: [{xi:.6f}, {yi:.6f}, {z}]}}"
                      for t, xi, yi in zip(times, x, y)]
    return "\n".join(lines) + "\n"


def hidden_errors(summary_json, experiment):
    """Per estimator: the cube's mean hidden translation error of the main estimate and of the
    hypothesis nearest the truth, over the seeds' hidden frames, and their number (`opf run`'s
    summary.json, `hypotheses`)."""
    with open(summary_json) as f:
        runs = json.load(f)["experiments"][experiment]
    return {e: (r["hypotheses"]["main_hidden_translation"],
                r["hypotheses"]["nearest_hidden_translation"], r["hypotheses"]["hidden_frames"])
            for e, r in runs.items()}


def opf_rows(frames_csv):
    """The OPF's rows of `opf run`'s frames CSV (every object, seed and hypothesis), read once
    for both reveals and carry_floor."""
    with open(frames_csv) as f:
        return [r for r in csv.DictReader(f) if r["estimator"] == "opf"]


def reveals(rows, target="cube", carriers=None):
    """The OPF's reveals of the target (`rows`: opf_rows): for each hidden span of every seed
    that ends in a detection, whether the main hypothesis in its last hidden frame was the right
    one, and whether the most probable one was: `carried` (by one of `carriers`, when given) if
    the target moved more than 1 cm over the span (the truth), `left` otherwise. Returns (main
    right, most probable right, reveals)."""
    spans = {}  # seed -> list of [first row, last row] of the hidden spans, in frame order
    frames = {}  # (seed, frame) -> every hypothesis's row
    rows = [r for r in rows if r["object"] == target]
    for r in rows:
        frames.setdefault((r["seed"], r["frame"]), []).append(r)
    right = likeliest_right = total = 0
    previous = {}
    for r in (r for r in rows if r["hypothesis"] == "0"):
        seed = r["seed"]
        hidden = r["visible"] == "0"
        span = spans.setdefault(seed, [])
        if hidden and not (previous.get(seed) and previous[seed]["visible"] == "0"):
            span.append([r, r])
        elif hidden:
            span[-1][1] = r
        elif previous.get(seed) and previous[seed]["visible"] == "0":
            first, last = span[-1]
            moved = np.hypot(float(last["true_x"]) - float(first["true_x"]),
                             float(last["true_y"]) - float(first["true_y"])) > 0.01
            likeliest = max(frames[(seed, last["frame"])],
                            key=lambda h: float(h.get("probability") or 1.0))
            right += is_right(last, moved, carriers)
            likeliest_right += is_right(likeliest, moved, carriers)
            total += 1
        previous[seed] = r
    return right, likeliest_right, total


def is_right(row, moved, carriers):
    """Whether a hypothesis's row says what happened: carried (by one of `carriers`) if moved."""
    mode = row["mode"].split("+")[0]
    if moved:
        return mode == "carried" and (carriers is None or row.get("model") in carriers)
    return mode == "left"


def yaw_turn(yaw):
    """The rotation by `yaw` (rad) about the vertical."""
    c, s = np.cos(yaw), np.sin(yaw)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def plate_covers(place, hand, yaw):
    """Whether the hand's plate (PLATE, centred at `hand`, turned by `yaw` about the vertical)
    stands on the line of sight from `place` to the camera: the segment between them, in the
    plate's frame, crosses its box (the slab test)."""
    camera = np.array([WORKSPACE[0], WORKSPACE[1], CAMERA_HEIGHT])
    into_plate = yaw_turn(yaw).T
    start = into_plate @ (np.asarray(place, float) - hand)
    along = into_plate @ (camera - hand) - start
    half = np.array(PLATE) / 2
    lo, hi = 0.0, 1.0
    for k in range(3):
        if abs(along[k]) < 1e-12:
            if abs(start[k]) > half[k]:
                return False
            continue
        t0, t1 = sorted(((-half[k] - start[k]) / along[k], (half[k] - start[k]) / along[k]))
        lo, hi = max(lo, t0), min(hi, t1)
        if lo > hi:
            return False
    return True


def carry_floor(rows, target="cube", hand="hand"):
    """The error left in a carry to an estimator that waits for the camera's plain evidence, under
    the OPF's rules (`left` is the prior; a hypothesis changes only on evidence): the mean error
    over the target's hidden frames [m] of one that knows where each hypothesis puts it and takes
    the evidence the first frame it is plain. It says `left` until the target moves and the centre
    of the place it left is out from under the plate (seen empty), then `carried` at the target's
    place on the hand, until the target is seen again: after a put-down nothing the camera shows
    moves it off the hand. (Evidence read sooner, from a place at the plate's edge, can beat it,
    or mislead in a pass-over.) Returns (floor,
    the pick-up's share: `left` while the target moves, the put-down's share: `carried` while it
    stays), each over every seed's hidden frames of the OPF's run (`rows`: opf_rows)."""
    truth = {}  # (seed, frame) -> {object: (position, yaw about the vertical, visible)}
    for r in rows:
        if r["hypothesis"] == "0" and r["object"] in (target, hand):
            position = np.array([float(r["true_x"]), float(r["true_y"]), float(r["true_z"])])
            yaw = 2.0 * np.arctan2(float(r["true_qz"]), float(r["true_qw"]))
            truth.setdefault((r["seed"], int(r["frame"])), {})[r["object"]] = (
                position, yaw, r["visible"] == "1")
    pick_up = put_down = 0.0
    hidden = 0
    previous_seed = rest = previous = offset = None
    for (seed, _), objects in sorted(truth.items()):
        cube, _, seen = objects[target]
        centre, yaw, _ = objects[hand]
        turn = yaw_turn(yaw)
        if seed != previous_seed or seen:  # a seed's start or a sighting: left where it is seen
            previous_seed, rest, previous, offset, dismissed = seed, cube, cube, None, False
        if np.linalg.norm(cube - previous) > 1e-6:  # it moves: on the hand, at this offset
            offset = turn.T @ (cube - centre)
        previous = cube
        on_hand = offset is not None and np.linalg.norm(centre + turn @ offset - cube) < 1e-4
        dismissed = dismissed or (on_hand and not plate_covers(rest, centre, yaw))
        if seen:
            continue
        hidden += 1
        if on_hand and not dismissed:
            pick_up += np.linalg.norm(cube - rest)
        elif offset is not None and not on_hand:
            put_down += np.linalg.norm(centre + turn @ offset - cube)
    if hidden == 0:
        return 0.0, 0.0, 0.0
    return (pick_up + put_down) / hidden, pick_up / hidden, put_down / hidden


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out")
    parser.add_argument("--opf", default=os.path.join(REPO, "build", "bin", "opf"))
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--recordings", type=int, default=None)
    parser.add_argument("--window-start", type=float, default=None,
                        help="s into each recording where the windows begin (default 2): other "
                        "stretches of the same recordings, motion the scenes were not built on")
    parser.add_argument("--unseen", action="store_true",
                        help="the scenes on motion the shipped ones were not built on: the rooms "
                        "and two EuRoC flights as the hands' paths, from 2, 6 and 12 s, any "
                        "scene already run left out (rows recording@start)")
    parser.add_argument("--unsized", action="store_true",
                        help="a detector that states no body's size (the pose alone): the "
                        "occluder module measures how far each cover reaches")
    args = parser.parse_args()
    if args.seeds < 1:
        parser.error(f"--seeds: {args.seeds} is not a number of seeds >= 1")
    if args.recordings is not None and not 1 <= args.recordings <= len(RECORDINGS):
        parser.error(f"--recordings: {args.recordings} is not between 1 and {len(RECORDINGS)}, "
                     "the recordings there are")
    if not os.access(args.opf, os.X_OK):
        parser.error(f"no opf program at {args.opf} (build it, or pass --opf)")
    if args.unseen and (args.window_start is not None or args.recordings is not None):
        parser.error("--unseen takes its own recordings and starts: not with --window-start or "
                     "--recordings")
    start = WINDOW_START if args.window_start is None else args.window_start
    if not start >= 0.0:
        parser.error(f"--window-start: {start} is not a time >= 0 s")
    os.makedirs(args.out, exist_ok=True)
    if args.unseen:
        built, skipped = unseen_scenes()
    else:
        built, skipped = build_scenes(RECORDINGS, start, args.recordings)
        built = [(name, start, *rest) for name, *rest in built]
    for name, kind, reason in skipped:
        print(f"hand_scenes: {name} {kind} not run: {reason}", file=sys.stderr)
    if not built:
        sys.exit(f"hand_scenes: no scene can be built from {start:g} s into the recordings")
    table = []
    for name, begins, kind, text, target, carriers in built:
        text = without_sizes(text) if args.unsized else text
        # Each start's scenes in a folder of their own: they share names.
        out = os.path.join(args.out, f"from_{begins:g}s") if args.unseen else args.out
        table.append((f"{name}@{begins:g}" if args.unseen else name, kind,
                      *run_scene(args, f"{name}_{kind}", text, target, carriers, out)))
    write_results(args.out, table, skipped)


def unseen_scenes():
    """The scenes of every recording, FLIGHTS then RECORDINGS (the cups game's cup A from the next
    in that order), from each of UNSEEN_STARTS, as (recording, start, scene, experiment file's
    text, object of interest, its carriers), leaving out any scene identical to a shipped one
    (RECORDINGS from WINDOW_START) or to one already listed; and those no window fits, as
    (recording@start, scene, why)."""
    seen = {text for _, _, text, _, _ in build_scenes(RECORDINGS, WINDOW_START)[0]}
    built, skipped = [], []
    for start in UNSEEN_STARTS:
        scenes, missing = build_scenes(FLIGHTS + RECORDINGS, start)
        for name, kind, text, target, carriers in scenes:
            if text not in seen:
                seen.add(text)
                built.append((name, start, kind, text, target, carriers))
        skipped += [(f"{name}@{start:g}", kind, why) for name, kind, why in missing]
    return built, skipped


def build_scenes(recordings, start, count=None):
    """The scenes of each of the first `count` recordings (all by default) from `start` s on, as
    (recording, scene, experiment file's text, object of interest, its carriers), and those no
    window fits, as (recording, scene, why); the cups game takes cup B from a recording and cup A
    from the next in `recordings`."""
    built, skipped = [], []
    for i, (name, read, path) in enumerate(recordings[:count]):
        for kind, cube_time, left_at in (("carry", PICK, PLACE), ("pass", PASS, PASS)):
            try:
                times, x, y, yaw = hand_path(read, path, cube_time, left_at, start)
            except NoWindow as e:
                skipped.append((name, kind, str(e)))
                continue
            built.append((name, kind, scene_yaml(name, kind, times, x, y, yaw), "cube", None))
        try:
            times, b, a = cups_paths(recordings[i], recordings[(i + 1) % len(recordings)], start)
        except NoWindow as e:
            skipped.append((name, "cups", str(e)))
            continue
        built.append((name, "cups", cups_yaml(name, times, b, a), "ball", {"cup_b", "hand_b"}))
    return built, skipped


def run_scene(args, experiment, text, target, carriers=None, out=None):
    """Writes the experiment file into `out` (args.out by default), runs every estimator on it
    and returns the target's hidden errors (hidden_errors), the OPF's reveals (reveals) and, for
    a carry, the error left to an estimator that waits for plain evidence (carry_floor; None
    otherwise)."""
    out = out or args.out
    os.makedirs(out, exist_ok=True)
    scene = os.path.join(out, f"{experiment}.yaml")
    with open(scene, "w") as f:
        f.write(text)
    run_dir = os.path.join(out, experiment)
    command = [args.opf, "run", scene, "--estimators", ESTIMATORS, "--seeds", str(args.seeds),
               "--quiet", "--out", run_dir]
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"hand_scenes: {' '.join(command)} failed ({done.returncode}):\n"
                 f"{done.stderr.strip() or '(it wrote no message)'}")
    frames = opf_rows(os.path.join(run_dir, f"{experiment}_frames.csv"))
    floor = carry_floor(frames, target) if experiment.endswith("_carry") else None
    return (hidden_errors(os.path.join(run_dir, "summary.json"), experiment),
            reveals(frames, target, carriers), floor)


def reveal_totals(table):
    """The line under the table: per scene kind, at how many of its reveals the OPF's most
    probable hypothesis was the right one ("" for no rows)."""
    counts = {}
    for _, kind, _, (_, likeliest, total), _ in table:
        right, all_ = counts.get(kind, (0, 0))
        counts[kind] = (right + likeliest, all_ + total)
    if not counts:
        return ""
    return ("\nThe most probable hypothesis right at reveal: " +
            "; ".join(f"{kind} {right} of {all_}" for kind, (right, all_) in counts.items()) +
            ".\n")


def write_results(out, table, skipped=()):
    """hand_scenes.csv (tidy) and hand_scenes.md (the table, the carries' floor, and the scenes not
    run), the tables also printed. Each row of `table` is (recording, scene, hidden_errors,
    reveals, carry_floor or None)."""
    estimators = ESTIMATORS.split(",")
    with open(os.path.join(out, "hand_scenes.csv"), "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["recording", "scene", "estimator", "hidden_frames", "hidden_translation",
                         "nearest_hidden_translation", "right_at_reveal",
                         "most_probable_right_at_reveal", "reveals", "floor_hidden_translation"])
        for name, kind, errors, (right, likeliest, total), floor in table:
            for e in estimators:
                main_error, nearest, frames = errors[e]
                revealed = [right, likeliest, total] if e == "opf" else ["", "", ""]
                writer.writerow([name, kind, e, frames, f"{main_error:.6g}", f"{nearest:.6g}"] +
                                revealed + ["" if floor is None else f"{floor[0]:.6g}"])
    lines = ["| recording | scene | hidden frames | " + " | ".join(estimators) +
             " | opf: nearest hypothesis | opf: right at reveal, main | most probable |",
             "|---|---|---|" + "---|" * (len(estimators) + 3)]
    for name, kind, errors, (right, likeliest, total), _ in table:
        cells = [f"{errors[e][0] * 1000:.1f}" for e in estimators]
        lines.append(f"| {name} | {kind} | {errors['opf'][2]} | " + " | ".join(cells) +
                     f" | {errors['opf'][1] * 1000:.1f} | {right}/{total} | "
                     f"{likeliest}/{total} |")
    text = ("The hidden object's mean translation error while hidden [mm] (the cube; in the "
            "cups game the ball), over the seeds; hidden frames summed over the seeds. Right at "
            "reveal: the reveals at which the OPF's main hypothesis, and its most probable one, "
            "in the last hidden frame was the right one (carried, in the cups game by cup B or "
            "its hand, if the object moved while hidden; left otherwise).\n\n" +
            "\n".join(lines) + "\n")
    text += reveal_totals(table)
    text += floor_table(table)
    if skipped:
        text += ("\nNot run, no window of the recording fits:\n\n" +
                 "".join(f"- {name} {kind}: {reason}\n" for name, kind, reason in skipped))
    with open(os.path.join(out, "hand_scenes.md"), "w") as f:
        f.write(text)
    print(text, end="")


def floor_table(table):
    """The carries' floor (carry_floor) beside the OPF's main estimate, in hand_scenes.md ("" for
    no carry)."""
    rows = [(name, errors["opf"][0], floor) for name, _, errors, _, floor in table
            if floor is not None]
    if not rows:
        return ""
    return ("\nThe carries' floor [mm]: the main estimate's error while hidden for an estimator "
            "that knows where each hypothesis puts the cube and takes the camera's evidence the "
            "first frame it is plain: `left` until the centre of the place it left is out from "
            "under the plate, then carried, also after a put-down until the cube is seen (pick-up "
            "and put-down: their shares of the floor).\n\n"
            "| recording | opf | floor | pick-up | put-down |\n|---|---|---|---|---|\n" +
            "".join(f"| {name} | {opf * 1000:.1f} | {floor[0] * 1000:.1f} | "
                    f"{floor[1] * 1000:.1f} | {floor[2] * 1000:.1f} |\n"
                    for name, opf, floor in rows))


if __name__ == "__main__":
    main()
