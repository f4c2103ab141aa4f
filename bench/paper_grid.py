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
only.

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
import math
import os
import re
import sys
from fractions import Fraction as Fr
from math import comb

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
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
# Exact helpers
# ---------------------------------------------------------------------------


def qmul(p, q):
    a1, b1, c1, d1 = p
    a2, b2, c2, d2 = q
    return (a1 * a2 - b1 * b2 - c1 * c2 - d1 * d2,
            a1 * b2 + b1 * a2 + c1 * d2 - d1 * c2,
            a1 * c2 - b1 * d2 + c1 * a2 + d1 * b2,
            a1 * d2 + b1 * c2 - c1 * b2 + d1 * a2)


def rot_matrix(q):
    """Unnormalised rotation matrix R(q); R(q)/|q|^2 is orthogonal."""
    a, b, c, d = q
    return [[a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
            [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
            [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d]]


def bern_mul(a, b):
    """Exact Bernstein coefficients of the product of two Bernstein polynomials."""
    n, m = len(a) - 1, len(b) - 1
    out = []
    for k in range(n + m + 1):
        s = Fr(0)
        for i in range(max(0, k - m), min(n, k) + 1):
            s += Fr(comb(n, i) * comb(m, k - i), comb(n + m, k)) * a[i] * b[k - i]
        out.append(s)
    return out


def bern_elevate(pts, target):
    pts = [tuple(Fr(x) for x in p) for p in pts]
    while len(pts) - 1 < target:
        n = len(pts) - 1
        new = [pts[0]]
        for i in range(1, n + 1):
            al = Fr(i, n + 1)
            new.append(tuple(al * x + (1 - al) * y for x, y in zip(pts[i - 1], pts[i])))
        new.append(pts[n])
        pts = new
    return pts


def matvec(m, v):
    return tuple(sum(m[i][j] * v[j] for j in range(3)) for i in range(3))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def scale(s, a):
    return tuple(s * x for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def fmt(x):
    x = Fr(x)
    if x.denominator == 1:
        return str(x.numerator)
    return '"%d/%d"' % (x.numerator, x.denominator)


def parse_num(v):
    if isinstance(v, str):
        return Fr(v)
    return Fr(str(v)) if isinstance(v, float) else Fr(v)


# ---------------------------------------------------------------------------
# Construction
# ---------------------------------------------------------------------------


def tilt_matrix():
    r = rot_matrix(Q_TILT)
    n2 = sum(Fr(x) ** 2 for x in Q_TILT)
    return [[Fr(x) / n2 for x in row] for row in r]


def build_motion():
    """(weights w_k, numerator matrices N_k) of the base motion, world frame."""
    T = tilt_matrix()
    qs = [tuple(Fr(x) for x in qmul(Q_TILT, q)) for q in Q_DESIGN]
    comp = [[q[i] for q in qs] for i in range(4)]
    prod = {}
    for i in range(4):
        for j in range(i, 4):
            prod[(i, j)] = prod[(j, i)] = bern_mul(comp[i], comp[j])
    a, b, c, d = 0, 1, 2, 3
    w = [prod[(a, a)][k] + prod[(b, b)][k] + prod[(c, c)][k] + prod[(d, d)][k] for k in range(9)]
    R = []
    for k in range(9):
        P = lambda i, j: prod[(i, j)][k]
        R.append([[P(a, a) + P(b, b) - P(c, c) - P(d, d), 2 * (P(b, c) - P(a, d)), 2 * (P(b, d) + P(a, c))],
                  [2 * (P(b, c) + P(a, d)), P(a, a) - P(b, b) + P(c, c) - P(d, d), 2 * (P(c, d) - P(a, b))],
                  [2 * (P(b, d) - P(a, c)), 2 * (P(c, d) + P(a, b)), P(a, a) - P(b, b) - P(c, c) + P(d, d)]])
    guide = [matvec(T, p) for p in bern_elevate(PATH, 8)]
    N = [[R[k][i] + [w[k] * guide[k][i]] for i in range(3)] for k in range(9)]
    return w, N


def affine_control_points(w, N, shift):
    out = []
    for k in range(len(w)):
        if w[k] <= 0:
            raise SystemExit("weight w_%d = %s is not positive" % (k, w[k]))
        out.append([[N[k][i][j] / w[k] + (shift[i] if j == 3 else 0) for j in range(4)] for i in range(3)])
    return out


def grid(n, place):
    """n x n sub-squares of the centred unit square, counter-clockwise, as
    dict (i, j) -> polygon; `place` maps (u, v) to a 3D point."""
    coord = [Fr(k, n) * SIDE - HALF for k in range(n + 1)]
    return {(i, j): [place(coord[i], coord[j]), place(coord[i + 1], coord[j]),
                     place(coord[i + 1], coord[j + 1]), place(coord[i], coord[j + 1])]
            for j in range(n) for i in range(n)}


def squares():
    T = tilt_matrix()
    fixed_place = lambda u, v: matvec(T, (Fr(0), u, v))
    moving_place = lambda u, v: (u, v, Fr(0))
    return fixed_place, moving_place


# ---------------------------------------------------------------------------
# Writing
# ---------------------------------------------------------------------------


def pt(p):
    return "[" + ", ".join(fmt(x) for x in p) + "]"


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
# Float geometry for the self-checks
# ---------------------------------------------------------------------------


def fsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def fdot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def fcross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def fnorm(a):
    return math.sqrt(fdot(a, a))


def seg_seg_dist(p1, q1, p2, q2):
    """Distance between segments [p1,q1] and [p2,q2] (Ericson, RTCD 5.1.9)."""
    d1, d2, r = fsub(q1, p1), fsub(q2, p2), fsub(p1, p2)
    a, e, f = fdot(d1, d1), fdot(d2, d2), fdot(d2, r)
    c, b = fdot(d1, r), fdot(d1, d2)
    denom = a * e - b * b
    s = min(1.0, max(0.0, (b * f - c * e) / denom)) if denom > 1e-300 * a * e + 1e-300 else 0.0
    t = (b * s + f) / e
    if t < 0.0:
        t, s = 0.0, min(1.0, max(0.0, -c / a))
    elif t > 1.0:
        t, s = 1.0, min(1.0, max(0.0, (b - c) / a))
    c1 = (p1[0] + d1[0] * s, p1[1] + d1[1] * s, p1[2] + d1[2] * s)
    c2 = (p2[0] + d2[0] * t, p2[1] + d2[1] * t, p2[2] + d2[2] * t)
    return fnorm(fsub(c1, c2))


class FPoly:
    def __init__(self, verts):
        self.v = verts
        n = (0.0, 0.0, 0.0)
        for i in range(len(verts)):  # Newell normal
            a, b = verts[i], verts[(i + 1) % len(verts)]
            n = (n[0] + (a[1] - b[1]) * (a[2] + b[2]),
                 n[1] + (a[2] - b[2]) * (a[0] + b[0]),
                 n[2] + (a[0] - b[0]) * (a[1] + b[1]))
        ln = fnorm(n)
        self.n = (n[0] / ln, n[1] / ln, n[2] / ln)
        self.off = fdot(self.n, verts[0])

    def inside(self, x):
        m = len(self.v)
        for i in range(m):
            a, b = self.v[i], self.v[(i + 1) % m]
            if fdot(fcross(fsub(b, a), fsub(x, a)), self.n) < 0.0:
                return False
        return True

    def point_dist(self, x):
        s = fdot(self.n, x) - self.off
        proj = (x[0] - s * self.n[0], x[1] - s * self.n[1], x[2] - s * self.n[2])
        return abs(s) if self.inside(proj) else None

    def segment_hits(self, p, q):
        sp, sq = fdot(self.n, p) - self.off, fdot(self.n, q) - self.off
        if (sp > 0 and sq > 0) or (sp < 0 and sq < 0) or sp == sq:
            return False
        lam = sp / (sp - sq)
        x = (p[0] + lam * (q[0] - p[0]), p[1] + lam * (q[1] - p[1]), p[2] + lam * (q[2] - p[2]))
        return self.inside(x)


def poly_dist(P, F):
    """Distance between two convex planar polygons in 3D (0 if they meet)."""
    for A, B in ((P, F), (F, P)):
        m = len(A.v)
        for i in range(m):
            if B.segment_hits(A.v[i], A.v[(i + 1) % m]):
                return 0.0
    best = float("inf")
    for A, B in ((P, F), (F, P)):
        for x in A.v:
            d = B.point_dist(x)
            if d is not None and d < best:
                best = d
    mp, mf = len(P.v), len(F.v)
    for i in range(mp):
        for j in range(mf):
            d = seg_seg_dist(P.v[i], P.v[(i + 1) % mp], F.v[j], F.v[(j + 1) % mf])
            best = min(best, d)
    return best


def eval_motion(cps, ws, t):
    n = len(cps) - 1
    B = [comb(n, i) * t ** i * (1 - t) ** (n - i) for i in range(n + 1)]
    den = sum(B[k] * ws[k] for k in range(n + 1))
    return [[sum(B[k] * ws[k] * cps[k][i][j] for k in range(n + 1)) / den for j in range(4)] for i in range(3)]


def apply(M, x):
    return tuple(M[i][0] * x[0] + M[i][1] * x[1] + M[i][2] * x[2] + M[i][3] for i in range(3))


def rigidity_error(cps_f, ws_f):
    err, min_det = 0.0, float("inf")
    for s in range(SAMPLES):
        A = [row[:3] for row in eval_motion(cps_f, ws_f, s / (SAMPLES - 1))]
        for i in range(3):
            for j in range(3):
                err = max(err, abs(sum(A[k][i] * A[k][j] for k in range(3)) - (1.0 if i == j else 0.0)))
        det = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1])
               - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
               + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]))
        min_det = min(min_det, det)
    return err, min_det


def exact_edge_through_interior(moving_world, fixed):
    nrm = cross(sub(fixed[1], fixed[0]), sub(fixed[2], fixed[0]))
    m = len(moving_world)
    for i in range(m):
        p, q = moving_world[i], moving_world[(i + 1) % m]
        sp, sq = dot(nrm, sub(p, fixed[0])), dot(nrm, sub(q, fixed[0]))
        if sp * sq >= 0:
            continue
        x = add(p, scale(sp / (sp - sq), sub(q, p)))
        k = len(fixed)
        if all(dot(cross(sub(fixed[(j + 1) % k], fixed[j]), sub(x, fixed[j])), nrm) > 0 for j in range(k)):
            return i, x
    return None


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

    w, N = build_motion()
    fixed_place, moving_place = squares()
    fixed_sq = [fixed_place(u, v) for (u, v) in ((-HALF, -HALF), (HALF, -HALF), (HALF, HALF), (-HALF, HALF))]
    moving_sq = [moving_place(u, v) for (u, v) in ((-HALF, -HALF), (HALF, -HALF), (HALF, HALF), (-HALF, HALF))]
    F = FPoly([tuple(float(x) for x in p) for p in fixed_sq])
    P_loc = [tuple(float(x) for x in p) for p in moving_sq]
    T = tilt_matrix()
    ok = True

    # Per variant: motion, float checks on the whole squares.
    motions, variant_info = {}, {}
    for variant, sz in VARIANTS:
        shift = matvec(T, (Fr(0), Fr(0), sz))
        cps = affine_control_points(w, N, shift)
        motions[variant] = cps
        cps_f = [[[float(x) for x in row] for row in m] for m in cps]
        ws_f = [float(x) for x in w]
        err, min_det = rigidity_error(cps_f, ws_f)
        ds = []
        for s in range(SAMPLES):
            M = eval_motion(cps_f, ws_f, s / (SAMPLES - 1))
            ds.append(poly_dist(FPoly([apply(M, x) for x in P_loc]), F))
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
            runs = []
            for s in zero:
                if runs and s == runs[-1][1] + 1:
                    runs[-1][1] = s
                else:
                    runs.append([s, s])
            if not runs or max(b - a for a, b in runs) < 20:
                print("  FAIL: no run of interpenetrating samples")
                ok = False
            else:
                a, b = max(runs, key=lambda r: r[1] - r[0])
                info["interpenetration_t"] = [round(a / (SAMPLES - 1), 6), round(b / (SAMPLES - 1), 6)]
                tm = Fr(round((a + b) / 2), SAMPLES - 1)
                Me = eval_motion(cps, w, tm)
                wit = exact_edge_through_interior([apply(Me, p) for p in moving_sq], fixed_sq)
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
                    mot = b["motion"]
                    cps_r = [[[parse_num(x) for x in row] for row in m] for m in mot["control_points"]]
                    ws_r = [parse_num(x) for x in mot["weights"]]
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
