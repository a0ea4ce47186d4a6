"""Two benchmark runs compared: the verdict follows the stated rule, bad input names its place."""

import csv
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "experiments" / "real_motion" / "compare_runs.py"
RESULT_COLUMNS = ("sequence", "kind", "rate", "gap", "preset", "estimator", "hidden_translation",
                  "hidden_rotation", "nees_translation", "nees_rotation", "inside95_translation",
                  "inside95_rotation")
PROFILE_COLUMNS = ("sequence", "kind", "rate", "gap", "preset", "estimator", "time_hidden_from",
                   "time_hidden_to", "frames", "hidden_translation", "hidden_rotation")


def write_run(directory, opf_errors, nees=1.0, inside=0.93):
    """A run over logs a, b, c (100 hidden frames each): cvkf's hidden error 1.0 on every log,
    the OPF's the given ones, its calibration the given one on every log."""
    directory.mkdir()
    results, profile = [], []
    for sequence, opf in zip("abc", opf_errors):
        for estimator, error in (("opf", opf), ("cvkf", 1.0)):
            key = [sequence, "handheld", "native", "1", "default", estimator]
            results.append(key + [error, error, nees, nees, inside, inside])
            profile.append(key + [0, 0.1, 100, error, error])
    for name, columns, rows in (("results.csv", RESULT_COLUMNS, results),
                                ("profile.csv", PROFILE_COLUMNS, profile)):
        with open(directory / name, "w", newline="") as f:
            writer = csv.writer(f, lineterminator="\n")
            writer.writerow(columns)
            writer.writerows(rows)
    return directory


def compare(base, change):
    return subprocess.run([sys.executable, str(SCRIPT), str(base), str(change)],
                          capture_output=True, text=True, check=False)


def compare_errors(tmp_path, base_errors, change_errors, **change_calibration):
    """compare() of a base and a change written by write_run under tmp_path."""
    return compare(write_run(tmp_path / "base", base_errors),
                   write_run(tmp_path / "change", change_errors, **change_calibration))


def test_a_better_mean_everywhere_is_taken(tmp_path):
    done = compare_errors(tmp_path, [0.9, 0.9, 0.9], [0.8, 0.85, 0.9])
    assert done.returncode == 0, done.stdout + done.stderr
    assert done.stdout.strip().endswith("verdict: taken")
    # (0.8 * 0.85 * 0.9)^(1/3) = 0.849; two of the three rows moved by more than 5%.
    assert "change: hidden error / cvkf 0.849" in done.stdout
    assert "rows moved by more than 5%: 2 of 3" in done.stdout
    assert "  a/native/1: 0.900 -> 0.800" in done.stdout


def test_a_better_mean_with_a_row_pushed_past_the_worst_allowed_is_not_taken(tmp_path):
    # The mean falls from 1.0 to (0.6 * 0.6 * 1.2)^(1/3) = 0.756, but log c goes to 1.2x cvkf.
    done = compare_errors(tmp_path, [1.0, 1.0, 1.0], [0.6, 0.6, 1.2])
    assert done.returncode == 1
    assert "verdict: not taken: 1 row(s) newly above 1.10x cvkf: c/native/1 1.200" in done.stdout


def test_a_row_already_above_the_worst_allowed_does_not_block_a_better_change(tmp_path):
    done = compare_errors(tmp_path, [1.3, 1.0, 1.0], [1.2, 0.9, 0.9])
    assert done.returncode == 0, done.stdout


def test_a_calibration_that_leaves_its_bounds_is_not_taken(tmp_path):
    done = compare_errors(tmp_path, [1.0, 1.0, 1.0], [0.8, 0.8, 0.8], nees=2.5, inside=0.80)
    assert done.returncode == 1
    assert "the calibration leaves its bounds" in done.stdout
    assert "NEES/3 2.5 with 80% inside 95%" in done.stdout


def test_a_worse_mean_is_not_taken(tmp_path):
    done = compare_errors(tmp_path, [0.8, 0.8, 0.8], [0.7, 0.9, 0.95])
    assert done.returncode == 1
    assert "verdict: not taken: the mean is not better" in done.stdout


def test_bad_input_names_the_file_line_and_column(tmp_path):
    base = write_run(tmp_path / "base", [1.0, 1.0, 1.0])
    change = write_run(tmp_path / "change", [1.0, 1.0, 1.0])
    text = (change / "results.csv").read_text().replace("0.93", "lots", 1)
    (change / "results.csv").write_text(text)
    done = compare(base, change)
    assert done.returncode == 2
    assert f"{change / 'results.csv'}:2: column inside95_translation: not a number: 'lots'" \
        in done.stderr
    missing = compare(base, tmp_path / "nowhere")
    assert missing.returncode == 2 and "no such file" in missing.stderr


def test_the_change_is_given_with_its_interval_over_resampled_recordings(tmp_path):
    # Better by the same factor on every log: every resampled suite says 0.889.
    (tmp_path / "1").mkdir()
    (tmp_path / "2").mkdir()
    everywhere = compare_errors(tmp_path / "1", [0.9, 0.9, 0.9], [0.8, 0.8, 0.8])
    assert ("change / base: 0.889 (geometric mean over 3 logs; 95% interval over resampled "
            "recordings 0.889-0.889, below 1: better on resampled suites)") in everywhere.stdout
    # Better on the mean, (0.5 / 0.9 * 1 * 1.05 / 0.9)^(1/3) = 0.865, and taken, but worse on
    # log c: a suite of c alone says 1.167, one of a alone 0.556.
    mixed = compare_errors(tmp_path / "2", [0.9, 0.9, 0.9], [0.5, 0.9, 1.05])
    assert mixed.returncode == 0, mixed.stdout
    assert "change / base: 0.865" in mixed.stdout
    assert "interval over resampled recordings 0.556-1.167, it spans 1" in mixed.stdout
