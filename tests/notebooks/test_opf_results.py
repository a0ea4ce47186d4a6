"""notebooks/opf_results.py: one sample standard deviation (ddof=1) over seeds everywhere."""

import math
import sys
from pathlib import Path

import pandas as pd
import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "notebooks"))
import opf_results  # noqa: E402


def test_mean_std_is_the_sample_std():
    mean, std, n = opf_results.mean_std([1, 2, 3, 4])
    assert (mean, n) == (2.5, 4)
    assert std == pytest.approx(1.2910, abs=1e-4)  # ddof=0 would give 1.1180


def test_mean_std_of_one_value_has_no_std():
    mean, std, n = opf_results.mean_std([0.5, float("nan")])
    assert (mean, n) == (0.5, 1) and math.isnan(std)


def test_seeds_text():
    assert opf_results.seeds_text([5, 5]) == "5 seeds"
    assert opf_results.seeds_text([2, 5]) == "2-5 seeds"
    assert opf_results.seeds_text([1]) == "1 seed"


def test_table_one_std_is_over_seeds_with_ddof_1(tmp_path):
    runs = pd.DataFrame({"experiment": "general_op", "estimator": "opf", "seed": range(4),
                         "translation_error": [1.0, 2.0, 3.0, 4.0],
                         "rotation_error_paper": [0.1, 0.1, 0.1, 0.1]})
    runs.to_csv(tmp_path / "general_op_runs.csv", index=False)
    row = opf_results.table_one(str(tmp_path)).iloc[0]
    assert row.seeds == 4
    assert row.translation_std == pytest.approx(1.2910, abs=1e-4)
    assert row.paper_translation_mean == pytest.approx(0.01138)


def test_summarise_std_is_the_sample_std():
    rows = pd.DataFrame({"estimator": "opf", "particles": 100,
                         "translation_error": [1.0, 2.0, 3.0, 4.0]})
    summary = opf_results.summarise(rows, ["estimator", "particles"]).iloc[0]
    assert summary["count"] == 4
    assert summary["std"] == pytest.approx(1.2910, abs=1e-4)


def test_dynamics_ablation_summary_is_a_geometric_mean():
    rows = pd.DataFrame({"variant": ["full bank"] * 2 + ["without velocity"] * 2,
                         "kind": ["flying", "driving"] * 2,
                         "hidden_translation_over_cvkf": [0.5, 2.0, 1.0, 4.0],
                         "hidden_rotation_over_cvkf": [1.0, 1.0, 1.0, float("nan")]})
    table = opf_results.dynamics_ablation_summary(rows)
    assert table.loc["full bank", "translation / cvkf"] == pytest.approx(1.0)
    assert table.loc["without velocity", "translation / cvkf"] == pytest.approx(2.0)
    assert table.loc["without velocity", "driving"] == pytest.approx(4.0)
    assert table.attrs["logs"] == 2


def test_sweeps_drawn_on_one_axis_all_show():
    # Two experiments' sweeps on one axis, the second an order of magnitude above the first: the
    # axis starts at zero and holds the second's error bars too.
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots()
    for experiment, error in (("general_op", 0.005), ("baseball", 0.4)):
        rows = pd.DataFrame({"series": f"opf {experiment}", "kappa": [1.0, 1.0, 2.0, 2.0],
                             "translation_error": [error, error * 1.1, error, error * 1.1]})
        opf_results.plot_sweep(rows, "kappa", "translation_error", ax, series="series")
    low, high = ax.get_ylim()
    plt.close(fig)
    assert low == 0.0 and high >= 0.44
