#!/usr/bin/env python3
"""Prints the performance targets (docs/performance.md) against a Google Benchmark JSON report
written by bench/run_benchmarks.sh (medians of the repetitions). Standard library only.

    /usr/bin/python3 bench/summarise.py bench/results/HOST-DATE.json
"""

import json
import sys


SCALE = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}


def medians(report):
    """Benchmark name (without the _median suffix) -> real time in microseconds."""
    out = {}
    for b in report["benchmarks"]:
        if b.get("aggregate_name") == "median" or b.get("run_type") == "iteration":
            name = b["run_name"] if "run_name" in b else b["name"]
            out.setdefault(name, b["real_time"] * SCALE[b["time_unit"]])
            if b.get("aggregate_name") == "median":
                out[name] = b["real_time"] * SCALE[b["time_unit"]]
    return out


def fastest(report):
    """Benchmark name -> its fastest repetition's real time in microseconds, where reported."""
    return {b["run_name"]: b["real_time"] * SCALE[b["time_unit"]]
            for b in report["benchmarks"] if b.get("aggregate_name") == "min"}


def main():
    report = json.load(open(sys.argv[1], encoding="utf-8"))
    t = medians(report)
    c = report["context"]
    print(f"\n{c.get('host_name')}: {c.get('num_cpus')} CPUs at {c.get('mhz_per_cpu')} MHz, "
          f"{c.get('compiler')}, {c.get('build_type')}, kernels {c.get('particle_kernels')}")

    def show(label, value, target, unit="us"):
        if value is None:
            print(f"  {label:58s} (not run)")
            return
        verdict = "meets" if value <= target else "MISSES"
        # Milliseconds to two places: a frame of 2.01 ms must not print as the 2.0 it misses.
        digits = 2 if unit == "ms" else 1
        print(f"  {label:58s} {value:9.{digits}f} {unit}  target <= {target:g} {unit}: {verdict}")

    opf_step, pf_step = t.get("BM_EstimatorStep/opf/n:5000"), t.get("BM_EstimatorStep/pf/n:5000")
    show("OPF step, 5000 + 5000 particles", opf_step, 50)
    show("PF step, 5000 + 5000 particles", pf_step, 50)
    show("OPF step while hidden, 5000 + 5000 particles", t.get("BM_OpfHiddenStep/n:5000"), 50)
    low = fastest(report)
    low_opf, low_pf = low.get("BM_EstimatorStep/opf/n:5000"), low.get("BM_EstimatorStep/pf/n:5000")
    if low_opf and low_pf:
        # Not a verdict: what the step costs in the host's quietest moment of the run.
        label = "fastest repetition: OPF step, PF step"
        print(f"  {label:58s} {low_opf:9.1f} us, {low_pf:.1f} us")
    if opf_step and pf_step:
        # The OP update's own cost: a slower CPU or a busy host scales both steps alike.
        label = "OPF step over the PF step (the OP update's cost)"
        print(f"  {label:58s} {opf_step / pf_step:9.2f} x")
    base = t.get("BM_EstimatorStep/opf/n:1000")
    if base:
        for n in (3000, 5000, 10000, 30000, 100000):
            v = t.get(f"BM_EstimatorStep/opf/n:{n}")
            if v:
                ratio = v / (base * n / 1000)
                print(f"  OPF step at {n:6d}: {v:9.1f} us = {ratio:4.2f} x the linear extrapolation "
                      f"from 1000 (target <= 1.2): {'meets' if ratio <= 1.2 else 'MISSES'}")
    v = t.get("BM_EnsembleFrame/objects:64/threads:1/real_time")
    if v:
        print(f"  {'frame of 64 objects, 1 thread':58s} {v / 1e3:9.2f} ms")
    v = t.get("BM_EnsembleFrame/objects:64/threads:2/real_time")
    show("frame of 64 objects, 2 threads", v / 1e3 if v else None, 2, "ms")
    # Per object both banks update every frame: the translation bank's and the rotation bank's.
    translation, rotation = t.get("BM_BankUpdate"), t.get("BM_RotationBankUpdate/damped:1")
    if translation and rotation:
        label = "banks' update per object: translation, rotation"
        print(f"  {label:58s} {translation:9.1f} us, {rotation:.1f} us")
    show("banks' update per object, both", translation + rotation if translation and rotation
         else None, 5, "us")
    # The same with a camera's clock: every interval 1/30 s +- 1 ms, no two steps alike.
    show("banks' update per object, both, a camera's clock", t.get("BM_BanksUpdateJitteredClock"),
         5, "us")
    v = t.get("BM_RenderAndDetectFrame")
    show("render + detect a 640x480 frame", v / 1e3 if v else None, 10, "ms")


if __name__ == "__main__":
    main()
