#!/usr/bin/env python3
"""Replays the 3-object, 2000-frame log of bench/make_track_log.py (5000 + 5000 particles, one
thread, the default OPF) through the `opf` program and through the Python module, and prints
the best of REPEATS wall times of each and their ratio. The Python replay should cost at most
10% more than the program's (it skips writing text, and converts every estimate to numpy).

    PYTHONPATH=build/python /usr/bin/python3 bench/python_replay.py [--build build] [--repeats 5]
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time


def best_of(repeats, run):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    sys.path.insert(0, os.path.join(args.build, "python"))
    import opf

    here = os.path.dirname(os.path.abspath(__file__))
    with tempfile.TemporaryDirectory() as work:
        log = os.path.join(work, "log.csv")
        subprocess.run([sys.executable, os.path.join(here, "make_track_log.py"), log], check=True)
        program = os.path.join(args.build, "bin", "opf")
        cli = best_of(args.repeats, lambda: subprocess.run(
            [program, "track", "--in", log, "--out", os.path.join(work, "est.csv"),
             "--particles", "5000", "--threads", "1", "--quiet"], check=True))
        python = best_of(args.repeats, lambda: opf.track_log(log, particles=5000,
                                                             dataframe=False))
    print(f"opf track (process, 2000 frames): {cli:.3f} s; opf.track_log: {python:.3f} s; "
          f"ratio {python / cli:.3f} (best of {args.repeats})")


if __name__ == "__main__":
    main()
