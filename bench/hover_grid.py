#!/usr/bin/env python3
"""A flat worst case for sphere hierarchies: two n x n grids of unit size, the
moving one sliding over the fixed one, parallel to it, 1/1000 above it at
the lowest point of a degree-2 path (epsilon 1/10000).  Every moving cell is
within 1/1000 of fixed cells for much of the motion, far below the cells'
size, so bounding spheres cannot separate them; the slab test of flat nodes
(proofs/hierarchy.md section 1b) can.  Exact decimals; standard library.

Usage: python3 bench/hover_grid.py OUT.json [n]   (default n = 40)
Expected verdict: safe.
"""
import json
import sys


def grid(n):
    polys = []
    for i in range(n):
        for j in range(n):
            polys.append([[f"{i}/{n}", f"{j}/{n}", 0], [f"{i + 1}/{n}", f"{j}/{n}", 0],
                          [f"{i + 1}/{n}", f"{j + 1}/{n}", 0], [f"{i}/{n}", f"{j + 1}/{n}", 0]])
    return polys


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 40
    # z(t) = 0.01 (1-t)^2 - 2 * 0.008 t (1-t) + 0.01 t^2: lowest 0.001 at t = 1/2.
    scene = {
        "format": "tmcert-scene/1",
        "epsilon": "1/10000",
        "bodies": [
            {"name": "fixed", "polygons": grid(n)},
            {"name": "moving", "polygons": grid(n),
             "motion": {"type": "rational_bezier", "control_points": [
                 [[1, 0, 0, "-1/2"], [0, 1, 0, "1/4"], [0, 0, 1, "1/100"]],
                 [[1, 0, 0, 0], [0, 1, 0, "1/4"], [0, 0, 1, "-8/1000"]],
                 [[1, 0, 0, "1/2"], [0, 1, 0, "1/4"], [0, 0, 1, "1/100"]]]}}],
    }
    with open(out, "w") as f:
        json.dump(scene, f)


if __name__ == "__main__":
    main()
