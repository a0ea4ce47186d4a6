"""The Python module `opf` against the C++ program it wraps: the same numbers, the same errors.

Run by ctest (Python.Module) with PYTHONPATH at the build's staged package and OPF (the built
`opf` program) and OPF_SOURCE_DIR in the environment."""

import csv
import math
import os
import subprocess

import numpy as np
import pytest

import opf

SOURCE = os.environ["OPF_SOURCE_DIR"]
OPF = os.environ["OPF"]
EXAMPLE_LOG = os.path.join(SOURCE, "experiments", "data", "example_log.csv")
PARTICLES = 500


def cup_at(t):
    """A cup sliding along x at 0.2 m/s, turned 0.3 rad about z."""
    half = 0.15
    return [0.2 * t, 0.1, 0.5, 0.0, 0.0, math.sin(half), math.cos(half)]


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


def test_track_log_is_opf_track_number_for_number(tmp_path):
    out = tmp_path / "estimates.csv"
    subprocess.run([OPF, "track", "--in", EXAMPLE_LOG, "--out", str(out), "--estimator", "opf",
                    "--seed", "4", "--particles", str(PARTICLES), "--quiet"], check=True)
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))
    columns = opf.track_log(EXAMPLE_LOG, estimator="opf", seed=4, particles=PARTICLES,
                            dataframe=False)
    assert len(columns["t"]) == len(rows) > 300
    for name in ("t", "x", "y", "z", "qx", "qy", "qz", "qw", "trace"):
        # The file holds the shortest text that reads back exactly: equality, not closeness.
        assert np.array_equal(columns[name], np.array([float(r[name]) for r in rows])), name
    assert columns["object"] == [r["object"] for r in rows]
    assert columns["mode"] == [r["mode"] for r in rows]
    assert list(columns["hypothesis"]) == [int(r["hypothesis"]) for r in rows]
    assert list(columns["alert"]) == [r["alert"] == "1" for r in rows]
    assert columns["model"] == [r["model"] for r in rows]


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
    with pytest.raises(ValueError, match="unit norm"):
        opf.Tracker().step(0.0, {"cup": [0, 0, 0, 0, 0, 0, 2]})
    with pytest.raises(ValueError, match="particles must be at least 1"):
        opf.Tracker(particles=0)


def test_the_estimator_names_are_the_registrys():
    assert opf.estimators() == ["opf", "pf", "cvkf", "imm", "oapf"]
