"""run_ablation.py refuses what cannot run before it converts or runs anything."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "experiments" / "real_motion" / "run_ablation.py"


def test_bad_arguments_are_refused_by_name(tmp_path):
    for extra, message in ((["--seeds", "0"], "--seeds and --jobs must be at least 1"),
                           (["--jobs", "0"], "--seeds and --jobs must be at least 1"),
                           (["--opf", str(tmp_path / "none")],
                            f"no opf program at {tmp_path / 'none'}")):
        done = subprocess.run([sys.executable, str(SCRIPT), str(tmp_path / "out"), "--opf",
                               sys.executable, *extra], capture_output=True, text=True)
        assert done.returncode == 2, extra
        assert message in done.stderr, (extra, done.stderr)
        assert not (tmp_path / "out").exists()
