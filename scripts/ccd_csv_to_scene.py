#!/usr/bin/env python3
"""Turn continuous-collision query files into one tmcert scene.

Reads the rational CSV format of the large continuous-collision benchmark
(Wang et al. 2021, "A Large Scale Benchmark and an Inclusion-Based Algorithm
for Continuous Collision Detection"): every 8 lines are one query, each line
one vertex as `x_num,x_den,y_num,y_den,z_num,z_den[,truth]`, in the order

    vertex-face: p(0), f0(0), f1(0), f2(0), p(1), f0(1), f1(1), f2(1)
    edge-edge:   a0(0), a1(0), b0(0), b1(0),  a0(1), a1(1), b0(1), b1(1)

(the order of the benchmark's vertexFaceCCD / edgeEdgeCCD arguments). The
kind comes from --kind, or from a path component `vertex-face` or
`edge-edge`. Every number is kept exactly: tmcert reads "p/q" as the
rational p/q.

Each query becomes two bodies moving linearly per vertex (README, "Linear
per-vertex motion"): the canonical point, segment or triangle mapped by
[v1 - v0, v2 - v0, 0 | v0] at t = 0 and at t = 1, and one check between
them. The scene's epsilon is --epsilon, or --epsilon-fraction (default
1e-6) times the largest diagonal of one query's box (the box around its 8
vertices): the queries are independent, so their spread across the set is
not a size that matters to any of them.

Writes the scene (-o) and, with --truth-out, a JSON list with one entry per
check: {"check": i, "file": ..., "query": k, "kind": "vf"|"ee",
"truth": true|false|null} (null when the file carries no ground truth and
no --truth file gives it). scripts/ccd_compare.py scores a tmcert result
against it.

Usage:
  ccd_csv_to_scene.py [--kind vf|ee] [--truth mma_bool.json] [--skip K] [--limit N]
                      [--epsilon E | --epsilon-fraction F]
                      -o scene.json [--truth-out truth.json] FILE.csv...
"""
import argparse
import json
import math
import sys
from fractions import Fraction


def fail(message):
    print(f"ccd_csv_to_scene: {message}", file=sys.stderr)
    sys.exit(3)


def rational(num, den, where):
    try:
        n, d = int(num.strip()), int(den.strip())
    except ValueError:
        fail(f"{where}: '{num.strip()}/{den.strip()}' is not a pair of integers")
    if d == 0:
        fail(f"{where}: zero denominator")
    return Fraction(n, d)


def read_queries(path):
    """The queries of one file: a list of (8 vertices, truth or None)."""
    queries = []
    vertices, truth = [], None
    with open(path) as f:
        lines = [(i + 1, l.strip()) for i, l in enumerate(f)]
    lines = [(n, l) for n, l in lines if l and not l.startswith("#")]
    if len(lines) % 8 != 0:
        fail(f"{path}: {len(lines)} data lines, not a multiple of 8")
    for number, line in lines:
        items = line.split(",")
        where = f"{path}:{number}"
        if len(items) < 6:
            fail(f"{where}: {len(items)} fields, a vertex needs 6 (x_num,x_den,y_num,y_den,z_num,z_den)")
        vertices.append(tuple(rational(items[2 * j], items[2 * j + 1], where) for j in range(3)))
        if len(items) > 6 and items[6].strip():
            try:
                t = bool(int(items[6]))
            except ValueError:
                fail(f"{where}: ground truth '{items[6].strip()}' is not 0 or 1")
            if truth is not None and t != truth:
                fail(f"{where}: ground truth differs from the query's first line")
            truth = t
        if len(vertices) == 8:
            queries.append((vertices, truth))
            vertices, truth = [], None
    return queries


def kind_of(path, forced):
    if forced:
        return forced
    parts = path.replace("\\", "/").split("/")
    if "vertex-face" in parts:
        return "vf"
    if "edge-edge" in parts:
        return "ee"
    fail(f"{path}: cannot tell vertex-face from edge-edge; give --kind vf or --kind ee")


def text(x):
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def pose(vs):
    """The 3x4 map [v1 - v0, v2 - v0, 0 | v0] (missing columns zero)."""
    rows = []
    for i in range(3):
        cols = [vs[k][i] - vs[0][i] if k < len(vs) else Fraction(0) for k in (1, 2)]
        rows.append([text(cols[0]), text(cols[1]), "0", text(vs[0][i])])
    return rows


CANONICAL = {
    1: {"points": [[0, 0, 0]]},
    2: {"segments": [[[0, 0, 0], [1, 0, 0]]]},
    3: {"polygons": [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]]},
}


def body(name, at0, at1):
    b = {"name": name}
    b.update(CANONICAL[len(at0)])
    b["motion"] = {"type": "rational_bezier", "control_points": [pose(at0), pose(at1)]}
    return b


def decimal_text(x):
    """A short decimal not above x > 0 (an epsilon only needs to be about right)."""
    digits = 6
    e = math.floor(math.log10(x))
    scaled = math.floor(x / 10.0 ** (e - digits + 1))
    value = Fraction(scaled) * Fraction(10) ** (e - digits + 1)
    while value > Fraction(x):
        scaled -= 1
        value = Fraction(scaled) * Fraction(10) ** (e - digits + 1)
    return f"{scaled}e{e - digits + 1}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="+")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--truth-out")
    ap.add_argument("--truth", help="a JSON list of booleans, one per query of the (single) input file")
    ap.add_argument("--kind", choices=["vf", "ee"])
    ap.add_argument("--skip", type=int, default=0, help="leave out the first SKIP queries (with --limit, to split a set)")
    ap.add_argument("--limit", type=int, help="at most this many queries in all")
    group = ap.add_mutually_exclusive_group()
    group.add_argument("--epsilon", help="epsilon in scene units, exactly as tmcert reads it")
    group.add_argument("--epsilon-fraction", type=float, default=1e-6)
    args = ap.parse_args()
    if args.truth and len(args.files) != 1:
        fail("--truth goes with exactly one input file")

    bodies, checks, truths = [], [], []
    size = 0.0  # the largest diagonal of a query's box
    seen = 0    # queries read, skipped ones included
    for path in args.files:
        kind = kind_of(path, args.kind)
        queries = read_queries(path)
        if args.truth:
            with open(args.truth) as f:
                given = json.load(f)
            if not isinstance(given, list) or len(given) != len(queries) or not all(isinstance(g, bool) for g in given):
                fail(f"{args.truth}: expected a list of {len(queries)} booleans")
            queries = [(v, g) for (v, _), g in zip(queries, given)]
        for k, (v, truth) in enumerate(queries):
            seen += 1
            if seen <= args.skip:
                continue
            if args.limit is not None and len(checks) >= args.limit:
                break
            i = len(checks)
            if kind == "vf":
                a0, a1, b0, b1 = v[0:1], v[4:5], v[1:4], v[5:8]
            else:
                a0, a1, b0, b1 = v[0:2], v[4:6], v[2:4], v[6:8]
            na, nb = f"q{i}-{'p' if kind == 'vf' else 'ea'}", f"q{i}-{'f' if kind == 'vf' else 'eb'}"
            bodies += [body(na, a0, a1), body(nb, b0, b1)]
            checks.append([na, nb])
            truths.append({"check": i, "file": path, "query": k, "kind": kind, "truth": truth})
            size = max(size, math.sqrt(sum(float(max(x[c] for x in v) - min(x[c] for x in v)) ** 2 for c in range(3))))
    if not checks:
        fail("no queries read")
    if len(checks) > 100000:
        print(f"ccd_csv_to_scene: warning: {len(checks)} queries; tmcert reads at most 10^7 JSON values "
              "per scene (about 100 000 queries): split the input (--skip and --limit, or fewer files)", file=sys.stderr)

    scene = {"format": "tmcert-scene/1"}
    if args.epsilon:
        scene["epsilon"] = args.epsilon
    else:
        eps = args.epsilon_fraction * size
        if not (eps > 0 and math.isfinite(eps)):
            fail("every query is a single point: give --epsilon")
        scene["epsilon"] = decimal_text(eps)
    scene["bodies"] = bodies
    scene["checks"] = checks
    with open(args.output, "w") as f:
        json.dump(scene, f, separators=(",", ":"))
    if args.truth_out:
        with open(args.truth_out, "w") as f:
            json.dump(truths, f, indent=0)
    print(f"ccd_csv_to_scene: {len(checks)} queries, epsilon {scene['epsilon']} -> {args.output}", file=sys.stderr)


if __name__ == "__main__":
    main()
