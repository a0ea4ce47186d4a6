"""paper/make_report.py: one sample std over N seeds, every missed target marked, and no
placeholder for what has not run (the section is left out, the command named once)."""

import importlib.util
import json
import math
import os
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pandas as pd
import pytest

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "paper" / "make_report.py"
_spec = importlib.util.spec_from_file_location("make_report", SCRIPT)
report = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(report)

MISSED = r"\textbf{missed}"


def test_mean_pm_std_is_the_sample_std():
    assert report.pm_of([1, 2, 3, 4], 2) == r"2.50 $\pm$ 1.29"  # ddof=0 would say 1.12
    assert report.pm_of([0.5], 2) == "0.50"  # one seed: no std
    assert report.std_over([5, 5]) == "std over 5 seeds"


def test_a_value_beyond_its_target_is_marked_missed():
    assert report.mark(79.4, report.TARGETS["opf_step_us"]) == MISSED
    assert report.mark(43.1, report.TARGETS["opf_step_us"]) == "met"
    assert report.mark(2.99, report.TARGETS["frame_64_objects_2_threads_ms"]) == MISSED
    assert report.mark(1.35, report.TARGETS["nees_position"]) == "met"
    assert report.mark(2.31, report.TARGETS["nees_position"]) == MISSED
    assert report.mark(0.99, report.TARGETS["inside95_position"]) == MISSED
    assert report.mark(math.nan, report.TARGETS["opf_step_us"]) == "--"


def test_rounding_does_not_hide_a_miss():
    # 84.98% inside the 95% ellipsoid misses 85-98%; "85%" would read as met.
    assert report.mark(0.8498, report.TARGETS["inside95_position"]) == MISSED
    assert report.inside_percent(0.8498) == r"84.98\%"
    assert report.inside_percent(0.925) == r"92.5\%"


def test_table_one_marks_the_opf_above_the_papers_error():
    row = SimpleNamespace(estimator="opf", translation_mean=0.0443, paper_translation_mean=0.0213,
                          rotation_mean=0.0267, paper_rotation_mean=0.0034)
    assert report.table_one_verdict(row).startswith(MISSED)
    assert report.table_one_verdict(row) == MISSED + ": translation, rotation"
    general_op = SimpleNamespace(estimator="opf", translation_mean=0.0108,
                                 paper_translation_mean=0.0114, rotation_mean=0.0163,
                                 paper_rotation_mean=0.0687)
    assert report.table_one_verdict(general_op) == "met"


def hand_scene(opf_mm, pf_mm, nearest_mm, right, reveals, floor_mm=math.nan):
    return pd.DataFrame({"hidden_translation": [opf_mm / 1000, pf_mm / 1000],
                         "nearest_hidden_translation": [nearest_mm / 1000, pf_mm / 1000],
                         "right_at_reveal": [right, math.nan], "reveals": [reveals, math.nan],
                         "floor_hidden_translation": [floor_mm / 1000] * 2},
                        index=["opf", "pf"])


def test_hand_scenes_mark_each_missed_target():
    assert report.hand_error_verdict("carry", hand_scene(20.8, 162.8, 13.5, 5, 5)) == MISSED
    assert report.hand_error_verdict("carry", hand_scene(9.9, 162.8, 8.0, 5, 5)) == "met"
    # A carry's floor, where the table has one, stands beside its verdict.
    assert report.hand_error_verdict("carry", hand_scene(20.8, 162.8, 13.5, 5, 5, 15.1)) == (
        MISSED + " (floor 15.1)")
    assert report.hand_error_verdict("pass", hand_scene(6.6, 4.0, 6.0, 5, 5)) == MISSED
    assert report.hand_error_verdict("cups", hand_scene(54.5, 210.6, 15.5, 4, 5)) == MISSED
    assert report.hand_reveal_verdict("cups", hand_scene(9.9, 287.2, 5.3, 4, 5)) == "4/5 met"
    assert report.hand_reveal_verdict("carry", hand_scene(9.9, 287.2, 5.3, 4, 5)) == "4/5 " + MISSED


def write_results(results):
    """Runs of general_op (the OPF above the paper's error) and one carry hand scene (the OPF
    above 10 mm), 3 seeds each; nothing else."""
    results.mkdir()
    runs = pd.DataFrame({"experiment": "general_op", "estimator": ["opf"] * 3 + ["pf"] * 3,
                         "seed": [0, 1, 2] * 2,
                         "translation_error": [0.02, 0.03, 0.04] + [0.06] * 3,
                         "rotation_error_paper": [0.01] * 6, "rotation_error_geodesic": [0.01] * 6,
                         "translation_error_unobserved": [0.05] * 6})
    runs.to_csv(results / "general_op_runs.csv", index=False)
    hands = results / "hand_scenes"
    (hands / "room_carry").mkdir(parents=True)
    pd.DataFrame({"recording": "room", "scene": "carry", "estimator": ["opf", "pf"],
                  "hidden_frames": 300, "hidden_translation": [0.0208, 0.16],
                  "nearest_hidden_translation": [0.0135, 0.16], "right_at_reveal": [3, None],
                  "reveals": [3, None]}).to_csv(hands / "hand_scenes.csv", index=False)
    pd.DataFrame({"experiment": "room_carry", "estimator": ["opf"] * 3 + ["pf"] * 3,
                  "seed": [0, 1, 2] * 2,
                  "translation_error_unobserved": [0.0198, 0.0208, 0.0218] + [0.16] * 3}).to_csv(
        hands / "room_carry" / "room_carry_runs.csv", index=False)


def generate(tmp_path, results):
    out = tmp_path / "generated"
    env = dict(os.environ, OPF_RESULTS=str(results), OPF_SWEEPS=str(tmp_path / "no_sweeps"),
               OPF_BENCH=str(tmp_path / "no_bench.json"),
               OPF_DYNAMICS_ABLATION=str(tmp_path / "no_ablation"))
    done = subprocess.run([sys.executable, str(SCRIPT), str(out)], env=env, capture_output=True,
                          text=True, check=True)
    return out, {p.name: p.read_text() for p in out.glob("*.tex")}, done.stderr


def test_missing_sections_are_left_out_with_their_command(tmp_path):
    results = tmp_path / "results"
    write_results(results)
    out, tex, stderr = generate(tmp_path, results)
    for name, text in tex.items():
        assert "not in this build" not in text.lower(), name
    assert r"\HaveSimulatedtrue" in tex["values.tex"]
    assert r"\HaveHandScenestrue" in tex["values.tex"]
    for absent in ("RealMotion", "DynamicsAblation", "ModuleAblation", "Sweeps",
                   "ParticleCounts", "Benchmarks"):
        assert rf"\Have{absent}false" in tex["values.tex"]
    assert "benchmarks.tex" not in tex and "sweeps.tex" not in tex
    assert tex["not_run.tex"].startswith(r"\medskip\noindent\textbf{Not run here.}")
    assert "bash bench/run_benchmarks.sh" in tex["not_run.tex"]
    assert "run_real_motion.sh" in tex["not_run.tex"] and "not run here:" in stderr


def test_generated_tables_carry_std_over_n_seeds_and_misses(tmp_path):
    results = tmp_path / "results"
    write_results(results)
    _, tex, _ = generate(tmp_path, results)
    assert "std over 3 seeds" in tex["table_one.tex"]
    assert r"0.0300 $\pm$ 0.0100" in tex["table_one.tex"]  # sample std of 0.02, 0.03, 0.04
    assert MISSED in tex["table_one.tex"]  # 0.03 m against the paper's 0.0114 m
    assert "std over 3 seeds" in tex["baselines.tex"]
    assert "std over 3 seeds" in tex["hand_scenes.tex"]
    assert r"20.8 $\pm$ 1.0" in tex["hand_scenes.tex"]
    assert MISSED in tex["hand_scenes.tex"]  # 20.8 mm carried, target 10 mm


@pytest.mark.skipif(not (ROOT / "results" / "real_motion" / "results.csv").exists(),
                    reason="no main-job results in results/")
def test_the_main_jobs_results_mark_the_real_motion_misses(tmp_path):
    _, tex, _ = generate(tmp_path, ROOT / "results")
    assert MISSED in tex["real_motion.tex"]
    for name, text in tex.items():
        assert "not in this build" not in text.lower(), name
        assert "over - seeds" not in text and "--{} seeds" not in text, name


def bench_report(path, medians):
    """A benchmark report holding the given medians (run name: microseconds)."""
    path.write_text(json.dumps({"context": {}, "benchmarks": [
        {"run_name": name, "aggregate_name": "median", "real_time": us, "time_unit": "us"}
        for name, us in medians.items()]}))
    return path


def test_the_banks_update_per_object_is_both_banks(tmp_path):
    results = tmp_path / "results"
    write_results(results)
    bench = bench_report(tmp_path / "bench.json", {"BM_BankUpdate": 3.1,
                                                   "BM_RotationBankUpdate/damped:1": 4.5,
                                                   "BM_BanksUpdateJitteredClock": 4.9})
    env = dict(os.environ, OPF_RESULTS=str(results), OPF_SWEEPS=str(tmp_path / "no_sweeps"),
               OPF_BENCH=str(bench), OPF_DYNAMICS_ABLATION=str(tmp_path / "no_ablation"))
    out = tmp_path / "generated"
    subprocess.run([sys.executable, str(SCRIPT), str(out)], env=env, check=True,
                   capture_output=True)
    rows = {line.split("&")[0].strip(): line for line in
            (out / "benchmarks.tex").read_text().splitlines() if "&" in line}
    assert "3.1" in rows["translation bank's update per object"]
    assert "4.5" in rows["rotation bank's update per object"]
    both = rows["both banks' update per object"]
    assert "7.6" in both and MISSED in both  # 7.6 us against the 5 us target
    clock = rows["both banks, a camera's clock (1/30 s $\\pm$ 1 ms)"]
    assert "4.9" in clock and MISSED not in clock  # its own benchmark, against the same target
    # Without the rotation bank's figure (an older report) there is no sum to give.
    bench_report(bench, {"BM_BankUpdate": 3.1})
    subprocess.run([sys.executable, str(SCRIPT), str(out)], env=env, check=True,
                   capture_output=True)
    assert "both banks" not in (out / "benchmarks.tex").read_text()
