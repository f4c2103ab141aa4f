#!/usr/bin/env python3
"""Generate the single-polygon examples of Schroecker & Weber, Section 7.1.

"Guaranteed Collision Detection With Toleranced Motions", Section 7
("Examples and timings"), first group of examples: one fixed convex octagon F
and one moving convex octagon P under a rational rigid motion of degree eight.
The paper runs two motions that "differ only by a constant translation": one
where P is always near F but never touches it, and one where the two polygons
interfere during a time interval; it also mentions translating P by about half
its diameter away, which makes the no-collision proof cheaper.  This script
writes three tmcert-scene/1 files recreating these situations:

  octagons-near.json       near miss (sampled clearance 5-10 % of the diameter)
  octagons-collision.json  same motion shifted so that P cuts through F
  octagons-clear.json      same motion shifted about half a diameter farther

All scene data is exact (fractions.Fraction); the output is deterministic, so
running `python3 examples/generate_paper_examples.py` regenerates the files
byte-identically.  Standard library only.

Construction of the motion
--------------------------
q(t) is a quaternion polynomial of degree 4 in Bernstein form (5 rational
control quaternions).  With the standard unnormalised rotation matrix R(q)
(R(q)/|q|^2 is orthogonal) and a translation polynomial d(t) of degree 8, the
motion is  x -> (R(q(t)) x + d(t)) / |q(t)|^2.  Its homogeneous form is the
numerator N(t) = [R(q(t)) | d(t)] (3x4, entries of degree 8) with weight
w(t) = |q(t)|^2 (degree 8).  The Bernstein coefficients of R(q(t)) and w(t) are
computed exactly with the product formula
  (sum a_i B_i^n)(sum b_j B_j^m)
      = sum_k [sum_{i+j=k} C(n,i) C(m,j) / C(n+m,k) a_i b_j] B_k^{n+m}.
d(t) has the Bernstein coefficients d_k = w_k p_k, where p_0..p_8 is the
degree-8 elevation of a low-degree (quadratic) guide path; hence the
translation columns of the affine control points are exactly the p_k.
The scene stores the affine control points P_k = N_k / w_k and weights w_k
(all verified > 0).

The three scenes differ only by a constant translation s (d -> d + s w, i.e.
the translation column of every affine control point is shifted by s).

Self-checks (the script exits non-zero if one fails):
  * exact: all weights positive; the polygons are planar, convex and rational;
    the collision scene has an exact witness (a rational t at which an edge of
    P crosses the interior of F);
  * float, on 2001 samples of [0,1]: the motion evaluated from the scene file
    (re-read from disk) is rigid (|A^T A - I| < 1e-9, det A > 0) and equals
    (R(q) x + d) / |q|^2 evaluated directly from q(t), d(t);
  * float: sampled minimum polygon-polygon distance in the required range for
    each scene, and a run of interpenetrating samples for the collision scene.
"""

import json
import math
import os
import sys
from fractions import Fraction as Fr
from math import comb

HERE = os.path.dirname(os.path.abspath(__file__))

# ---------------------------------------------------------------------------
# Parameters (all exact)
# ---------------------------------------------------------------------------

# Regular-ish octagon of diameter 2 with rational vertices on the unit circle:
# (1,0), (119/169, 120/169) (from the Pythagorean triple 119-120-169, angle
# 45.24 deg), (0,1), ... in counter-clockwise order.
_C, _S = Fr(119, 169), Fr(120, 169)
OCTAGON = [(Fr(1), Fr(0)), (_C, _S), (Fr(0), Fr(1)), (-_S, _C),
           (Fr(-1), Fr(0)), (-_C, -_S), (Fr(0), Fr(-1)), (_S, -_C)]
DIAMETER = 2.0

# Rational rotation used to place the whole design in the world frame:
# quaternion (3,0,0,1), |q|^2 = 10, a rotation about z by atan2(3,4)*2/2 with
# matrix [[4/5,-3/5,0],[3/5,4/5,0],[0,0,1]].
Q_TILT = (3, 0, 0, 1)

# Control quaternions of q(t) in the design frame (degree 4, before tilting).
Q_DESIGN = [(4, 0, 0, 0),
            (4, 1, -1, 1),
            (4, 1, 1, 2),
            (4, 2, 1, 0),
            (4, 1, 2, -1)]

# Quadratic guide path of the translation in the design frame (F lies in the
# plane x = 0 of the design frame, P sweeps over its upper rim).
PATH = [(Fr(-5, 2), Fr(-1, 2), Fr(0)),
        (Fr(0), Fr(1), Fr(0)),
        (Fr(5, 2), Fr(0), Fr(0))]

# Constant translations (design frame, along +z) of the three scenes.
# The base motion (shift 0) cuts P through the middle of F; raising it by
# 29/20 gives the near miss, and one more unit (half the diameter) the clear
# no-collision.  The tilt is about z, so these are world z-translations too.
SHIFTS = {"near": Fr(29, 20), "collision": Fr(0), "clear": Fr(49, 20)}

EPSILON = Fr(1, 50)          # about 1 % of the polygon diameter
MAX_DEPTH = 40
MASS_HEIGHT = Fr(1, 5)       # point over the barycentre of P, 1/10 diameter

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
            j = k - i
            s += Fr(comb(n, i) * comb(m, j), comb(n + m, k)) * a[i] * b[j]
        out.append(s)
    return out


def bern_elevate(pts, target):
    """Degree elevation of Bernstein control points (tuples) to degree target."""
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
    """Return (quaternion control points, translation guide control points (deg 8),
    weights w_k, numerator matrices N_k) for the base motion, world frame."""
    T = tilt_matrix()
    qs = [tuple(Fr(x) for x in qmul(Q_TILT, q)) for q in Q_DESIGN]
    # products of quaternion components, degree 8
    comp = [[q[i] for q in qs] for i in range(4)]
    prod = {}
    for i in range(4):
        for j in range(i, 4):
            prod[(i, j)] = prod[(j, i)] = bern_mul(comp[i], comp[j])
    a, b, c, d = 0, 1, 2, 3
    n_coef = 9
    w = [prod[(a, a)][k] + prod[(b, b)][k] + prod[(c, c)][k] + prod[(d, d)][k]
         for k in range(n_coef)]
    R = []
    for k in range(n_coef):
        P = lambda i, j: prod[(i, j)][k]
        R.append([[P(a, a) + P(b, b) - P(c, c) - P(d, d), 2 * (P(b, c) - P(a, d)), 2 * (P(b, d) + P(a, c))],
                  [2 * (P(b, c) + P(a, d)), P(a, a) - P(b, b) + P(c, c) - P(d, d), 2 * (P(c, d) - P(a, b))],
                  [2 * (P(b, d) - P(a, c)), 2 * (P(c, d) + P(a, b)), P(a, a) - P(b, b) - P(c, c) + P(d, d)]])
    guide = [matvec(T, p) for p in bern_elevate(PATH, 8)]
    dvec = [scale(w[k], guide[k]) for k in range(n_coef)]
    N = [[R[k][i] + [dvec[k][i]] for i in range(3)] for k in range(n_coef)]
    return qs, guide, w, N


def scene_polygons():
    T = tilt_matrix()
    moving = [(u, v, Fr(0)) for (u, v) in OCTAGON]
    fixed = [matvec(T, (Fr(0), u, v)) for (u, v) in OCTAGON]
    return fixed, moving


def affine_control_points(w, N, shift):
    """P_k = N_k / w_k with the translation column shifted by `shift`."""
    out = []
    for k in range(len(w)):
        if w[k] <= 0:
            raise SystemExit("weight w_%d = %s is not positive" % (k, w[k]))
        out.append([[N[k][i][j] / w[k] + (shift[i] if j == 3 else 0) for j in range(4)]
                    for i in range(3)])
    return out


def write_scene(path, fixed, moving, cps, w):
    def pt(p):
        return "[" + ", ".join(fmt(x) for x in p) + "]"

    lines = []
    lines.append("{")
    lines.append('  "format": "tmcert-scene/1",')
    lines.append('  "epsilon": "%s",' % EPSILON)
    lines.append('  "max_depth": %d,' % MAX_DEPTH)
    lines.append('  "bodies": [')
    lines.append('    { "name": "fixed",')
    lines.append('      "polygons": [ [')
    lines.append(",\n".join("        " + pt(p) for p in fixed))
    lines.append("      ] ] },")
    lines.append('    { "name": "moving",')
    lines.append('      "polygons": [ [')
    lines.append(",\n".join("        " + pt(p) for p in moving))
    lines.append("      ] ],")
    bary = scale(Fr(1, len(moving)), tuple(sum(p[i] for p in moving) for i in range(3)))
    mass_pts = list(moving) + [(bary[0], bary[1], bary[2] + MASS_HEIGHT)]
    lines.append('      "mass": {')
    lines.append('        "points": [')
    lines.append(",\n".join("          " + pt(p) for p in mass_pts))
    lines.append("        ],")
    lines.append('        "weights": [' + ", ".join("1" for _ in mass_pts) + "] },")
    lines.append('      "motion": {')
    lines.append('        "type": "rational_bezier",')
    lines.append('        "interval": [0, 1],')
    lines.append('        "control_points": [')
    lines.append(",\n".join("          [" + ", ".join(pt(row) for row in m) + "]" for m in cps))
    lines.append("        ],")
    lines.append('        "weights": [')
    lines.append(",\n".join("          " + fmt(x) for x in w))
    lines.append("        ] } }")
    lines.append("  ],")
    lines.append('  "checks": [ ["moving", "fixed"] ]')
    lines.append("}")
    text = "\n".join(lines) + "\n"
    json.loads(text)  # must be valid JSON
    with open(path, "w", newline="\n") as f:
        f.write(text)


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
        """x (assumed in the plane) inside the convex polygon (closed)."""
        m = len(self.v)
        for i in range(m):
            a, b = self.v[i], self.v[(i + 1) % m]
            if fdot(fcross(fsub(b, a), fsub(x, a)), self.n) < 0.0:
                return False
        return True

    def point_dist(self, x):
        s = fdot(self.n, x) - self.off
        proj = (x[0] - s * self.n[0], x[1] - s * self.n[1], x[2] - s * self.n[2])
        if self.inside(proj):
            return abs(s)
        return None  # the closest point is on the boundary: edge-edge covers it

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
            if d < best:
                best = d
    return best


def bernstein_basis(n, t):
    return [comb(n, i) * t ** i * (1 - t) ** (n - i) for i in range(n + 1)]


def eval_scene_motion(cps, ws, t):
    """Rational Bezier in R^12 from float control points/weights."""
    n = len(cps) - 1
    B = bernstein_basis(n, t)
    den = sum(B[k] * ws[k] for k in range(n + 1))
    return [[sum(B[k] * ws[k] * cps[k][i][j] for k in range(n + 1)) / den for j in range(4)]
            for i in range(3)]


def eval_direct(qs, guide, w, t):
    """(R(q(t)) | d(t)) / |q(t)|^2 straight from the quaternion polynomial."""
    B4 = bernstein_basis(4, t)
    q = [sum(B4[i] * float(qs[i][c]) for i in range(5)) for c in range(4)]
    B8 = bernstein_basis(8, t)
    d = [sum(B8[k] * float(w[k]) * float(guide[k][c]) for k in range(9)) for c in range(3)]
    R = rot_matrix(q)
    n2 = sum(x * x for x in q)
    return [[R[i][j] / n2 for j in range(3)] + [d[i] / n2] for i in range(3)]


def apply(M, x):
    return tuple(M[i][0] * x[0] + M[i][1] * x[1] + M[i][2] * x[2] + M[i][3] for i in range(3))


# ---------------------------------------------------------------------------
# Exact collision witness
# ---------------------------------------------------------------------------


def exact_eval(cps, ws, t):
    n = len(cps) - 1
    B = [comb(n, i) * t ** i * (1 - t) ** (n - i) for i in range(n + 1)]
    den = sum(B[k] * ws[k] for k in range(n + 1))
    return [[sum(B[k] * ws[k] * cps[k][i][j] for k in range(n + 1)) / den for j in range(4)]
            for i in range(3)]


def exact_edge_through_interior(moving_world, fixed):
    """Return (edge index, point) of an edge of P crossing F's open interior."""
    nrm = cross(sub(fixed[1], fixed[0]), sub(fixed[2], fixed[0]))
    m = len(moving_world)
    for i in range(m):
        p, q = moving_world[i], moving_world[(i + 1) % m]
        sp, sq = dot(nrm, sub(p, fixed[0])), dot(nrm, sub(q, fixed[0]))
        if sp * sq >= 0:
            continue
        x = add(p, scale(sp / (sp - sq), sub(q, p)))
        k = len(fixed)
        if all(dot(cross(sub(fixed[(j + 1) % k], fixed[j]), sub(x, fixed[j])), nrm) > 0
               for j in range(k)):
            return i, x
    return None


# ---------------------------------------------------------------------------
# Main
# ---------------------------------------------------------------------------


def exact_polygon_checks(poly):
    n = len(poly)
    nrm = cross(sub(poly[1], poly[0]), sub(poly[2], poly[0]))
    assert any(x != 0 for x in nrm)
    for p in poly:
        assert dot(nrm, sub(p, poly[0])) == 0, "polygon not planar"
    for i in range(n):
        a, b, c = poly[i], poly[(i + 1) % n], poly[(i + 2) % n]
        assert dot(cross(sub(b, a), sub(c, b)), nrm) > 0, "polygon not strictly convex"


def sample_distances(cps_f, ws_f, Pf_loc, F, ns=2001):
    ds = []
    for s in range(ns):
        t = s / (ns - 1)
        M = eval_scene_motion(cps_f, ws_f, t)
        ds.append(poly_dist(FPoly([apply(M, x) for x in Pf_loc]), F))
    return ds


def main():
    fixed, moving = scene_polygons()
    exact_polygon_checks(fixed)
    exact_polygon_checks(moving)
    qs, guide, w, N = build_motion()
    assert all(x > 0 for x in w), "non-positive weight"
    T = tilt_matrix()
    # near: Sec. 7.1 example 1 (always near, no collision); collision: example 2
    # (same motion, constant translation, interference during an interval);
    # clear: the near motion translated half a diameter farther away.
    names = [("near", "octagons-near.json"),
             ("collision", "octagons-collision.json"),
             ("clear", "octagons-clear.json")]
    F = FPoly([tuple(float(x) for x in p) for p in fixed])
    Pf_loc = [tuple(float(x) for x in p) for p in moving]
    ok = True
    for key, fname in names:
        shift = matvec(T, (Fr(0), Fr(0), SHIFTS[key]))
        cps = affine_control_points(w, N, shift)
        path = os.path.join(HERE, fname)
        write_scene(path, fixed, moving, cps, w)
        # --- re-read from disk and check ---
        with open(path) as f:
            doc = json.load(f)
        mot = doc["bodies"][1]["motion"]
        cps_r = [[[parse_num(x) for x in row] for row in m] for m in mot["control_points"]]
        ws_r = [parse_num(x) for x in mot["weights"]]
        assert cps_r == cps and ws_r == w, "round trip mismatch"
        assert all(x > 0 for x in ws_r)
        cps_f = [[[float(x) for x in row] for row in m] for m in cps_r]
        ws_f = [float(x) for x in ws_r]
        shift_f = tuple(float(x) for x in shift)
        err_orth = err_direct = 0.0
        min_det = float("inf")
        for s in range(2001):
            t = s / 2000
            M = eval_scene_motion(cps_f, ws_f, t)
            A = [row[:3] for row in M]
            for i in range(3):
                for j in range(3):
                    v = sum(A[k][i] * A[k][j] for k in range(3)) - (1.0 if i == j else 0.0)
                    err_orth = max(err_orth, abs(v))
            det = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1])
                   - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
                   + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]))
            min_det = min(min_det, det)
            D = eval_direct(qs, guide, w, t)
            for i in range(3):
                for j in range(4):
                    ref = D[i][j] + (shift_f[i] if j == 3 else 0.0)
                    err_direct = max(err_direct, abs(M[i][j] - ref))
        ds = sample_distances(cps_f, ws_f, Pf_loc, F)
        dmin = min(ds)
        imin = ds.index(dmin)
        zero = [s for s, d in enumerate(ds) if d == 0.0]
        # rotation swept: angle between the initial and final orientation
        A0 = [row[:3] for row in eval_scene_motion(cps_f, ws_f, 0.0)]
        A1 = [row[:3] for row in eval_scene_motion(cps_f, ws_f, 1.0)]
        tr = sum(A0[k][i] * A1[k][i] for i in range(3) for k in range(3))
        ang = math.degrees(math.acos(max(-1.0, min(1.0, (tr - 1) / 2))))
        print("%-24s weights in [%.4g, %.4g]; orthogonality err %.2e; min det %.12f; "
              "|scene - direct| %.2e; rotation t=0->1 %.1f deg"
              % (fname, min(ws_f), max(ws_f), err_orth, min_det, err_direct, ang))
        print("%-24s sampled min distance %.6f (= %.4f diameters) at t = %.4f"
              % ("", dmin, dmin / DIAMETER, imin / 2000))
        if err_orth > 1e-9 or err_direct > 1e-9 or min_det < 1 - 1e-9:
            print("  FAIL: motion is not the intended rigid motion")
            ok = False
        if key == "near" and not (0.05 <= dmin / DIAMETER <= 0.10):
            print("  FAIL: near clearance not within 5-10 % of the diameter")
            ok = False
        if key == "clear" and not (0.4 <= dmin / DIAMETER <= 0.6):
            print("  FAIL: clear clearance not about half a diameter")
            ok = False
        if key == "collision":
            if not zero:
                print("  FAIL: no interpenetrating sample")
                ok = False
            else:
                runs = []
                for s in zero:
                    if runs and s == runs[-1][1] + 1:
                        runs[-1][1] = s
                    else:
                        runs.append([s, s])
                longest = max(runs, key=lambda r: r[1] - r[0])
                print("%-24s interpenetrating samples: %d, runs %s (t in [%.4f, %.4f] longest)"
                      % ("", len(zero), [(a / 2000, b / 2000) for a, b in runs],
                         longest[0] / 2000, longest[1] / 2000))
                tm = Fr(round((longest[0] + longest[1]) / 2), 2000)
                Me = exact_eval(cps_r, ws_r, tm)
                pw = [tuple(sum(Me[i][j] * p[j] for j in range(3)) + Me[i][3] for i in range(3))
                      for p in moving]
                wit = exact_edge_through_interior(pw, fixed)
                if wit is None:
                    print("  FAIL: no exact witness at t = %s" % tm)
                    ok = False
                else:
                    print("%-24s exact witness: at t = %s edge %d of P crosses the interior of F"
                          % ("", tm, wit[0]))
                if longest[1] - longest[0] < 20:
                    print("  FAIL: interpenetration interval too short")
                    ok = False
    if not ok:
        print("SELF-CHECK FAILED")
        return 1
    print("all self-checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
