"""The benchmark's summary: calibration pooled over every hidden frame of the logs."""

import importlib.util
import math
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location(
    "run_benchmark", ROOT / "experiments" / "real_motion" / "run_benchmark.py")
bench = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(bench)


def row(sequence, estimator, nees, inside, hidden=1.0):
    return {"sequence": sequence, "kind": "handheld", "rate": "native", "gap": "1",
            "preset": "default", "estimator": estimator, "hidden_translation": hidden,
            "hidden_rotation": hidden, "nees_translation": nees, "inside95_translation": inside,
            "nees_rotation": math.nan, "inside95_rotation": math.nan}


def frames(sequence, estimator, counts):
    return [{"sequence": sequence, "rate": "native", "gap": "1", "preset": "default",
             "estimator": estimator, "frames": n} for n in counts]


def test_calibration_is_weighed_by_hidden_frames():
    # Log a: 100 hidden frames at NEES/3 1.0 and 90% inside; log b: 300 frames at 3.0 and 50%.
    # Pooled over the 400 frames: (100 + 900) / 400 = 2.5 and (90 + 150) / 400 = 60%, where the
    # mean over the two logs would say 2.0 and 70%.
    rows = [row("a", "opf", 1.0, 0.9), row("b", "opf", 3.0, 0.5),
            row("a", "cvkf", 1.0, 1.0), row("b", "cvkf", 1.0, 1.0)]
    bins = (frames("a", "opf", [60, 40]) + frames("b", "opf", [300])
            + frames("a", "cvkf", [100]) + frames("b", "cvkf", [300]))
    summary = {s["estimator"]: s for s in bench.summarise(rows, bins)}
    assert summary["opf"]["nees_translation"] == pytest.approx(2.5)
    assert summary["opf"]["inside95_translation"] == pytest.approx(0.6)
    # Nothing to score (a pedestrian's rotation): NaN, not zero.
    assert math.isnan(summary["opf"]["nees_rotation"])


def test_a_share_just_outside_the_calibration_bounds_is_not_rounded_onto_them():
    assert bench.percent(0.8498) == "84.98%"
    assert bench.percent(0.9804) == "98.04%"
    assert bench.percent(0.85) == "85%" and bench.percent(0.93) == "93%"
    assert bench.percent(math.nan) == "nan%"
