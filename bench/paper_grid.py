#!/usr/bin/env python3
"""Scenes for the asymptotic experiment of Schroecker & Weber, Section 7.2.

"Guaranteed Collision Detection With Toleranced Motions", Section 7.2
("Experiments on asymptotic behavior"): two unit squares, each subdivided
into n x n sub-squares, one fixed and one moving by a rational rigid motion
of degree eight, in three variants that differ only by a constant
translation (collision, near-collision, "clear" no-collision), with two mass
strategies (one global mass distribution for the whole moving surface, or an
individual one per moving sub-square).

Usage:
    python3 bench/paper_grid.py [OUTDIR] [n ...]

OUTDIR defaults to build/paper_grid (under the repository root), the n list
to 1 2 ... 10.  For every n it writes six tmcert-scene/1 files

    nNN-global-{collision,near,clear}.json
        bodies "fixed" and "moving", each with the n^2 sub-squares as
        polygons (vertices shared exactly between neighbours); the moving
        body has no "mass", so the tool's default applies (its vertices with
        equal weights plus two points off its plane, SCENE_FORMAT.md): the
        paper's global mass distribution.  One check [moving, fixed].
    nNN-individual-{collision,near,clear}.json
        the same geometry and motion, but every moving sub-square is its own
        body "m_I_J" (default mass: its own 4 vertices plus two points off
        its plane, i.e. an individual metric per sub-square) with a check
        [m_I_J, fixed] each: n^2 checks.

and a side file paper_grid.json with the construction parameters, the
sampled minimum distances (per n, strategy and variant) and the list of
scenes.  Scene files of this naming pattern already in OUTDIR are removed
first, so that the directory holds exactly the requested n.  All scene data
is exact (fractions.Fraction); the output is deterministic.  Standard library
only; the motion construction and the float checks are shared with
examples/generate_paper_examples.py in examples/rational_motion.py.

Geometry and motion (all exact)
-------------------------------
Both squares have side 1 and are centred at the origin of their frames.  The
moving square lies in the plane z = 0 of its own frame; the fixed square lies
in the plane x = 0 of a design frame that is rotated into the world by the
rational rotation of the quaternion (4, 2, 1, 2) (a general axis, so that the
axis-aligned swept boxes of the two bodies overlap in every variant).  The motion is built as in
examples/generate_paper_examples.py (the paper's Section 7.1 examples):
x -> (R(q(t)) x + d(t)) / |q(t)|^2 with a degree-4 quaternion polynomial q
(5 rational control quaternions, Bernstein form) and a degree-8 translation
d(t) = |q(t)|^2 p(t), p the degree-8 elevation of a quadratic guide path
(the octagon example's path scaled by 1/2 for the unit square).  The scene
stores the affine control points N_k / w_k and the weights w_k = |q|^2
coefficients (all positive).  The variants shift the translation column of
every control point by a constant s along the design z axis (an exact world
translation): 0 (collision: the squares pass through each other), 4/5
(near: sampled closest approach about 4 % of the side, no contact) and 13/10
(clear: half a side farther).

epsilon = 1/100 (1 % of the side), max_depth = 40.

Self-checks (exit status 1 if one fails):
  * exact: weights positive, the scenes re-read from disk reproduce the
    control points and weights exactly, the collision variant has an exact
    witness (a rational t at which an edge of the moving square crosses the
    interior of the fixed square);
  * float, 2001 samples of t in [0, 1]: the motion is rigid
    (|A^T A - I| < 1e-9, det A > 0); the minimum distance between the two
    squares (the union of the sub-squares of each body is the whole square)
    is 0 with a run of interpenetrating samples for the collision variant,
    in (0, 0.1) for near and in [0.4, 0.7] for clear.
"""

import json
import os
import re
import sys
from fractions import Fraction as Fr

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The exact motion and the float checks are shared with the Section 7.1
# generator: import examples/rational_motion.py from the repository's examples/.
sys.path.insert(0, os.path.join(ROOT, "examples"))
from rational_motion import (FPoly, affine_control_points, build_motion,  # noqa: E402
                             exact_witness, float_motion, fmt, matvec, parse_motion, pt,
                             rigidity_error, runs_of, sample_distances, tilt_matrix)

DEFAULT_OUT = os.path.join(ROOT, "build", "paper_grid")
DEFAULT_NS = list(range(1, 11))

# ---------------------------------------------------------------------------
# Parameters (all exact)
# ---------------------------------------------------------------------------

SIDE = Fr(1)
HALF = SIDE / 2
# World placement of the whole design: the rotation of the quaternion
# (4, 2, 1, 2), |q|^2 = 25.  A general axis, so that the world-axis-aligned
# boxes around everything the bodies sweep overlap in all three variants: with
# a rotation about z (as in examples/) the clear variant would be decided by
# the verifier's swept-box prefilter with no subdivision at all, and would
# measure nothing of the paper's algorithm.
Q_TILT = (4, 2, 1, 2)
Q_DESIGN = [(4, 0, 0, 0),          # control quaternions of q(t), design frame
            (4, 1, -1, 1),
            (4, 1, 1, 2),
            (4, 2, 1, 0),
            (4, 1, 2, -1)]
PATH = [(Fr(-5, 4), Fr(-1, 4), Fr(0)),   # quadratic guide path, design frame
        (Fr(0), Fr(1, 2), Fr(0)),
        (Fr(5, 4), Fr(0), Fr(0))]
VARIANTS = [("collision", Fr(0)), ("near", Fr(4, 5)), ("clear", Fr(13, 10))]
EPSILON = Fr(1, 100)
MAX_DEPTH = 40
SAMPLES = 2001

SCENE_NAME = re.compile(r"^n\d+-(global|individual)-(collision|near|clear)\.json$")

# ---------------------------------------------------------------------------
# Construction
# ---------------------------------------------------------------------------


def grid(n, place):
    """n x n sub-squares of the centred unit square, counter-clockwise, as
    dict (i, j) -> polygon; `place` maps (u, v) to a 3D point."""
    coord = [Fr(k, n) * SIDE - HALF for k in range(n + 1)]
    return {(i, j): [place(coord[i], coord[j]), place(coord[i + 1], coord[j]),
                     place(coord[i + 1], coord[j + 1]), place(coord[i], coord[j + 1])]
            for j in range(n) for i in range(n)}


def squares():
    T = tilt_matrix(Q_TILT)
    fixed_place = lambda u, v: matvec(T, (Fr(0), u, v))
    moving_place = lambda u, v: (u, v, Fr(0))
    return fixed_place, moving_place


# ---------------------------------------------------------------------------
# Writing
# ---------------------------------------------------------------------------


def polygons_lines(polys, indent):
    out = []
    for k, poly in enumerate(polys):
        sep = "," if k + 1 < len(polys) else ""
        out.append(indent + "[" + ", ".join(pt(p) for p in poly) + "]" + sep)
    return out


def motion_lines(cps, w, indent):
    return [indent + '"motion": {',
            indent + '  "type": "rational_bezier",',
            indent + '  "interval": [0, 1],',
            indent + '  "control_points": [',
            ",\n".join(indent + "    [" + ", ".join(pt(row) for row in m) + "]" for m in cps),
            indent + "  ],",
            indent + '  "weights": [' + ", ".join(fmt(x) for x in w) + "] }"]


def scene_text(n, strategy, variant, fixed, moving, cps, w):
    keys = sorted(fixed.keys(), key=lambda ij: (ij[1], ij[0]))
    lines = ["{",
             '  "format": "tmcert-scene/1",',
             '  "comment": "bench/paper_grid.py: Schroecker & Weber Sec. 7.2, n = %d, %s mass, %s variant; '
             'two unit squares of %d x %d sub-squares",' % (n, strategy, variant, n, n),
             '  "epsilon": "%s",' % EPSILON,
             '  "max_depth": %d,' % MAX_DEPTH,
             '  "bodies": [',
             '    { "name": "fixed",',
             '      "polygons": [']
    lines += polygons_lines([fixed[k] for k in keys], "        ")
    lines.append("      ] },")
    if strategy == "global":
        lines += ['    { "name": "moving",',
                  '      "polygons": [']
        lines += polygons_lines([moving[k] for k in keys], "        ")
        lines.append("      ],")
        lines += motion_lines(cps, w, "      ")
        lines[-1] += " }"
        lines.append("  ],")
        lines.append('  "checks": [ ["moving", "fixed"] ]')
        names = ["moving"]
    else:
        names = []
        for idx, (i, j) in enumerate(keys):
            name = "m_%d_%d" % (i, j)
            names.append(name)
            lines.append('    { "name": "%s",' % name)
            lines.append('      "polygons": [ [' + ", ".join(pt(p) for p in moving[(i, j)]) + "] ],")
            lines += motion_lines(cps, w, "      ")
            lines[-1] += " }" + ("," if idx + 1 < len(keys) else "")
        lines.append("  ],")
        lines.append('  "checks": [')
        lines.append(",\n".join('    ["%s", "fixed"]' % name for name in names))
        lines.append("  ]")
    lines.append("}")
    return "\n".join(lines) + "\n", names


# ---------------------------------------------------------------------------
# Main
# ---------------------------------------------------------------------------


def parse_args(argv):
    out, ns = DEFAULT_OUT, []
    args = list(argv)
    if args and not re.fullmatch(r"\d+", args[0]):
        out = args.pop(0)
    for a in args:
        if not re.fullmatch(r"\d+", a) or int(a) < 1:
            raise SystemExit("usage: paper_grid.py [OUTDIR] [n ...]  (n: positive integers), got %r" % a)
        ns.append(int(a))
    return out, sorted(set(ns)) or DEFAULT_NS


def main(argv):
    out_dir, ns = parse_args(argv)
    os.makedirs(out_dir, exist_ok=True)
    for name in sorted(os.listdir(out_dir)):
        if SCENE_NAME.match(name):
            os.remove(os.path.join(out_dir, name))

    _, _, w, N = build_motion(Q_TILT, Q_DESIGN, PATH)
    fixed_place, moving_place = squares()
    fixed_sq = [fixed_place(u, v) for (u, v) in ((-HALF, -HALF), (HALF, -HALF), (HALF, HALF), (-HALF, HALF))]
    moving_sq = [moving_place(u, v) for (u, v) in ((-HALF, -HALF), (HALF, -HALF), (HALF, HALF), (-HALF, HALF))]
    F = FPoly([tuple(float(x) for x in p) for p in fixed_sq])
    P_loc = [tuple(float(x) for x in p) for p in moving_sq]
    T = tilt_matrix(Q_TILT)
    ok = True

    # Per variant: motion, float checks on the whole squares.
    motions, variant_info = {}, {}
    for variant, sz in VARIANTS:
        shift = matvec(T, (Fr(0), Fr(0), sz))
        cps = affine_control_points(w, N, shift)
        motions[variant] = cps
        cps_f, ws_f = float_motion(cps, w)
        err, min_det = rigidity_error(cps_f, ws_f, SAMPLES)
        ds = sample_distances(cps_f, ws_f, P_loc, F, SAMPLES)
        dmin = min(ds)
        at = ds.index(dmin) / (SAMPLES - 1)
        zero = [s for s, d in enumerate(ds) if d == 0.0]
        info = {"shift_z": str(sz), "min_distance": round(dmin, 6), "at_t": round(at, 6),
                "interpenetrating_samples": len(zero)}
        print("%-9s shift %-5s rigid err %.1e, min det %.12f; sampled min distance %.6f (%.1f %% of the side) "
              "at t = %.4f; %d of %d samples interpenetrate"
              % (variant, sz, err, min_det, dmin, 100 * dmin / float(SIDE), at, len(zero), SAMPLES))
        if err > 1e-9 or min_det < 1 - 1e-9:
            print("  FAIL: not the intended rigid motion")
            ok = False
        if variant == "near" and not (0 < dmin < 0.1):
            print("  FAIL: near clearance not in (0, 0.1)")
            ok = False
        if variant == "clear" and not (0.4 <= dmin <= 0.7):
            print("  FAIL: clear clearance not about half a side")
            ok = False
        if variant == "collision":
            runs = runs_of(zero)
            if not runs or max(b - a for a, b in runs) < 20:
                print("  FAIL: no run of interpenetrating samples")
                ok = False
            else:
                a, b = max(runs, key=lambda r: r[1] - r[0])
                info["interpenetration_t"] = [round(a / (SAMPLES - 1), 6), round(b / (SAMPLES - 1), 6)]
                tm, wit = exact_witness(cps, w, a, b, SAMPLES, moving_sq, fixed_sq)
                if wit is None:
                    print("  FAIL: no exact witness at t = %s" % tm)
                    ok = False
                else:
                    info["exact_witness_t"] = str(tm)
                    print("          interpenetration for t in [%.4f, %.4f] (longest run); exact witness: at t = %s "
                          "edge %d of the moving square crosses the interior of the fixed one"
                          % (a / (SAMPLES - 1), b / (SAMPLES - 1), tm, wit[0]))
        variant_info[variant] = info

    scenes = []
    for n in ns:
        fixed = grid(n, fixed_place)
        moving = grid(n, moving_place)
        for strategy in ("global", "individual"):
            for variant, _ in VARIANTS:
                fname = "n%02d-%s-%s.json" % (n, strategy, variant)
                path = os.path.join(out_dir, fname)
                text, names = scene_text(n, strategy, variant, fixed, moving, motions[variant], w)
                with open(path, "w", newline="\n") as f:
                    f.write(text)
                # Re-read and compare exactly.
                with open(path) as f:
                    doc = json.load(f)
                movers = [b for b in doc["bodies"] if "motion" in b]
                good = len(movers) == len(names)
                for b in movers:
                    cps_r, ws_r = parse_motion(b["motion"])
                    good = good and cps_r == motions[variant] and ws_r == w and all(x > 0 for x in ws_r)
                polys = sum(len(b["polygons"]) for b in movers)
                good = good and polys == n * n and len(doc["bodies"][0]["polygons"]) == n * n
                if not good:
                    print("  FAIL: %s does not round-trip" % fname)
                    ok = False
                scenes.append({"file": fname, "n": n, "strategy": strategy, "variant": variant,
                               "moving_bodies": len(names), "checks": len(doc["checks"]),
                               "polygon_pairs": n ** 4,
                               "sampled_min_distance": variant_info[variant]["min_distance"]})
        print("n = %2d: 6 scenes written" % n)

    side = {"format": "tmcert-paper-grid/1",
            "generator": "bench/paper_grid.py",
            "paper": "Schroecker & Weber, Guaranteed Collision Detection With Toleranced Motions, Sec. 7.2",
            "side": str(SIDE), "epsilon": str(EPSILON), "max_depth": MAX_DEPTH, "samples": SAMPLES,
            "note": "distances are between the two whole squares (each body's sub-squares tile its square "
                    "exactly), sampled in float at t = k/2000; they do not depend on n or the strategy",
            "variants": variant_info, "scenes": scenes}
    with open(os.path.join(out_dir, "paper_grid.json"), "w", newline="\n") as f:
        json.dump(side, f, indent=2, sort_keys=True)
        f.write("\n")
    if not ok:
        print("SELF-CHECK FAILED")
        return 1
    print("%d scenes and paper_grid.json written to %s; all self-checks passed" % (len(scenes), out_dir))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
