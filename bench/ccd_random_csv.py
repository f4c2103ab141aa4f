#!/usr/bin/env python3
"""Writes N random vertex-face queries in the benchmark's rational CSV
format (scripts/ccd_csv_to_scene.py), for load tests of the whole command
line on large files: each query is a point and a triangle near a random
spot of [-1, 1]^3 (spread 0.05), moving by a common random step (0.02) with
per-vertex noise (0.005); coordinates are doubles written exactly, as in
the benchmark's simulation data. No ground truth (the truth column is
left out).

  bench/ccd_random_csv.py N SEED OUT.csv
"""
import random
import sys
from fractions import Fraction


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: ccd_random_csv.py N SEED OUT.csv")
    n, seed, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    rng = random.Random(seed)
    with open(out, "w") as f:
        for _ in range(n):
            base = [rng.uniform(-1, 1) for _ in range(3)]
            at0 = [[b + rng.gauss(0, 0.05) for b in base] for _ in range(4)]
            step = [rng.gauss(0, 0.02) for _ in range(3)]
            at1 = [[x + step[j] + rng.gauss(0, 0.005) for j, x in enumerate(p)] for p in at0]
            for p in at0 + at1:
                fields = []
                for x in p:
                    q = Fraction(x)
                    fields += [str(q.numerator), str(q.denominator)]
                f.write(",".join(fields) + "\n")


if __name__ == "__main__":
    main()
