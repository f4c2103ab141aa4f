#!/usr/bin/env python3
"""Writes N random vertex-face queries in the benchmark's rational CSV
format (scripts/ccd_csv_to_scene.py), for load tests of whole sets;
coordinates are doubles written exactly, as in the benchmark's simulation
data; no ground truth (the truth column is left out).

  bench/ccd_random_csv.py N SEED OUT.csv [--resting]

Default: a point and a triangle near a random spot of [-1, 1]^3 (spread
0.05), moving by a common random step (0.02) with per-vertex noise (0.005):
most such pairs are far apart, as after a broad phase.

--resting: a point resting near the triangle (0,0,0), (1,0,0), (0,1,0),
which tilts slightly (each vertex's height moves by up to d); the point
starts at height d and slides by up to 0.1 sideways and up to d in height,
d log-uniform in [1e-9, 1e-5]. Such pairs come within 1e-6 of contact over
long stretches of the motion, the stress case of an epsilon-driven
subdivision (bench/README.md, "Bodies resting within epsilon").
"""
import random
import sys
from fractions import Fraction


def broad_phase_like(rng):
    base = [rng.uniform(-1, 1) for _ in range(3)]
    at0 = [[b + rng.gauss(0, 0.05) for b in base] for _ in range(4)]
    step = [rng.gauss(0, 0.02) for _ in range(3)]
    at1 = [[x + step[j] + rng.gauss(0, 0.005) for j, x in enumerate(p)] for p in at0]
    return at0 + at1


def resting(rng):
    d = 10 ** rng.uniform(-9, -5)
    p0 = (rng.uniform(0.05, 0.4), rng.uniform(0.05, 0.4), d)
    step = (rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1), rng.uniform(-d, d))
    tri0 = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
    tri1 = [(x, y, z + rng.uniform(-d, d)) for x, y, z in tri0]
    p1 = tuple(a + b for a, b in zip(p0, step))
    return [p0] + tri0 + [p1] + tri1


def main():
    args = [a for a in sys.argv[1:] if a != "--resting"]
    if len(args) != 3:
        sys.exit("usage: ccd_random_csv.py N SEED OUT.csv [--resting]")
    n, seed, out = int(args[0]), int(args[1]), args[2]
    make = resting if "--resting" in sys.argv[1:] else broad_phase_like
    rng = random.Random(seed)
    with open(out, "w") as f:
        for _ in range(n):
            for v in make(rng):
                fields = []
                for x in v:
                    q = Fraction(x)
                    fields += [str(q.numerator), str(q.denominator)]
                f.write(",".join(fields) + "\n")


if __name__ == "__main__":
    main()
