"""Shared helpers for the scene generators of Schroecker & Weber, Section 7.

Used by examples/generate_paper_examples.py (Section 7.1, octagons) and
bench/paper_grid.py (Section 7.2, subdivided squares).  Standard library only.

  * exact (fractions.Fraction): quaternion product, rotation matrix R(q),
    Bernstein product and degree elevation, small vector helpers, the
    degree-8 rational rigid motion x -> (R(q(t)) x + d(t)) / |q(t)|^2 built
    from a tilt quaternion, control quaternions and a guide path, and an
    exact collision witness;
  * scene numbers: writing exact numbers as JSON (integers, or "p/q"
    strings) and reading them back;
  * float (self-checks): segment and convex-polygon distances, evaluation of
    a rational Bezier motion, rigidity error, sampled distances.
"""

import math
from fractions import Fraction as Fr
from math import comb

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


# ---------------------------------------------------------------------------
# The rational motion
# ---------------------------------------------------------------------------


def tilt_matrix(q_tilt):
    """The orthogonal matrix R(q_tilt) / |q_tilt|^2, exact."""
    r = rot_matrix(q_tilt)
    n2 = sum(Fr(x) ** 2 for x in q_tilt)
    return [[Fr(x) / n2 for x in row] for row in r]


def build_motion(q_tilt, q_design, path):
    """The motion x -> (R(q(t)) x + d(t)) / |q(t)|^2 in the world frame.

    q(t) has the control quaternions q_tilt * q_design[i] (Bernstein form),
    d(t) = |q(t)|^2 p(t) with p the elevation of the guide path `path` (design
    frame) to the degree of |q|^2, turned into the world by tilt_matrix.
    Returns (quaternion control points, guide control points, weights w_k,
    numerator matrices N_k = [R_k | w_k p_k] (3x4))."""
    T = tilt_matrix(q_tilt)
    qs = [tuple(Fr(x) for x in qmul(q_tilt, q)) for q in q_design]
    # products of quaternion components, degree 2 deg q
    comp = [[q[i] for q in qs] for i in range(4)]
    prod = {}
    for i in range(4):
        for j in range(i, 4):
            prod[(i, j)] = prod[(j, i)] = bern_mul(comp[i], comp[j])
    a, b, c, d = 0, 1, 2, 3
    n_coef = len(prod[(a, a)])
    w = [prod[(a, a)][k] + prod[(b, b)][k] + prod[(c, c)][k] + prod[(d, d)][k]
         for k in range(n_coef)]
    R = []
    for k in range(n_coef):
        P = lambda i, j: prod[(i, j)][k]
        R.append([[P(a, a) + P(b, b) - P(c, c) - P(d, d), 2 * (P(b, c) - P(a, d)), 2 * (P(b, d) + P(a, c))],
                  [2 * (P(b, c) + P(a, d)), P(a, a) - P(b, b) + P(c, c) - P(d, d), 2 * (P(c, d) - P(a, b))],
                  [2 * (P(b, d) - P(a, c)), 2 * (P(c, d) + P(a, b)), P(a, a) - P(b, b) - P(c, c) + P(d, d)]])
    guide = [matvec(T, p) for p in bern_elevate(path, n_coef - 1)]
    dvec = [scale(w[k], guide[k]) for k in range(n_coef)]
    N = [[R[k][i] + [dvec[k][i]] for i in range(3)] for k in range(n_coef)]
    return qs, guide, w, N


def affine_control_points(w, N, shift):
    """P_k = N_k / w_k with the translation column shifted by `shift`."""
    out = []
    for k in range(len(w)):
        if w[k] <= 0:
            raise SystemExit("weight w_%d = %s is not positive" % (k, w[k]))
        out.append([[N[k][i][j] / w[k] + (shift[i] if j == 3 else 0) for j in range(4)]
                    for i in range(3)])
    return out


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
# Scene numbers
# ---------------------------------------------------------------------------


def fmt(x):
    """An exact number as JSON: an integer, or the string "p/q"."""
    x = Fr(x)
    if x.denominator == 1:
        return str(x.numerator)
    return '"%d/%d"' % (x.numerator, x.denominator)


def pt(p):
    return "[" + ", ".join(fmt(x) for x in p) + "]"


def parse_num(v):
    if isinstance(v, str):
        return Fr(v)
    return Fr(str(v)) if isinstance(v, float) else Fr(v)


def parse_motion(mot):
    """Exact (control points, weights) of a scene's "motion" object."""
    cps = [[[parse_num(x) for x in row] for row in m] for m in mot["control_points"]]
    ws = [parse_num(x) for x in mot["weights"]]
    return cps, ws


def float_motion(cps, ws):
    """Float copies of exact control points and weights."""
    return [[[float(x) for x in row] for row in m] for m in cps], [float(x) for x in ws]


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


def eval_motion(cps, ws, t):
    """Rational Bezier in R^12 (3x4 matrix) at t; float or exact alike."""
    n = len(cps) - 1
    B = bernstein_basis(n, t)
    den = sum(B[k] * ws[k] for k in range(n + 1))
    return [[sum(B[k] * ws[k] * cps[k][i][j] for k in range(n + 1)) / den for j in range(4)]
            for i in range(3)]


def apply(M, x):
    return tuple(M[i][0] * x[0] + M[i][1] * x[1] + M[i][2] * x[2] + M[i][3] for i in range(3))


def rigidity_error(cps_f, ws_f, samples):
    """(max |A^T A - I|, min det A) of the linear part A over t = s/(samples-1)."""
    err, min_det = 0.0, float("inf")
    for s in range(samples):
        A = [row[:3] for row in eval_motion(cps_f, ws_f, s / (samples - 1))]
        for i in range(3):
            for j in range(3):
                err = max(err, abs(sum(A[k][i] * A[k][j] for k in range(3)) - (1.0 if i == j else 0.0)))
        det = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1])
               - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
               + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]))
        min_det = min(min_det, det)
    return err, min_det


def sample_distances(cps_f, ws_f, P_loc, F, samples):
    """poly_dist of the moved polygon P_loc and FPoly F at t = s/(samples-1)."""
    ds = []
    for s in range(samples):
        M = eval_motion(cps_f, ws_f, s / (samples - 1))
        ds.append(poly_dist(FPoly([apply(M, x) for x in P_loc]), F))
    return ds


def exact_witness(cps, ws, first, last, samples, moving, fixed):
    """Exact check in the middle of the sample run [first, last] (t = s/(samples-1)).

    Returns (the rational t, exact_edge_through_interior of the polygon
    `moving` placed by the exact motion (cps, ws) and the polygon `fixed`)."""
    tm = Fr(round((first + last) / 2), samples - 1)
    M = eval_motion(cps, ws, tm)
    return tm, exact_edge_through_interior([apply(M, p) for p in moving], fixed)


def runs_of(indices):
    """Maximal runs [first, last] of consecutive integers in a sorted list."""
    runs = []
    for s in indices:
        if runs and s == runs[-1][1] + 1:
            runs[-1][1] = s
        else:
            runs.append([s, s])
    return runs
