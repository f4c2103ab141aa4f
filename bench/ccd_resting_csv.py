#!/usr/bin/env python3
"""Writes N vertex-face queries of a point resting near a triangle, in the
benchmark's rational CSV format (scripts/ccd_csv_to_scene.py): the
triangle (0,0,0), (1,0,0), (0,1,0) tilts slightly (each vertex's height
moves by up to d), the point starts at height d above it and slides by up
to 0.1 sideways and up to d in height, with d log-uniform in [1e-9, 1e-5].
Such pairs come within 1e-6 of contact over long stretches of the motion,
the stress case of an epsilon-driven subdivision (bench/README.md, "Bodies
resting within epsilon"). Coordinates are doubles written exactly; no
ground truth.

  bench/ccd_resting_csv.py N SEED OUT.csv
"""
import random
import sys
from fractions import Fraction


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: ccd_resting_csv.py N SEED OUT.csv")
    n, seed, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    rng = random.Random(seed)
    with open(out, "w") as f:
        for _ in range(n):
            d = 10 ** rng.uniform(-9, -5)
            p0 = (rng.uniform(0.05, 0.4), rng.uniform(0.05, 0.4), d)
            step = (rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1), rng.uniform(-d, d))
            tri0 = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
            tri1 = [(x, y, z + rng.uniform(-d, d)) for x, y, z in tri0]
            p1 = tuple(a + b for a, b in zip(p0, step))
            for v in [p0] + tri0 + [p1] + tri1:
                fields = []
                for x in v:
                    q = Fraction(x)
                    fields += [str(q.numerator), str(q.denominator)]
                f.write(",".join(fields) + "\n")


if __name__ == "__main__":
    main()
