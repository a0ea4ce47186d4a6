"""The benchmark's --config, --gaps and --missed: the settings file reaches every `opf evaluate`; a
missing one, bad gap lengths or probabilities, both ways of hiding frames at once and either with
the subset are refused before anything runs; missed detections in a clip keep their rows."""

import importlib.util
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "experiments" / "real_motion" / "run_benchmark.py"
_spec = importlib.util.spec_from_file_location("run_benchmark", SCRIPT)
bench = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(bench)

JOB = {"log": "a.csv", "truth": "a_truth.csv", "preset": "default"}


def test_the_settings_file_follows_the_preset_in_every_evaluate():
    command = bench.evaluate_command(JOB, "opf", "opf,cvkf", 3, "runs/a", "noise.yaml")
    assert command[command.index("--preset") + 1] == "default"
    assert command[command.index("--config") + 1] == "noise.yaml"
    # After the preset: opf applies --config on top of it.
    assert command.index("--config") > command.index("--preset")
    paper = bench.evaluate_command(dict(JOB, preset="paper"), "opf", "opf,cvkf,pf", 3, "runs/a",
                                   "noise.yaml")
    assert paper[paper.index("--estimators") + 1] == "opf,pf"
    assert paper[paper.index("--config") + 1] == "noise.yaml"


def test_without_a_settings_file_the_command_has_none():
    command = bench.evaluate_command(JOB, "opf", "opf,cvkf", 3, "runs/a")
    assert "--config" not in command
    assert command[-6:] == ["--out", "runs/a.csv", "--hidden-profile", "runs/a_profile.csv",
                            "--gap-errors", "runs/a_gaps.csv"]


def test_a_missing_settings_file_is_refused_by_name(tmp_path):
    missing = tmp_path / "nowhere.yaml"
    done = subprocess.run([sys.executable, str(SCRIPT), str(tmp_path / "out"), "--opf",
                           sys.executable, "--config", str(missing)],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 2
    assert f"--config {missing}: no such settings file" in done.stderr
    assert not (tmp_path / "out").exists()


def test_bad_gap_lengths_and_gaps_with_the_subset_are_refused_before_anything_runs(tmp_path):
    for extra, message in ((["--gaps", "2,x"], "--gaps '2,x': expected seconds"),
                           (["--gaps", "40"], "each above 0 and at most 30"),
                           (["--subset", "--gaps", "2"], "--subset runs the 0.6 s gaps only"),
                           (["--missed", "1"], "--missed '1': expected a probability above 0"),
                           (["--missed", "x"], "--missed 'x': expected a probability"),
                           (["--subset", "--missed", "0.3"], "leave out --gaps and --missed"),
                           (["--gaps", "2", "--missed", "0.3"], "give one")):
        done = subprocess.run([sys.executable, str(SCRIPT), str(tmp_path / "out"), "--opf",
                               sys.executable, *extra], capture_output=True, text=True,
                              check=False)
        assert done.returncode == 2, extra
        assert message in done.stderr, done.stderr
        assert not (tmp_path / "out").exists()


def test_a_clips_missed_detections_keep_their_rows_and_the_first_is_seen(tmp_path):
    truth = tmp_path / "clip.csv"
    rows = ["t,object,x,y,z,qx,qy,qz,qw,extra_noise"]
    rows += [f"{k / 30!r},box,{k},0,1,0,0,0,1,0" for k in range(300)]
    truth.write_text("\n".join(rows) + "\n")
    log = tmp_path / "clip_missed0.3.csv"
    bench.drop_detections(truth, log, 0.3, 5)
    out = log.read_text().splitlines()
    assert len(out) == len(rows) and out[0] == rows[0] and out[1] == rows[1]
    emptied = [line for line in out[1:] if line.split(",")[2] == ""]
    assert 60 < len(emptied) < 120  # 0.3 of 299, binomial sd 8
    for line in emptied:
        fields = line.split(",")
        assert fields[1] == "box" and fields[2:9] == [""] * 7 and fields[9] == "0"
    bench.drop_detections(truth, tmp_path / "again.csv", 0.3, 5)
    assert (tmp_path / "again.csv").read_bytes() == log.read_bytes()  # seeded
    assert bench.hiding_text("missed0.3") == "30% missed"
    assert bench.convert.missed_probability(bench.convert.missed_label(0.25)) == 0.25
    assert bench.convert.missed_probability("0.6") is None
    assert bench.hiding_text("occluded") == "annotated" and bench.hiding_text("0.6") == "0.6 s"
