#!/usr/bin/env python3
"""Generates the bundled example measurement log and its ground truth.

Simulates a 30 Hz pose tracker watching two objects for 6 s (t = k/30, k = 0..179):

  ball  moves from (0.40, -0.20, 0.02) m at a constant (0, 0.08, 0) m/s while turning about z at
        0.5 rad/s (yaw = 0.5 t). It is occluded for t in [2.0, 3.0): in that window every other
        frame has a row with the seven pose fields empty and the rest have no ball row at all, so
        both ways of marking an object unobserved are exercised.
  mug   stands still at (0.55, 0.10, 0.05) m with yaw 0.3 rad; a seeded 5% of the frames (9 of 180)
        have no mug row, as when a detector misses.

Detections carry Gaussian noise: N(0, 0.005^2) m per axis on the position and, on the orientation,
q_true * exp(w) with the rotation vector w ~ N(0, 0.02^2) rad per axis (body frame), normalised and
written with qw >= 0. Both files have the measurement-log columns t,object,x,y,z,qx,qy,qz,qw plus a
`source` column (always `sim`) that readers must ignore.

Writes example_log.csv (the detections) and example_truth.csv (every object at every frame) next
to this script. Numbers have fixed precision (%.6f, quaternions %.9f) and the noise is seeded, so
regenerating gives byte-identical files:

    /usr/bin/python3 experiments/data/make_example_log.py [--seed 7]

Standard library only.
"""

import argparse
import math
import pathlib
import random

RATE_HZ = 30
FRAMES = 180  # 6 s
TRANSLATION_NOISE = 0.005  # m, per axis
ROTATION_NOISE = 0.02  # rad, per axis of the rotation vector
OCCLUSION_FRAMES = range(2 * RATE_HZ, 3 * RATE_HZ)  # t in [2.0, 3.0)
MUG_MISSED_FRAMES = 9  # 5% of 180
HEADER = "t,object,x,y,z,qx,qy,qz,qw,source\n"


def quaternion_multiply(a, b):
    """Hamilton product of quaternions stored as (x, y, z, w)."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    )


def quaternion_exp(v):
    """Unit quaternion (x, y, z, w) of the rotation vector v."""
    angle = math.sqrt(sum(c * c for c in v))
    if angle < 1e-12:
        return (0.5 * v[0], 0.5 * v[1], 0.5 * v[2], 1.0)
    s = math.sin(0.5 * angle) / angle
    return (s * v[0], s * v[1], s * v[2], math.cos(0.5 * angle))


def yaw_quaternion(yaw):
    return (0.0, 0.0, math.sin(0.5 * yaw), math.cos(0.5 * yaw))


def canonical(q):
    """Normalised, with qw >= 0 (q and -q are the same rotation)."""
    norm = math.sqrt(sum(c * c for c in q))
    sign = -1.0 if q[3] < 0.0 else 1.0
    return tuple(sign * c / norm for c in q)


def true_pose(name, t):
    if name == "ball":
        return (0.40, -0.20 + 0.08 * t, 0.02), yaw_quaternion(0.5 * t)
    return (0.55, 0.10, 0.05), yaw_quaternion(0.3)


def measure(rng, position, orientation):
    noisy_position = tuple(p + rng.gauss(0.0, TRANSLATION_NOISE) for p in position)
    w = tuple(rng.gauss(0.0, ROTATION_NOISE) for _ in range(3))
    return noisy_position, canonical(quaternion_multiply(orientation, quaternion_exp(w)))


def row(t, name, position=None, orientation=None):
    if position is None:
        return f"{t:.6f},{name},,,,,,,,sim\n"
    xyz = ",".join(f"{p:.6f}" for p in position)
    quaternion = ",".join(f"{c:.9f}" for c in orientation)
    return f"{t:.6f},{name},{xyz},{quaternion},sim\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=7, help="noise seed (default 7)")
    parser.add_argument("--out-dir", type=pathlib.Path, default=pathlib.Path(__file__).parent,
                        help="where to write the two CSV files (default: next to this script)")
    args = parser.parse_args()

    rng = random.Random(args.seed)
    mug_missed = set(rng.sample(range(FRAMES), MUG_MISSED_FRAMES))
    log = [HEADER]
    truth = [HEADER]
    for k in range(FRAMES):
        t = k / RATE_HZ
        for name in ("ball", "mug"):
            position, orientation = true_pose(name, t)
            truth.append(row(t, name, position, canonical(orientation)))
            if name == "ball" and k in OCCLUSION_FRAMES:
                if k % 2 == 0:
                    log.append(row(t, name))  # occluded, said explicitly
                continue  # odd frames: occluded, no row at all
            if name == "mug" and k in mug_missed:
                continue
            log.append(row(t, name, *measure(rng, position, orientation)))

    args.out_dir.mkdir(parents=True, exist_ok=True)
    for file_name, lines in (("example_log.csv", log), ("example_truth.csv", truth)):
        with open(args.out_dir / file_name, "w", encoding="ascii", newline="") as out:
            out.writelines(lines)


if __name__ == "__main__":
    main()
