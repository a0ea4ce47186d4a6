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


def ratios_of(pairs):
    """{(sequence, rate, gap): ratio} for (sequence, ratio) pairs, a log per pair."""
    return {(sequence, "native", str(k)): ratio for k, (sequence, ratio) in enumerate(pairs)}


def test_the_interval_resamples_recordings_and_weighs_their_logs():
    # Two recordings, each one log: a draw holds a twice (1/4), b twice (1/4) or both (1/2), so
    # the geometric means are 0.5, 2 and 1, and the 95% interval runs from 0.5 to 2 exactly.
    draws = bench.bootstrap_draws({"a", "b"})
    assert bench.geometric_mean_interval(ratios_of([("a", 0.5), ("b", 2.0)]), draws) == \
        pytest.approx((0.5, 2.0))
    # A drawn recording brings all its logs: a's three at 0.5 and b's one at 2 give
    # exp((3 ln 0.5 + ln 2) / 4) = 0.707 for a draw of both, not 1, the recordings' mean.
    low, high = bench.geometric_mean_interval(
        ratios_of([("a", 0.5), ("a", 0.5), ("a", 0.5), ("b", 2.0)]), draws)
    assert (low, high) == pytest.approx((0.5, 2.0))
    means = {round(bench.geometric_mean_interval(ratios_of(
        [("a", 0.5), ("a", 0.5), ("a", 0.5), ("b", 2.0)]), [draw], level=0.0)[0], 3)
        for draw in (["a", "b"], ["b", "a"])}
    assert means == {0.707}


def test_a_sequences_pedestrians_are_one_recording():
    # Two tracks of one MOT sequence, 0.5 and 2: every draw takes both, so the interval is their
    # geometric mean, 1, with no spread; as two recordings they would span 0.5-2.
    assert bench.recording("mot17_02_p38") == "mot17_02"
    assert bench.recording("euroc_v101") == "euroc_v101"
    tracks = ratios_of([("mot17_02_p38", 0.5), ("mot17_02_p68", 2.0)])
    draws = bench.bootstrap_draws({"mot17_02"})
    assert bench.geometric_mean_interval(tracks, draws) == pytest.approx((1.0, 1.0))


def test_the_interval_is_seeded_and_skips_what_it_cannot_take_the_log_of():
    ratios = ratios_of([(name, 0.5 + 0.1 * k) for k, name in enumerate("abcdefgh")])
    recordings = set("abcdefgh")
    first = bench.geometric_mean_interval(ratios, bench.bootstrap_draws(recordings))
    assert first == bench.geometric_mean_interval(ratios, bench.bootstrap_draws(recordings))
    assert 0.5 < first[0] < bench.geometric_mean(ratios.values()) < first[1] < 1.2
    with_nan = {**ratios, **ratios_of([("z", math.nan)])}
    assert bench.geometric_mean_interval(with_nan, bench.bootstrap_draws(recordings)) == first
    nothing = bench.geometric_mean_interval(ratios_of([("a", math.nan)]),
                                            bench.bootstrap_draws({"a"}))
    assert all(math.isnan(v) for v in nothing)


def test_the_worst_rows_interval_resamples_its_gaps():
    # Three gaps of 10 frames; the OPF 2 cm, 1 cm and 1 cm where cvkf is 1 cm on each: 4/3 over
    # the row, 1 where a draw has no first gap, 2 where it has only that one.
    cvkf = {("o", t): (10, 0.01) for t in (1.0, 2.0, 3.0)}
    opf = {("o", 1.0): (10, 0.02), ("o", 2.0): (10, 0.01), ("o", 3.0): (10, 0.01)}
    ratio, low, high, count = bench.gap_ratio_interval(opf, cvkf)
    assert (ratio, low, high, count) == pytest.approx((4 / 3, 1.0, 2.0, 3))
    # Gaps one run lacks are left out; one gap gives no interval.
    ratio, low, high, count = bench.gap_ratio_interval({("o", 1.0): (10, 0.02)}, cvkf)
    assert ratio == pytest.approx(2.0) and count == 1 and math.isnan(low) and math.isnan(high)


def test_the_summary_names_the_worst_rows_interval_over_its_gaps():
    rows = [dict(row("a", "opf", 1.0, 0.9), hidden_translation=0.0133),
            dict(row("a", "cvkf", 1.0, 0.9), hidden_translation=0.01)]
    bins = frames("a", "opf", [30]) + frames("a", "cvkf", [30])
    gaps = [{"sequence": "a", "rate": "native", "gap": "1", "preset": "default",
             "estimator": estimator, "object": "o", "gap_start": t, "frames": 10,
             "hidden_translation": error}
            for estimator, errors in (("opf", (0.02, 0.01, 0.01)), ("cvkf", (0.01,) * 3))
            for t, error in zip((1.0, 2.0, 3.0), errors)]
    opf = next(s for s in bench.summarise(rows, bins, gaps) if s["estimator"] == "opf")
    assert opf["worst_gaps"] == pytest.approx((1.0, 2.0, 3))
    assert bench.gaps_text(opf) == "; 1.00-2.00 over its 3 gaps"
