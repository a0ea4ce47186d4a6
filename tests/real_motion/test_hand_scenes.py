"""The hand scenes: which windows of a recording make a scene (the path in the camera's view), and
the reveal statistic: were the OPF's main hypothesis and its most probable one the right one when
the cube was seen again (carried if it moved while hidden, left otherwise)?"""

import csv
import importlib.util
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "experiments" / "real_motion"))
_spec = importlib.util.spec_from_file_location(
    "hand_scenes", ROOT / "experiments" / "real_motion" / "hand_scenes.py")
hand_scenes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(hand_scenes)

FIELDS = ["frame", "object", "estimator", "seed", "hypothesis", "visible", "mode",
          "true_x", "true_y"]


def write_frames(path, rows, fields=FIELDS):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fields)
        writer.writeheader()
        for r in rows:
            writer.writerow(dict(zip(fields, r)))


def test_each_reveal_is_judged_by_whether_the_cube_moved(tmp_path):
    path = tmp_path / "frames.csv"
    rows = []
    # Seed 0: hidden in frames 1-3 while it moves 5 cm, main `carried` at the end: right. Then
    # hidden in frames 5-6 without moving, main `carried+capped`: wrong.
    # Seed 1: hidden in frames 1-2 without moving, main `left`: right. Hidden from frame 4 to
    # the end: no reveal. The other rows (another object, a further hypothesis, the PF) count not.
    for frame, visible, mode, x in [(0, 1, "measured", 0.0), (1, 0, "left", 0.0),
                                    (2, 0, "left", 0.02), (3, 0, "carried", 0.05),
                                    (4, 1, "measured", 0.05), (5, 0, "left", 0.05),
                                    (6, 0, "carried+capped", 0.051), (7, 1, "measured", 0.051)]:
        rows.append((frame, "cube", "opf", 0, 0, visible, mode, x, 0.0))
        rows.append((frame, "cube", "opf", 0, 1, visible, "carried", x, 0.0))
        rows.append((frame, "cube", "pf", 0, 0, visible, "predicted", x, 0.0))
        rows.append((frame, "hand", "opf", 0, 0, 1, "measured", x, 0.0))
    for frame, visible, mode in [(0, 1, "measured"), (1, 0, "carried"), (2, 0, "left"),
                                 (3, 1, "measured"), (4, 0, "left"), (5, 0, "left")]:
        rows.append((frame, "cube", "opf", 1, 0, visible, mode, 0.3, 0.1))
    write_frames(path, rows)
    # Without a probability column every row counts as certain: the main one is the likeliest.
    assert hand_scenes.reveals(hand_scenes.opf_rows(path)) == (2, 2, 3)


def test_in_the_cups_game_only_the_right_carrier_counts(tmp_path):
    path = tmp_path / "frames.csv"
    rows = []
    # The ball moves under cup B while hidden in both seeds; seed 0 ends carried by cup B's hand
    # (right), seed 1 by cup A (wrong).
    for seed, carrier in ((0, "hand_b"), (1, "cup_a")):
        for frame, visible, mode, x in [(0, 1, "measured", 0.0), (1, 0, "left", 0.0),
                                        (2, 0, "carried", 0.1), (3, 1, "measured", 0.1)]:
            rows.append((frame, "ball", "opf", seed, 0, visible, mode, x, 0.0,
                         carrier if mode == "carried" else ""))
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, FIELDS + ["model"])
        writer.writeheader()
        for r in rows:
            writer.writerow(dict(zip(FIELDS + ["model"], r)))
    rows = hand_scenes.opf_rows(path)
    assert hand_scenes.reveals(rows, "ball", {"cup_b", "hand_b"}) == (1, 1, 2)
    assert hand_scenes.reveals(rows, "ball") == (2, 2, 2)


def test_the_most_probable_hypothesis_may_differ_from_the_main_one(tmp_path):
    path = tmp_path / "frames.csv"
    fields = FIELDS + ["model", "probability"]
    rows = []
    # The cube stays put while hidden in frames 1-2. Seed 0: main `left` at 0.45, `carried` at
    # 0.55 (the main hypothesis changes hands only on stronger evidence): the main is right, the
    # most probable is not. Seed 1: main `left` at 0.6: both right.
    for seed, p_left in ((0, 0.45), (1, 0.6)):
        for frame, visible in ((0, 1), (1, 0), (2, 0), (3, 1)):
            mode = "left" if not visible else "measured"
            rows.append((frame, "cube", "opf", seed, 0, visible, mode, 0.2, 0.0, "", p_left))
            if not visible:
                rows.append((frame, "cube", "opf", seed, 1, visible, "carried", 0.25, 0.0, "hand",
                             1.0 - p_left))
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fields)
        writer.writeheader()
        for r in rows:
            writer.writerow(dict(zip(fields, r)))
    assert hand_scenes.reveals(hand_scenes.opf_rows(path)) == (2, 1, 2)


def test_a_window_whose_path_leaves_the_view_is_refused():
    # A recording that drifts 1 m/s along x: scaled by 0.25 and centred, every 10 s window spans
    # +-1.25 m, far past the camera's view. One that stands still for its first 20 s and then
    # drifts gives windows, each in view.
    t = np.arange(0.0, 40.0, 0.01)
    drifting = np.stack([t, np.zeros_like(t), np.zeros_like(t)], axis=1)
    resting_first = np.where(t[:, None] < 20.0, 0.0, drifting - np.array([20.0, 0.0, 0.0]))
    identity = np.tile([0.0, 0.0, 0.0, 1.0], (len(t), 1))

    def reader(p):
        return lambda path: (t, p, identity)

    assert list(hand_scenes.windows(reader(drifting), "drifting")) == []
    kept = list(hand_scenes.windows(reader(resting_first), "resting"))
    assert kept
    for _, x, y, _ in kept:
        assert hand_scenes.in_view(x, y)
        assert np.abs(x - hand_scenes.WORKSPACE[0]).max() <= hand_scenes.IN_VIEW
    assert hand_scenes.in_view([0.55 + 0.39], [0.0])
    assert not hand_scenes.in_view([0.55 + 0.41], [0.0])
    assert not hand_scenes.in_view([0.55], [-0.41])


def test_the_windows_begin_where_asked(tmp_path):
    # A slow loop (in view everywhere): the first window from 6 s is the recording from 6 s on,
    # scaled into the workspace; from the default 2 s it is another stretch of motion.
    t = np.arange(0.0, 30.0, 0.01)
    loop = np.stack([0.3 * np.sin(2 * np.pi * t / 20), 0.2 * np.cos(2 * np.pi * t / 15),
                     np.zeros_like(t)], axis=1)
    identity = np.tile([0.0, 0.0, 0.0, 1.0], (len(t), 1))

    def reader(path):
        return t, loop, identity

    times, x, y, _ = next(hand_scenes.windows(reader, "loop", 6.0))
    xs = np.interp(times + 6.0, t, loop[:, 0])
    ys = np.interp(times + 6.0, t, loop[:, 1])
    assert np.array_equal(x, hand_scenes.WORKSPACE[0] + hand_scenes.SCALE * (xs - xs.mean()))
    assert np.array_equal(y, hand_scenes.WORKSPACE[1] + hand_scenes.SCALE * (ys - ys.mean()))
    _, x_default, _, _ = next(hand_scenes.windows(reader, "loop"))
    assert not np.allclose(x_default, x)
    # A negative start is refused on the command line, naming the option.
    run = subprocess.run([sys.executable, str(ROOT / "experiments" / "real_motion" /
                                              "hand_scenes.py"), str(tmp_path / "out"),
                          "--window-start", "-1"], capture_output=True, text=True)
    assert run.returncode == 2
    assert "--window-start: -1.0 is not a time >= 0 s" in run.stderr


def test_a_scene_no_window_fits_is_reported_and_the_others_are_built(tmp_path):
    # One recording circles within the view (radius 0.3 m once scaled, a turn in 8 s); the other
    # drifts out of it at once. The circling one's carry and pass are built; its cups game, whose
    # cup A would follow the drifting one, and each of the drifting one's scenes are not, each
    # named with the reason.
    t = np.arange(0.0, 30.0, 0.01)
    circle = np.stack([1.2 * np.cos(2 * np.pi * t / 8), 1.2 * np.sin(2 * np.pi * t / 8),
                       np.zeros_like(t)], axis=1)
    drifting = np.stack([t, np.zeros_like(t), np.zeros_like(t)], axis=1)
    identity = np.tile([0.0, 0.0, 0.0, 1.0], (len(t), 1))
    recordings = (("circling", lambda path: (t, circle, identity), "circling.csv"),
                  ("drifting", lambda path: (t, drifting, identity), "drifting.csv"))

    built, skipped = hand_scenes.build_scenes(recordings, 2.0)

    assert [(name, kind) for name, kind, *_ in built] == [("circling", "carry"),
                                                          ("circling", "pass")]
    assert all(text.startswith(f"# {kind} ") for _, kind, text, _, _ in built)
    assert [(name, kind) for name, kind, _ in skipped] == [
        ("circling", "cups"), ("drifting", "carry"), ("drifting", "pass"), ("drifting", "cups")]
    assert "no window of drifting.csv from 2 s" in skipped[0][2]
    assert all("drifting.csv" in reason for _, _, reason in skipped)
    # The first recording's scenes alone: its cups game still takes cup A from the next.
    built, skipped = hand_scenes.build_scenes(recordings, 2.0, 1)
    assert [(name, kind) for name, kind, *_ in built] == [("circling", "carry"),
                                                          ("circling", "pass")]
    assert [(name, kind) for name, kind, _ in skipped] == [("circling", "cups")]
    hand_scenes.write_results(str(tmp_path), [], skipped)
    written = (tmp_path / "hand_scenes.md").read_text()
    assert "- circling cups: no window of drifting.csv" in written


def test_the_unseen_scenes_leave_out_what_was_run_already(monkeypatch):
    # The shipped recording circles once in 8 s, a flight once in 11 s, and a still hand never
    # leaves where the cube lies (no window fits it as the one carrying or passing). From 2 s the
    # room's scenes are the shipped ones (left out; its cups game's cup A follows the still hand
    # as when shipped); from 6 and 12 s they are other stretches, and the flight's are new from
    # every start. The still hand's are named as not run, each time.
    t = np.arange(0.0, 30.0, 0.01)

    def circle(period):
        path = np.stack([1.2 * np.cos(2 * np.pi * t / period),
                         1.2 * np.sin(2 * np.pi * t / period), np.zeros_like(t)], axis=1)
        return lambda _: (t, path, np.tile([0.0, 0.0, 0.0, 1.0], (len(t), 1)))

    still = np.zeros((len(t), 3))
    monkeypatch.setattr(hand_scenes, "RECORDINGS", (
        ("room", circle(8.0), "room.csv"),
        ("still", lambda _: (t, still, np.tile([0.0, 0.0, 0.0, 1.0], (len(t), 1))),
         "still.csv")))
    monkeypatch.setattr(hand_scenes, "FLIGHTS", (("flight", circle(11.0), "flight.csv"),))

    built, skipped = hand_scenes.unseen_scenes()

    scenes = [(name, start, kind) for name, start, kind, *_ in built]
    kinds = ("carry", "pass", "cups")
    assert [s for s in scenes if s[0] == "room"] == [
        ("room", start, kind) for start in (6.0, 12.0) for kind in kinds]
    assert [s for s in scenes if s[0] == "flight"] == [
        ("flight", start, kind) for start in (2.0, 6.0, 12.0) for kind in kinds]
    assert len({text for _, _, _, text, _, _ in built}) == len(built)  # none twice
    assert [(name, kind) for name, kind, _ in skipped] == [
        (f"still@{start:g}", kind) for start in (2.0, 6.0, 12.0) for kind in kinds]
    assert all("still.csv" in why for _, _, why in skipped)
    # The table's line under it: the most probable hypothesis right at reveal, per scene kind.
    table = [("room@6", "carry", {}, (5, 5, 5), None), ("room@6", "pass", {}, (4, 3, 5), None),
             ("flight@2", "pass", {}, (5, 5, 5), None)]
    assert hand_scenes.reveal_totals(table) == (
        "\nThe most probable hypothesis right at reveal: carry 5 of 5; pass 8 of 10.\n")
    assert hand_scenes.reveal_totals([]) == ""


def test_unseen_takes_its_own_starts_and_recordings(tmp_path):
    script = str(ROOT / "experiments" / "real_motion" / "hand_scenes.py")
    for extra in (["--window-start", "6"], ["--recordings", "1"]):
        run = subprocess.run([sys.executable, script, str(tmp_path / "out"), "--unseen", *extra],
                             capture_output=True, text=True)
        assert run.returncode == 2
        assert ("--unseen takes its own recordings and starts: not with --window-start or "
                "--recordings") in run.stderr


def test_unsized_scenes_state_no_size_and_change_nothing_else(tmp_path):
    (_, _, text, _, _), *_ = hand_scenes.build_scenes(hand_scenes.RECORDINGS, 2.0, 1)[0]
    unsized = hand_scenes.without_sizes(text)
    assert unsized.replace("  state_sizes: false\n", "", 1) == text
    with pytest.raises(ValueError, match="no measurement section"):
        hand_scenes.without_sizes("name: x\n")
    # The detector of the file as written states no radius or box (the log has no such columns);
    # as shipped, it states both.
    opf = str(ROOT / "build" / "bin" / "opf")
    for name, scene, stated in (("sized", text, True), ("unsized", unsized, False)):
        path = tmp_path / f"{name}.yaml"
        path.write_text(scene)
        subprocess.run([opf, "run", str(path), "--estimators", "opf", "--seeds", "1",
                        "--frames", "3", "--particles", "100", "--no-figures", "--quiet",
                        "--measurements", "--out", str(tmp_path / name)], check=True,
                       stdout=subprocess.DEVNULL)
        (log,) = (tmp_path / name).glob("*_measurements_seed0.csv")
        with open(log) as f:
            rows = list(csv.DictReader(f))
        assert rows
        for r in rows:
            assert (float(r.get("radius") or 0) > 0 and float(r.get("box_x") or 0) > 0) == stated


def test_bad_arguments_are_refused_by_name(tmp_path):
    script = str(ROOT / "experiments" / "real_motion" / "hand_scenes.py")
    opf = str(ROOT / "build" / "bin" / "opf")
    for extra, message in ((["--seeds", "0"], "--seeds: 0 is not a number of seeds >= 1"),
                           (["--recordings", "0"], "--recordings: 0 is not between 1 and 4"),
                           (["--recordings", "5"], "--recordings: 5 is not between 1 and 4"),
                           (["--opf", str(tmp_path / "none")],
                            f"no opf program at {tmp_path / 'none'}")):
        run = subprocess.run([sys.executable, script, str(tmp_path / "out"), "--opf", opf,
                              *extra], capture_output=True, text=True)
        assert run.returncode == 2, extra
        assert message in run.stderr, (extra, run.stderr)
        assert not (tmp_path / "out").exists()


def test_a_failing_run_stops_with_its_command_and_its_words(tmp_path):
    failing = tmp_path / "opf"
    failing.write_text("#!/bin/sh\necho 'opf run: error: the scene is bad' >&2\nexit 3\n")
    failing.chmod(0o755)
    script = str(ROOT / "experiments" / "real_motion" / "hand_scenes.py")
    run = subprocess.run([sys.executable, script, str(tmp_path / "out"), "--opf", str(failing),
                          "--recordings", "1", "--seeds", "1"], capture_output=True, text=True)
    assert run.returncode == 1
    assert f"hand_scenes: {failing} run {tmp_path / 'out' / 'tumvi_room1_carry.yaml'}" in run.stderr
    assert "failed (3):\nopf run: error: the scene is bad" in run.stderr
    assert "Traceback" not in run.stderr
    assert not (tmp_path / "out" / "hand_scenes.md").exists()


def test_the_plate_covers_a_place_through_its_shadow_in_the_cameras_perspective():
    # The camera looks down from 0.8 m over the workspace's centre; the plate's top, 0.14 m up,
    # hides a place on the table up to 0.07 / (1 - 0.13 / 0.79) = 0.0838 m from under its centre
    # along its side, and further along its diagonal.
    cx, cy = hand_scenes.WORKSPACE
    hand = np.array([cx, cy, hand_scenes.HOVER])
    assert hand_scenes.plate_covers((cx, cy, 0.01), hand, 0.0)
    assert hand_scenes.plate_covers((cx + 0.083, cy, 0.01), hand, 0.0)
    assert not hand_scenes.plate_covers((cx + 0.085, cy, 0.01), hand, 0.0)
    assert hand_scenes.plate_covers((cx + 0.085, cy, 0.01), hand, np.pi / 4)  # its corner
    assert not hand_scenes.plate_covers((cx, cy + 0.2, 0.01), hand, np.pi / 4)


FLOOR_FIELDS = ["frame", "object", "estimator", "seed", "hypothesis", "visible", "true_x",
                "true_y", "true_z", "true_qz", "true_qw"]


def test_the_carry_floor_counts_a_pick_up_until_the_place_is_seen_and_a_put_down_until_the_reveal(
        tmp_path):
    cx, cy = hand_scenes.WORKSPACE
    # (hand x, cube x, cube seen): the cube seen, covered, picked up 5 cm with its place still
    # under the plate (0.05 m off), carried out of it (the place seen empty: carried from here on,
    # also back over the place), put down as the hand moves on 4 cm (0.04 m off), seen again.
    steps = [(0.20, 0.00, 1), (0.00, 0.00, 0), (0.05, 0.05, 0), (0.15, 0.15, 0), (0.02, 0.02, 0),
             (0.06, 0.02, 0), (0.20, 0.02, 1)]
    rows = []
    for frame, (hand_x, cube_x, seen) in enumerate(steps):
        rows.append([frame, "hand", "opf", 0, 0, 1, cx + hand_x, cy, hand_scenes.HOVER, 0.0, 1.0])
        rows.append([frame, "cube", "opf", 0, 0, seen, cx + cube_x, cy, 0.01, 0.0, 1.0])
        # Another hypothesis and another estimator count not.
        rows.append([frame, "cube", "opf", 0, 1, seen, cx + cube_x, cy, 0.01, 0.0, 1.0])
        rows.append([frame, "cube", "pf", 0, 0, seen, cx + 0.5, cy, 0.01, 0.0, 1.0])
    path = tmp_path / "frames.csv"
    write_frames(path, rows, FLOOR_FIELDS)
    floor, pick_up, put_down = hand_scenes.carry_floor(hand_scenes.opf_rows(path))
    # Five hidden frames: 0.05 m in the pick-up, 0.04 m in the put-down.
    assert pick_up == pytest.approx(0.05 / 5, abs=1e-9)
    assert put_down == pytest.approx(0.04 / 5, abs=1e-9)
    assert floor == pytest.approx(0.09 / 5, abs=1e-9)


def test_the_floor_is_tabled_under_the_carries_and_in_the_csv(tmp_path):
    errors = {e: (0.02, 0.015, 100) for e in hand_scenes.ESTIMATORS.split(",")}
    table = [("room", "carry", errors, (5, 5, 5), (0.018, 0.01, 0.008)),
             ("room", "pass", errors, (5, 5, 5), None)]
    hand_scenes.write_results(str(tmp_path), table)
    written = (tmp_path / "hand_scenes.md").read_text()
    assert "| room | 20.0 | 18.0 | 10.0 | 8.0 |" in written
    with open(tmp_path / "hand_scenes.csv") as f:
        floors = {(r["scene"], r["estimator"]): r["floor_hidden_translation"]
                  for r in csv.DictReader(f)}
    assert floors[("carry", "pf")] == "0.018" and floors[("pass", "opf")] == ""
    hand_scenes.write_results(str(tmp_path), table[1:])  # no carry: no floor table
    assert "floor [mm]" not in (tmp_path / "hand_scenes.md").read_text()
