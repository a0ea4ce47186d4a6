"""The Python module `opf` against the C++ program it wraps: the same numbers, the same errors.

Run by ctest (Python.Module) with PYTHONPATH at the build's staged package and OPF (the built
`opf` program) and OPF_SOURCE_DIR in the environment; without OPF the comparisons with the
program are skipped."""

import csv
import itertools
import math
import os
import re
import subprocess
import threading
import warnings
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import opf

SOURCE = os.environ["OPF_SOURCE_DIR"]
OPF = os.environ.get("OPF")
EXAMPLE_LOG = os.path.join(SOURCE, "experiments", "data", "example_log.csv")
PARTICLES = 500
TEXT_COLUMNS = ("object", "mode", "model")
# The example log states no sizes: track_log's note on that is tested once, below.
pytestmark = pytest.mark.filterwarnings("ignore:the occluder module took:UserWarning")


def program():
    """The `opf` program the module is compared with; without OPF the test is skipped."""
    if not OPF:
        pytest.skip("OPF (the opf program) is not set")
    return OPF


def opf_track(*arguments):
    """Runs `opf track` quietly; returns its stderr (bytes) and exit status."""
    run = subprocess.run([program(), "track", "--quiet", *map(str, arguments)],
                         capture_output=True)
    return run.stderr, run.returncode


def assert_columns_are_the_files(columns, path):
    """Every column of the estimate file at `path`, in its order, value for value (the file holds
    the shortest text that reads back exactly: equality, not closeness)."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = list(reader)
    assert list(columns) == header
    assert len(columns["t"]) == len(rows)
    for i, name in enumerate(header):
        values = [row[i] for row in rows]
        if name in TEXT_COLUMNS:
            assert columns[name] == values, name
        elif name == "hypothesis":
            assert list(columns[name]) == [int(v) for v in values], name
        elif name == "alert":
            assert list(columns[name]) == [v == "1" for v in values], name
        else:
            assert np.array_equal(columns[name], np.array([float(v) for v in values])), name


def cup_at(t):
    """A cup sliding along x at 0.2 m/s, turned 0.3 rad about z."""
    half = 0.15
    return [0.2 * t, 0.1, 0.5, 0.0, 0.0, math.sin(half), math.cos(half)]


def test_a_detection_stating_extra_noise_moves_the_estimate_less():
    # A still cup, then one detection 3 cm off: stated 10 cm noise (an eighth number), the
    # Kalman filter's gain P / (P + R) falls about a hundredfold.
    def x_after_jump(extra):
        tracker = opf.Tracker("cvkf", seed=1)
        for k in range(30):
            tracker.step(k / 30.0, {"cup": [0.0, 0.0, 0.0, 0, 0, 0, 1]})
        jump = [0.03, 0.0, 0.0, 0, 0, 0, 1] + ([extra] if extra is not None else [])
        return tracker.step(1.0, {"cup": jump})["cup"].position[0]

    unstated = x_after_jump(None)
    assert x_after_jump(0.0) == unstated  # 0 states nothing
    assert unstated > 0.003
    assert abs(x_after_jump(0.1)) < 0.1 * unstated


def test_a_position_alone_steps_as_the_pose_at_the_identity_orientation():
    # [x, y, z], as a log of positions reads: the OPF's estimates, seeded, through a gap, are
    # those of the same positions given with the identity quaternion, number for number.
    def estimates(pose_of):
        tracker = opf.Tracker("opf", seed=4, particles=PARTICLES)
        out = []
        for k in range(20):
            estimate = tracker.step(k / 30.0, {"cup": None if 8 <= k < 12 else pose_of(k)})["cup"]
            out.append((estimate.mode, tuple(estimate.position), tuple(estimate.quaternion)))
        return out

    positions = estimates(lambda k: [0.01 * k, 0.1, 0.5])
    assert positions == estimates(lambda k: [0.01 * k, 0.1, 0.5, 0.0, 0.0, 0.0, 1.0])
    assert [mode for mode, _, _ in positions].count("measured") == 16


def test_a_tracker_follows_what_it_is_shown_and_extrapolates_through_a_gap():
    tracker = opf.Tracker("opf", seed=3, particles=PARTICLES)
    dt = 1.0 / 30.0
    modes = []
    for k in range(60):
        t = k * dt
        hidden = 1.0 <= t < 1.3
        estimates = tracker.step(t, {"cup": None if hidden else cup_at(t)})
        e = estimates["cup"]
        modes.append(e.mode)
        assert e.position.shape == (3,) and e.quaternion.shape == (4,)
        assert e.covariance.shape == (6, 6)
        assert np.allclose(e.covariance, e.covariance.T)
        assert e.hypothesis == 0 and e.object == "cup" and e.t == pytest.approx(t)
        # 2 mm of detector noise is the default likelihood's scale: within 1 cm measured and
        # hidden alike on a straight line.
        assert np.linalg.norm(e.position - cup_at(t)[:3]) < 0.01, (t, e.mode, e.position)
        assert abs(abs(np.dot(e.quaternion, cup_at(t)[3:])) - 1.0) < 1e-3
    assert modes[:30] == ["measured"] * 30
    assert set(modes[30:39]) == {"dynamics"}
    assert modes[40:] == ["measured"] * 20


def test_the_same_seed_gives_the_same_estimates_and_another_seed_does_not():
    def run(seed):
        tracker = opf.Tracker("pf", seed=seed, particles=PARTICLES)
        return [tracker.step(k / 30.0, {"cup": cup_at(k / 30.0)})["cup"].position.copy()
                for k in range(10)]

    assert all(np.array_equal(a, b) for a, b in zip(run(5), run(5)))
    assert not all(np.array_equal(a, b) for a, b in zip(run(5), run(6)))


TRAY = [0.5, -0.2, 0.5, 0.0, 0.0, 0.0, 1.0]


def snapshot(estimates):
    return {name: (e.t, e.position.copy(), e.quaternion.copy(), e.covariance.copy(), e.mode)
            for name, e in estimates.items()}


def assert_same_estimates(a, b):
    assert set(a) == set(b)
    for name in a:
        t, position, quaternion, covariance, mode = a[name]
        u, position_b, quaternion_b, covariance_b, mode_b = b[name]
        assert (t, mode) == (u, mode_b), name
        assert np.array_equal(position, position_b), name
        assert np.array_equal(quaternion, quaternion_b), name
        assert np.array_equal(covariance, covariance_b), name


def test_threads_stepping_one_tracker_take_turns_and_get_the_serial_estimates():
    threads, steps = 4, 30
    tracker = opf.Tracker("opf", seed=8, particles=PARTICLES)
    frames = itertools.count()  # frame k at k / 30 s, drawn under the lock: each time once
    frames_lock = threading.Lock()
    accepted = {}

    def worker(_):
        done = refused = 0
        while done < steps:
            with frames_lock:
                t = next(frames) / 30.0
            try:
                estimates = tracker.step(t, {"cup": cup_at(t), "tray": TRAY})
            except ValueError as error:
                # A later frame drawn by another thread reached the tracker first: this one is
                # refused whole (time does not go back) and the thread draws the next.
                assert re.fullmatch(r"Tracker: frame time \S+ s does not follow the previous "
                                    r"frame at \S+ s", str(error)), str(error)
                refused += 1
                continue
            accepted[t] = snapshot(estimates)
            done += 1
        return refused

    with ThreadPoolExecutor(threads) as pool:
        refused = sum(pool.map(worker, range(threads)))
    assert len(accepted) == threads * steps
    assert next(frames) == threads * steps + refused  # every frame drawn accepted or refused
    # One step at a time, whole: the estimates of the accepted frames stepped in time order.
    serial = opf.Tracker("opf", seed=8, particles=PARTICLES)
    for t in sorted(accepted):
        expected = snapshot(serial.step(t, {"cup": cup_at(t), "tray": TRAY}))
        assert {name: value[0] for name, value in accepted[t].items()} == {"cup": t, "tray": t}
        assert_same_estimates(accepted[t], expected)


NEXT = None  # the next frame's own time: the pose alone is wrong
CUP = [0.1, 0.2, 0.3, 0.0, 0.0, 0.0, 1.0]


@pytest.mark.parametrize("t, pose, message", [
    (math.nan, CUP, "field 't': expected a finite number, got nan"),
    (math.inf, CUP, "field 't': expected a finite number, got inf"),
    (NEXT, [math.nan, 0.2, 0.3, 0, 0, 0, 1],
     "object 'cup', field 'x': expected a finite number, got nan"),
    (NEXT, [0.1, -math.inf, 0.3, 0, 0, 0, 1],
     "object 'cup', field 'y': expected a finite number, got -inf"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, math.inf, 1],
     "object 'cup', field 'qz': expected a finite number, got inf"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 0, math.nan],
     "object 'cup', field 'qw': expected a finite number, got nan"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 0, 0], "object 'cup', fields 'qx,qy,qz,qw': expected a unit "
                                        "quaternion (norm within 0.01 of 1), got norm 0"),
    (NEXT, [0.1, 0.2],
     "object 'cup': expected 7 pose fields [x, y, z, qx, qy, qz, qw] (3 for a position alone, 8 "
     "with extra_noise, 9 with radius, 12 with box_x, box_y, box_z), got 2"),
    (NEXT, [0.1, math.nan, 0.3], "object 'cup', field 'y': expected a finite number, got nan"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 1],
     "object 'cup': expected 7 pose fields [x, y, z, qx, qy, qz, qw] (3 for a position alone, 8 "
     "with extra_noise, 9 with radius, 12 with box_x, box_y, box_z), got 6"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 0, 1, 0.0, -0.05],
     "object 'cup', field 'radius': expected a radius >= 0, got -0.05"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 0, 1, 0.0, 0.05, 1.0],
     "object 'cup': expected 7 pose fields [x, y, z, qx, qy, qz, qw] (3 for a position alone, 8 "
     "with extra_noise, 9 with radius, 12 with box_x, box_y, box_z), got 10"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 0, 1, 0.0, 0.05, 0.1, 0.1],
     "object 'cup': expected 7 pose fields [x, y, z, qx, qy, qz, qw] (3 for a position alone, 8 "
     "with extra_noise, 9 with radius, 12 with box_x, box_y, box_z), got 11"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 0, 1, 0.0, 0.05, 0.1, 0.1, 0.1, 0.1],
     "object 'cup': expected 7 pose fields [x, y, z, qx, qy, qz, qw] (3 for a position alone, 8 "
     "with extra_noise, 9 with radius, 12 with box_x, box_y, box_z), got 13"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 0, 1, 0.0, 0.05, 0.1, 0.0, 0.1],
     "object 'cup', field 'box_y': expected an extent > 0, got 0"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 0, 1, 0.0, 0.05, 0.1, 0.1, math.inf],
     "object 'cup', field 'box_z': expected an extent > 0, got inf"),
    (NEXT, "0.1,0.2,0.3,0,0,0,1", "object 'cup': expected a pose [x, y, z, qx, qy, qz, qw] or "
                                  "None, got '0.1,0.2,0.3,0,0,0,1'"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 0, 1, -0.01],
     "object 'cup', field 'extra_noise': expected a standard deviation >= 0, got -0.01"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 0, 1, math.nan],
     "object 'cup', field 'extra_noise': expected a standard deviation >= 0, got nan"),
    (NEXT, [0.1, 0.2, 0.3, 0, 0, 0, 1, 1e300],
     "object 'cup', field 'extra_noise': expected a standard deviation up to 1e+06 m, got 1e+300"),
])
def test_a_bad_input_is_refused_by_name_and_the_tracker_goes_on(t, pose, message):
    times = [k / 30.0 for k in range(4)]

    def step(tracker, s, cup=CUP):
        return snapshot(tracker.step(s, {"cup": cup, "tray": TRAY}))

    tracker = opf.Tracker("opf", seed=5, particles=PARTICLES)
    estimates = []
    for k, s in enumerate(times):
        if k in (0, 2):  # refused as the very first step, and between good ones
            with pytest.raises(ValueError) as error:
                step(tracker, s if t is NEXT else t, pose)
            assert str(error.value) == message
        estimates.append(step(tracker, s))
    # A refused step leaves no trace: the estimates of a tracker that never saw it.
    reference = opf.Tracker("opf", seed=5, particles=PARTICLES)
    for s, got in zip(times, estimates):
        assert_same_estimates(got, step(reference, s))
        assert all(np.isfinite(e[1]).all() and np.isfinite(e[3]).all() for e in got.values())


def test_a_step_back_in_time_is_refused_and_an_empty_name_too():
    tracker = opf.Tracker("cvkf")
    tracker.step(1.0, {"cup": CUP})
    with pytest.raises(ValueError) as error:
        tracker.step(0.5, {"cup": CUP})
    assert str(error.value) == "Tracker: frame time 0.5 s does not follow the previous frame at 1 s"
    with pytest.raises(ValueError) as error:
        tracker.step(2.0, {"": CUP})
    assert str(error.value) == "object '': expected an object name, got an empty string"
    assert tracker.step(2.0, {"cup": None})["cup"].t == 2.0


def test_a_configs_particle_counts_are_used_unless_particles_is_given():
    def run(**arguments):
        tracker = opf.Tracker("pf", seed=9, **arguments)
        return [snapshot(tracker.step(k / 30.0, {"cup": cup_at(k / 30.0)})) for k in range(6)]

    def same(a, b):
        try:
            for x, y in zip(a, b, strict=True):
                assert_same_estimates(x, y)
        except AssertionError:
            return False
        return True

    counts = {"pf": {"translation_particles": 200, "rotation_particles": 200}}
    with_200 = run(particles=200)
    assert same(run(config=counts), with_200)
    assert same(run(config=counts, particles=200), with_200)  # the same count twice
    assert not same(run(), with_200)  # the default, 5000
    # A count the config leaves alone is the default's, not the other's.
    assert same(run(config={"pf": {"rotation_particles": 200}}),
                run(config={"pf": {"translation_particles": 5000, "rotation_particles": 200}}))
    with pytest.raises(ValueError) as error:
        opf.Tracker("pf", particles=100, config=counts)
    assert str(error.value) == ("particles=100 and the config's pf.translation_particles (200) "
                                "contradict each other: give the particle count in one place")
    with pytest.raises(ValueError) as error:
        opf.Tracker("pf", particles=100, config={"pf": {"rotation_particles": 200}})
    assert str(error.value).startswith("particles=100 and the config's pf.rotation_particles (200)")


def test_track_log_takes_a_settings_files_particle_count_as_opf_track_does(tmp_path):
    settings = tmp_path / "settings.yaml"
    settings.write_text("pf:\n  translation_particles: 300\n  rotation_particles: 200\n")
    out = tmp_path / "estimates.csv"
    assert opf_track("--in", EXAMPLE_LOG, "--out", out, "--estimator", "pf", "--seed", 2,
                     "--config", settings) == (b"", 0)
    columns = opf.track_log(EXAMPLE_LOG, estimator="pf", seed=2, config=settings,
                            dataframe=False)
    assert_columns_are_the_files(columns, out)


def test_the_version_is_the_projects_and_the_programs():
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
        project = re.search(r"project\(opf_toolkit VERSION (\S+)", f.read()).group(1)
    assert opf.__version__ == project
    if OPF:
        printed = subprocess.run([OPF, "--version"], capture_output=True, text=True,
                                 check=True).stdout
        assert printed.split()[:2] == ["opf", opf.__version__]


def test_track_log_is_opf_track_number_for_number(tmp_path):
    out = tmp_path / "estimates.csv"
    assert opf_track("--in", EXAMPLE_LOG, "--out", out, "--estimator", "opf", "--seed", 4,
                     "--particles", PARTICLES) == (b"", 0)
    columns = opf.track_log(EXAMPLE_LOG, estimator="opf", seed=4, particles=PARTICLES,
                            dataframe=False)
    assert len(columns) == 21 and len(columns["t"]) > 300
    assert_columns_are_the_files(columns, out)


# The measurement log in another system's shape: t in ms, positions in mm, the quaternion under
# other names, and a 0.5 s gap (filled at the rate).
OWN_COLUMNS = {"t": "time_ms", "qx": "rx", "qy": "ry", "qz": "rz", "qw": "rw"}
OWN_OPTIONS = {"time_unit": "ms", "length_unit": "mm", "columns": OWN_COLUMNS}
OWN_FLAGS = ["--time-unit", "ms", "--length-unit", "mm",
             "--columns", ",".join(f"{k}={v}" for k, v in OWN_COLUMNS.items())]


def write_own_log(path):
    with open(EXAMPLE_LOG, newline="") as f:
        rows = list(csv.DictReader(f))
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(OWN_COLUMNS.get(name, name) for name in
                     ("t", "object", "x", "y", "z", "qx", "qy", "qz", "qw"))
        for row in rows:
            if 2.0 <= float(row["t"]) < 2.5:
                continue
            millimetres = [repr(float(row[k]) * 1000) if row[k] else "" for k in "xyz"]
            out.writerow([repr(float(row["t"]) * 1000), row["object"], *millimetres,
                          row["qx"], row["qy"], row["qz"], row["qw"]])


@pytest.mark.parametrize("options, flags", [
    ({"preset": "paper", "rate": 20, "covariance": True},
     ["--preset", "paper", "--rate", "20", "--covariance"]),
    ({"camera": [2.0, 0.0, 0.3], "fill": False}, ["--camera", "2.0,0.0,0.3", "--no-fill"]),
    ({"camera": "2.0,0.0,0.3", "columns": OWN_FLAGS[5]}, ["--camera", "2.0,0.0,0.3"]),
])
def test_track_log_takes_opf_tracks_log_options(tmp_path, options, flags):
    log = tmp_path / "own.csv"
    write_own_log(log)
    out = tmp_path / "estimates.csv"
    assert opf_track("--in", log, "--out", out, "--seed", 3, "--particles", PARTICLES,
                     *OWN_FLAGS, *flags) == (b"", 0)
    common = dict(OWN_OPTIONS, seed=3, particles=PARTICLES, dataframe=False)
    columns = opf.track_log(log, **dict(common, **options))
    assert_columns_are_the_files(columns, out)
    assert len(columns) == (42 if options.get("covariance") else 21)
    # Each option changes the estimates of this log: none of them is ignored.
    defaults = {"preset": "default", "fill": True}
    for name in set(options) - {"covariance", "columns"}:
        without = opf.track_log(log, **{**common, **options, name: defaults.get(name)})
        assert not (len(without["t"]) == len(columns["t"])
                    and np.array_equal(without["x"], columns["x"])), name


def test_track_log_reads_a_tum_trajectory_as_opf_track_does(tmp_path):
    # The example's ball as a TUM trajectory (epoch times, '#' header): no option needed.
    with open(EXAMPLE_LOG, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["object"] == "ball" and r["x"]]
    log = tmp_path / "ball_run.txt"
    with open(log, "w") as f:
        f.write("# timestamp tx ty tz qx qy qz qw\n")
        for r in rows:
            f.write(" ".join([repr(1.7e9 + float(r["t"]))] +
                             [r[k] for k in ("x", "y", "z", "qx", "qy", "qz", "qw")]) + "\n")
    out = tmp_path / "estimates.csv"
    assert opf_track("--in", log, "--out", out, "--seed", 3, "--particles", PARTICLES) == (b"", 0)
    columns = opf.track_log(log, seed=3, particles=PARTICLES, dataframe=False)
    assert_columns_are_the_files(columns, out)
    assert set(columns["object"]) == {"ball_run"}
    named = opf.track_log(log, seed=3, particles=PARTICLES, object="ball", dataframe=False)
    assert set(named["object"]) == {"ball"} and np.array_equal(named["x"], columns["x"])
    with pytest.raises(ValueError, match="option 'columns' renames CSV columns; a TUM, "
                       "MOTChallenge, ASL or KITTI file's columns are its format's"):
        opf.track_log(log, columns={"qx": "rx"})
    with pytest.raises(ValueError, match='option \'format\': expected csv, tum, mot, euroc or kitti, got "kml"'):
        opf.track_log(log, format="kml")


# What a camera may be, in the words of opf track's --camera.
CAMERA = ("X,Y,Z in metres (a camera there) or X,Y,Z,0 (a camera infinitely far in the direction "
          "X,Y,Z: parallel lines of sight)")


@pytest.mark.parametrize("options, flag, message", [
    ({"time_unit": "h"}, ["--time-unit", "h"], 'expected s, ms, us or ns, got "h"'),
    ({"length_unit": "km"}, ["--length-unit", "km"], 'expected m or mm, got "km"'),
    ({"columns": {"foo": "bar"}}, ["--columns", "foo=bar"],
     "'foo' is not a column of the log format (t, object, x, y, z, qx, qy, qz, qw)"),
    ({"columns": "qx"}, ["--columns", "qx"],
     "'qx' is not NAME=COLUMN (e.g. qx=rx: the column rx holds qx)"),
    ({"camera": "0,0"}, ["--camera", "0,0"], f'expected {CAMERA}, got "0,0"'),
    ({"camera": "0,0,0,0"}, ["--camera", "0,0,0,0"], f'expected {CAMERA}, got "0,0,0,0"'),
    ({"preset": "fast"}, ["--preset", "fast"], 'expected default or paper, got "fast"'),
])
def test_track_log_refuses_a_bad_option_in_opf_tracks_words(tmp_path, options, flag, message):
    (name,) = options
    with pytest.raises(ValueError) as error:
        opf.track_log(EXAMPLE_LOG, **options)
    assert str(error.value) == f"option '{name}': {message}"
    stderr, status = opf_track("--in", EXAMPLE_LOG, "--out", tmp_path / "never.csv", *flag)
    assert (stderr.decode(), status) == (
        f"opf track: option '{flag[0]}': {message} (see 'opf track --help')\n", 2)


RATE = "a frame rate in Hz from 0.1 to 1e9 (frames 10 s to 1 ns apart)"


def test_track_log_refuses_the_other_bad_options_by_name():
    refusals = [
        ({"rate": 0}, f"option 'rate' expects {RATE}"),
        ({"rate": 0.09}, f"option 'rate' expects {RATE}"),
        ({"rate": math.inf}, f"option 'rate' expects {RATE}"),
        ({"rate": 1e12}, f"option 'rate' expects {RATE}"),
        ({"frame_tolerance": -0.1}, "option 'frame_tolerance' expects seconds >= 0"),
        ({"rate": 20, "fill": False}, "options 'rate' and 'fill=False' contradict each other: "
                                      "rate sets the rate gaps are filled at"),
        ({"camera": [0, 0, math.nan]}, f"option 'camera': expected {CAMERA}, got [0, 0, nan]"),
        ({"camera": [1, 2, 3, 4]}, f"option 'camera': expected {CAMERA}, got [1, 2, 3, 4]"),
        ({"columns": {"qx": "a,b"}},
         "option 'columns': expected names without commas, got 'qx': 'a,b'"),
        ({"config": {"opf": {"occluder": {"plane": "line_of_sight"}}}},
         "opf.occluder.plane is line_of_sight but no camera position is given: pass camera=[X, "
         "Y, Z] (or set opf.occluder.camera_position), or use plane auto (a top-down camera "
         "without one)"),
    ]
    for options, message in refusals:
        with pytest.raises(ValueError) as error:
            opf.track_log(EXAMPLE_LOG, **options)
        assert str(error.value) == message


def test_a_binary_file_is_refused_in_opf_tracks_words(tmp_path):
    binary = tmp_path / "image.bin"
    binary.write_bytes(b"\x7fELF\x02\x01\xff\xfe,\x01\n\x00\x00\x00")
    message = f"{binary}:1: not a text file: control byte 0x7f at byte 1 of the line"
    with pytest.raises(opf.InputError) as error:
        opf.track_log(binary)
    assert str(error.value) == message
    # The program says the same, and writes none of the file's bytes to the terminal.
    stderr, status = opf_track("--in", binary, "--out", tmp_path / "never.csv")
    assert (stderr.decode("ascii"), status) == (f"opf track: error: {message}\n", 1)


def test_an_input_error_says_where_as_attributes(tmp_path):
    log = tmp_path / "log.csv"
    log.write_text("t,object,x,y,z,qx,qy,qz,qw\n0,cup,0.1,0.2,0.3,0,0,0,1\n0.1,cup,0.1,high,0.3,0,0,0,1\n")
    with pytest.raises(opf.InputError) as error:
        opf.track_log(log)
    e = error.value
    assert (e.file, e.line, e.field) == (str(log), 3, "y")
    assert e.reason == 'expected a number, got "high"'
    assert str(e) == f"{log}:3: column 'y': {e.reason}"


def test_track_log_gives_a_dataframe_when_pandas_is_there():
    pandas = pytest.importorskip("pandas")
    frame = opf.track_log(EXAMPLE_LOG, estimator="cvkf", seed=1)
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns[:3]) == ["t", "object", "x"]
    assert set(frame["object"]) == {"ball", "mug"}


def test_a_config_dict_is_read_like_the_settings_file(tmp_path):
    settings = tmp_path / "settings.yaml"
    settings.write_text("opf:\n  modules:\n    dynamics: false\n")
    from_file = opf.track_log(EXAMPLE_LOG, seed=2, particles=PARTICLES, config=settings,
                              dataframe=False)
    from_dict = opf.track_log(EXAMPLE_LOG, seed=2, particles=PARTICLES,
                              config={"opf": {"modules": {"dynamics": False}}}, dataframe=False)
    default = opf.track_log(EXAMPLE_LOG, seed=2, particles=PARTICLES, dataframe=False)
    assert np.array_equal(from_file["x"], from_dict["x"])
    assert from_file["mode"] == from_dict["mode"]
    # Without the dynamics module the hidden ball (no occluder can hide it) is only predicted.
    assert "dynamics" in default["mode"] and "dynamics" not in from_dict["mode"]
    assert "predicted" in from_dict["mode"] and "predicted" not in default["mode"]


def test_errors_carry_the_programs_messages(tmp_path):
    with pytest.raises(ValueError, match=r"unknown estimator 'kalman' \(known: opf, pf, cvkf, imm, oapf\)"):
        opf.Tracker("kalman")
    with pytest.raises(ValueError, match=r"<config dict>:1: key 'opf.modules.occluder'"):
        opf.Tracker(config={"opf": {"modules": {"occluder": "sometimes"}}})
    bad = tmp_path / "bad.csv"
    bad.write_text("t,object,x,y,z,qx,qy,qz,qw\n0,cup,0,0,0,0,0,0,2\n")
    with pytest.raises(opf.InputError, match=r"bad.csv:2: .*qx,qy,qz,qw"):
        opf.track_log(bad)
    with pytest.raises(ValueError, match="expected a unit quaternion"):
        opf.Tracker().step(0.0, {"cup": [0, 0, 0, 0, 0, 0, 2]})
    with pytest.raises(ValueError, match="particles must be at least 1"):
        opf.Tracker(particles=0)
    with pytest.raises(ValueError, match="particles must be below 2\\^31"):
        opf.Tracker(particles=2**31)


def test_the_estimator_names_are_the_registrys():
    assert opf.estimators() == ["opf", "pf", "cvkf", "imm", "oapf"]


def test_a_tracker_takes_the_preset_and_the_camera_as_track_log_does():
    # A ball rolling out from under a resting mug, hidden for 10 frames: the paper's rules and the
    # defaults extrapolate it differently; the camera is accepted in either form.
    def run(**settings):
        tracker = opf.Tracker("opf", seed=2, particles=PARTICLES, **settings)
        for k in range(40):
            ball = None if 20 <= k < 30 else [0.3 + 0.01 * k, 0.0, 0.02, 0, 0, 0, 1]
            last = tracker.step(k / 30.0, {"ball": ball, "mug": [0.2, 0.3, 0.04, 0, 0, 0, 1]})
        return last["ball"].position
    default = run()
    assert not np.allclose(run(preset="paper"), default)
    assert np.array_equal(run(camera=[0.0, 0.0, 2.0]), run(camera="0,0,2"))
    assert np.array_equal(run(camera=[0.0, 0.0, 1.0, 0.0]), run(camera="0,0,1,0"))
    with pytest.raises(ValueError, match='option \'preset\': expected default or paper, got "fast"'):
        opf.Tracker("opf", preset="fast")
    with pytest.raises(ValueError, match="option 'camera'"):
        opf.Tracker("opf", camera=[0.0, 1.0])


def test_a_stated_box_reaches_the_tracker_as_the_logs_box_columns_do(tmp_path):
    # A cube at rest; a 14 cm square plate turned 45 degrees about z passes 10 cm above it at
    # 0.2 m/s, hiding the cube while its centre is within 9.9 cm along x (a corner's reach). With
    # the plate's box stated, the cube is left where it was throughout; with the disc of the
    # plate's area alone (7.9 cm), the place looks clear under the departing corner and the
    # carried hypothesis takes over. The box stated per step is the log's box columns'.
    turned = [0.0, 0.0, math.sin(math.pi / 8), math.cos(math.pi / 8)]
    radius, box = 0.079, [0.14, 0.14, 0.01]
    frames = []
    for k in range(75):
        t = k / 30.0
        plate = [-0.3 + 0.2 * t, 0.0, 0.1, *turned]
        hidden = abs(plate[0]) < 0.099
        frames.append((t, None if hidden else [0.0, 0.0, 0.0, 0, 0, 0, 1], plate))
    assert sum(cube is None for _, cube, _ in frames) > 20

    def cube_probabilities(stated):
        tracker = opf.Tracker("opf", seed=6, particles=PARTICLES)
        rows = []
        for t, cube, plate in frames:
            main = tracker.step(t, {"cube": cube, "plate": plate + stated})["cube"]
            rows.append([(main.mode, main.probability)] +
                        [(e.mode, e.probability) for e in tracker.hypotheses if e.object == "cube"])
        return rows

    with_box = cube_probabilities([0.0, radius, *box])
    hidden = [row for row, (_, cube, _) in zip(with_box, frames) if cube is None]
    assert all(row[0][0] == "left" for row in hidden)
    disc_only = cube_probabilities([0.0, radius])
    assert [row for row, (_, cube, _) in zip(disc_only, frames) if cube is None][-1][0][0] == \
        "carried"
    log = tmp_path / "plate.csv"
    with open(log, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["t", "object", "x", "y", "z", "qx", "qy", "qz", "qw", "radius",
                      "box_x", "box_y", "box_z"])
        for t, cube, plate in frames:
            out.writerow([repr(t), "cube", *(map(repr, cube) if cube else [""] * 7), "", "", "", ""])
            out.writerow([repr(t), "plate", *map(repr, plate), repr(radius), *map(repr, box)])
    columns = opf.track_log(log, estimator="opf", seed=6, particles=PARTICLES, dataframe=False)
    from_log = {}
    for t, name, mode, p in zip(columns["t"], columns["object"], columns["mode"],
                                columns["probability"]):
        if name == "cube":
            from_log.setdefault(t, []).append((mode, p))
    assert [from_log[t] for t, _, _ in frames] == with_box


UNSIZED_NOTE = ("the occluder module took a hidden object (carried or left) and no detection "
                "states a size (the radius or box_x,box_y,box_z columns)")


def test_track_log_warns_where_opf_track_notes_a_log_that_states_no_sizes(tmp_path):
    # The example's mug hides the ball, and the log states no sizes: opf track's note, as one
    # UserWarning. None for another estimator or a log that states a size (12 cm: the mug still
    # hides the ball once); a filter that makes warnings errors makes it one.
    options = {"camera": "0.4,0,0.8", "particles": PARTICLES, "seed": 2, "dataframe": False}

    def taken(columns):
        return sum(mode.startswith(("carried", "left")) for mode in columns["mode"])

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        columns = opf.track_log(EXAMPLE_LOG, **options)
    assert taken(columns) > 0
    assert [(w.category, str(w.message)[:len(UNSIZED_NOTE)], w.filename) for w in caught] == \
        [(UserWarning, UNSIZED_NOTE, __file__)]
    sized = tmp_path / "sized.csv"
    with open(EXAMPLE_LOG) as f, open(sized, "w") as out:
        for i, line in enumerate(f):
            out.write(line.rstrip("\n") + (",radius\n" if i == 0 else ",0.12\n"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert taken(opf.track_log(EXAMPLE_LOG, estimator="cvkf", **options)) == 0
        assert taken(opf.track_log(sized, **options)) > 0
        with pytest.raises(UserWarning, match=re.escape(UNSIZED_NOTE)):
            opf.track_log(EXAMPLE_LOG, **options)


def test_track_log_warns_where_opf_track_notes_a_log_of_positions_alone(tmp_path):
    # A log without qx, qy, qz, qw reads every orientation as the identity: opf track's note, as
    # one UserWarning naming the file. cvkf's positions are those of the whole log's.
    positions = tmp_path / "positions.csv"
    with open(EXAMPLE_LOG) as f, open(positions, "w") as out:
        for line in f:
            out.write(",".join(line.rstrip("\n").split(",")[:5]) + "\n")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        columns = opf.track_log(positions, estimator="cvkf", dataframe=False)
    note = (f"{positions}: it states positions only (no qx, qy, qz, qw columns): every "
            "detection's orientation is read as the identity, so the estimated orientations and "
            "rotation errors say nothing about the objects")
    assert [(w.category, str(w.message), w.filename) for w in caught] == \
        [(UserWarning, note, __file__)]
    whole = opf.track_log(EXAMPLE_LOG, estimator="cvkf", dataframe=False)
    assert len(columns["t"]) == len(whole["t"]) == 360
    for name in ("t", "x", "y", "z"):
        assert list(columns[name]) == list(whole[name]), name
    assert {tuple(q) for q in zip(*(columns[c] for c in ("qx", "qy", "qz", "qw")))} == \
        {(0.0, 0.0, 0.0, 1.0)}
