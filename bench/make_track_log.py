#!/usr/bin/env python3
"""Writes the measurement log of the `opf track` timing (bench/time_track.sh): 3 objects, 2000
frames at 30 Hz (66.7 s), in the measurement-log format of experiments/data/README.md.

  ball  circles (r = 0.15 m, 0.4 rad/s) around (0.5, 0, 0.02) while spinning about z; hidden for
        1 s out of every 5 (the OPF's dynamics and occluder modules run).
  mug   slides back and forth along x (0.1 m amplitude, 0.2 rad/s); always seen.
  cup   stands still at (0.3, 0.25, 0.05); a seeded 5% of its detections are missing.

Gaussian noise: 5 mm per axis, 0.02 rad per rotation axis. Seeded: the same file every time.

    /usr/bin/python3 bench/make_track_log.py OUT.csv [--frames 2000] [--seed 3]
"""

import argparse
import math
import random


def quaternion_z(angle, noise):
    """Unit quaternion (x, y, z, w) of yaw `angle` turned by a small noise rotation vector."""
    half = 0.5 * angle
    q = (0.0, 0.0, math.sin(half), math.cos(half))
    n = math.sqrt(sum(c * c for c in noise))
    if n < 1e-12:
        return q
    s = math.sin(0.5 * n) / n
    e = (s * noise[0], s * noise[1], s * noise[2], math.cos(0.5 * n))
    ax, ay, az, aw = q
    bx, by, bz, bw = e
    r = (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
         aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)
    if r[3] < 0:
        r = tuple(-c for c in r)
    return r


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--frames", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=3)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    with open(args.out, "w", encoding="ascii") as f:
        f.write("t,object,x,y,z,qx,qy,qz,qw\n")
        for k in range(args.frames):
            t = k / 30.0
            a = 0.4 * t
            truth = {
                "ball": ((0.5 + 0.15 * math.cos(a), 0.15 * math.sin(a), 0.02), 0.5 * t),
                "mug": ((0.6 + 0.1 * math.sin(0.2 * t), -0.2, 0.05), 0.3),
                "cup": ((0.3, 0.25, 0.05), -0.4),
            }
            for name, (p, yaw) in truth.items():
                noise = [rng.gauss(0, 1) for _ in range(6)]
                if name == "ball" and (t % 5.0) >= 4.0:
                    continue
                if name == "cup" and rng.random() < 0.05:
                    continue
                x, y, z = (p[i] + 0.005 * noise[i] for i in range(3))
                q = quaternion_z(yaw, [0.02 * v for v in noise[3:]])
                f.write(f"{t:.6f},{name},{x:.6f},{y:.6f},{z:.6f},"
                        f"{q[0]:.9f},{q[1]:.9f},{q[2]:.9f},{q[3]:.9f}\n")


if __name__ == "__main__":
    main()
