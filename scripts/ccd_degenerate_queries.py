#!/usr/bin/env python3
"""Degenerate continuous-collision query sets, with ground truth from an exact oracle.

Writes vertex-face and edge-edge queries (linear motion of every vertex
over t in [0, 1]) in the rational CSV format of the public CCD benchmark
(`x_num,x_den,y_num,y_den,z_num,z_den,truth`, 8 lines a query; the format
scripts/ccd_csv_to_scene.py reads), one directory per family:

    OUT/<family>/vertex-face/queries.csv
    OUT/<family>/edge-edge/queries.csv
    OUT/<family>/<kind>/first_contact.json   (the oracle's first contact per query)

The families are the cases a hostile tester tries (issue 14): edges sliding
along parallel edges (touching, and 1e-15 apart), a vertex sliding on a
face, along an edge's line, onto a vertex; contacts exactly at t = 0 and
t = 1; tangential grazing (a double root); two roots 1e-13 apart;
coordinates at 1e8 with motions of 1e-6; degenerate triangles (collinear,
a repeated vertex) and zero-length edges; motionless queries; everything in
one plane over the whole motion; edges meeting at their endpoints; random
doubles (exact binary fractions, not round decimals). Each family mixes
planted contacts with misses by 1e-15 and unplanted queries; the truth is
never taken from the construction but computed by the oracle.

The oracle decides exactly, in Python Fractions, whether the closed
primitives share a point at some t in [0, 1], and the earliest such t. It
uses the polynomial toolkit of tests/regression/exact_oracle.py (Sturm
isolation, signs at algebraic roots by gcd and bisection) and no tmcert
code. Candidates for the first contact T: t = 0, and else T > 0 is a time
where the contact starts, so (Lemma 6 of proofs/exact-resolution.md, here
re-argued for a point or segment against a triangle or segment) either the
coplanarity polynomial D vanishes at T (D not identically 0: T is one of
its roots), or D = 0 throughout and an endpoint reaches the other primitive's
boundary at T: T is a root of the gcd of the components of (v - e0) x (e1 -
e0) for a vertex v and an edge (e0, e1) of the other, or, when those vanish
identically (v on the edge's line throughout), of the components of v - e0 or
v - e1. All candidates are the distinct roots in [0, 1] of one square-free
product, taken in increasing order; at each the static test is exact:

- point in closed triangle: D = 0, and with a nonzero normal n all three
  edge orientations (e_k x (v - q_k)) . n >= 0; a collapsed triangle (n = 0)
  is the union of its three edges;
- point on closed segment: a segment reduced to a point needs v on it;
  else (v - e0) x d = 0, (v - e0) . d >= 0, (v - e1) . d <= 0, d = e1 - e0;
- two closed segments: D = 0; with non-parallel directions, the ends of
  each are on opposite sides of (or on) the other's line; parallel or
  degenerate: an endpoint of one on the other.

Usage:
  ccd_degenerate_queries.py OUT [--n N] [--seed S] [--families a,b,...]
  ccd_degenerate_queries.py --list
  ccd_degenerate_queries.py --check TMCERT [--n N] [--seed S] [--kernel K ...]

--check writes a sample to a temporary directory, converts all its files
into one scene with ccd_csv_to_scene.py, runs `TMCERT verify --json` with
each kernel and compares: the verdict must be the oracle's (no undecided), a rational first
contact must equal the oracle's, an irrational one must be a root of
tmcert's polynomial inside its interval, and first_contact must be exact.
Exit 0 when everything agrees. (The long sweep with per-query CPU times
runs the written files through `tmcert_ccd_bench --scene --truth`:
bench/README.md.)
"""
import argparse
import json
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction as F

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "regression"))
import exact_oracle as xo  # noqa: E402  (the polynomial toolkit; no tmcert code)

# ---------------------------------------------------------------- the oracle


def lin(p0, p1):
    """A linearly moving point: 3 polynomials in t (constant term first)."""
    return [xo.trim([F(p0[i]), F(p1[i]) - F(p0[i])]) for i in range(3)]


def is_zero(poly_vec):
    return all(not c for c in poly_vec)


def gcd_all(polys):
    g = []
    for p in polys:
        if p:
            g = xo.pgcd(g, p) if g else xo.trim(p)
    return g


class At:
    """Exact signs at one candidate time: a rational, or a root of a square-free p."""

    def __init__(self, p, r):
        self.p, self.r = p, r

    def sign(self, q):
        q = xo.trim(q)
        if not q:
            return 0
        return xo.sign_at(q, self.p, self.r)

    def zero(self, vec):
        return all(self.sign(c) == 0 for c in vec)


def on_segment(at, v, e0, e1):
    d = xo.vsub(e1, e0)
    if at.zero(d):
        return at.zero(xo.vsub(v, e0))
    return (at.zero(xo.cross(xo.vsub(v, e0), d)) and at.sign(xo.dot(xo.vsub(v, e0), d)) >= 0
            and at.sign(xo.dot(xo.vsub(v, e1), d)) <= 0)


def vf_touch(at, v, a, b, c):
    n = xo.cross(xo.vsub(b, a), xo.vsub(c, a))
    if at.sign(xo.dot(n, xo.vsub(v, a))) != 0:
        return False
    if at.zero(n):
        return any(on_segment(at, v, p, q) for p, q in ((a, b), (b, c), (c, a)))
    return all(at.sign(xo.dot(xo.cross(xo.vsub(q1, q0), xo.vsub(v, q0)), n)) >= 0 for q0, q1 in ((a, b), (b, c), (c, a)))


def ee_touch(at, a0, a1, b0, b1):
    da, db = xo.vsub(a1, a0), xo.vsub(b1, b0)
    if at.sign(xo.dot(xo.cross(da, db), xo.vsub(b0, a0))) != 0:
        return False
    m = xo.cross(da, db)
    if at.zero(m):
        return (on_segment(at, a0, b0, b1) or on_segment(at, a1, b0, b1) or on_segment(at, b0, a0, a1)
                or on_segment(at, b1, a0, a1))

    def side(d, o, x):
        return at.sign(xo.dot(xo.cross(d, xo.vsub(x, o)), m))
    return side(db, b0, a0) * side(db, b0, a1) <= 0 and side(da, a0, b0) * side(da, a0, b1) <= 0


def vertex_edge_events(v, e0, e1):
    """Polynomials whose roots hold every time v reaches the segment's boundary or line."""
    g = gcd_all(xo.cross(xo.vsub(v, e0), xo.vsub(e1, e0)))
    if g:
        return [g]
    out = []
    for e in (e0, e1):
        h = gcd_all(xo.vsub(v, e))
        if h:
            out.append(h)
    return out


def oracle(kind, pts):
    """The exact first contact of a linear query: None, or (p, (lo, hi)) with
    lo == hi a rational time, else the one root of square-free p in (lo, hi)."""
    if kind == "vf":
        v, a, b, c = pts
        d = xo.dot(xo.cross(xo.vsub(b, a), xo.vsub(c, a)), xo.vsub(v, a))
        touch = lambda at: vf_touch(at, v, a, b, c)  # noqa: E731
        pairs = [(v, a, b), (v, b, c), (v, c, a)]
    else:
        a0, a1, b0, b1 = pts
        d = xo.dot(xo.cross(xo.vsub(a1, a0), xo.vsub(b1, b0)), xo.vsub(b0, a0))
        touch = lambda at: ee_touch(at, a0, a1, b0, b1)  # noqa: E731
        pairs = [(a0, b0, b1), (a1, b0, b1), (b0, a0, a1), (b1, a0, a1)]
    if touch(At([F(0), F(1)], (F(0), F(0)))):
        return [F(0), F(1)], (F(0), F(0))
    events = [d] if d else [e for pair in pairs for e in vertex_edge_events(*pair)]
    product = [F(1)]
    for e in events:
        if len(e) > 1:
            product = xo.pmul(product, e)
    if len(product) <= 1:
        return None
    roots, p = xo.roots(product, F(0), F(1))
    for r in roots:
        if r[0] == r[1] == 0:
            continue
        if touch(At(p, r)):
            return p, r
    return None


# ---------------------------------------------------------------- building blocks


def rat(rng, k=1000):
    return F(rng.randint(-k, k), rng.randint(1, k))


def point(rng, k=1000):
    return [rat(rng, k) for _ in range(3)]


def add(a, b):
    return [a[i] + b[i] for i in range(3)]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def mul(s, a):
    return [s * x for x in a]


def cross3(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot3(a, b):
    return sum(a[i] * b[i] for i in range(3))


def lerp(a, b, s):
    return [a[i] + s * (b[i] - a[i]) for i in range(3)]


def rotation(rng):
    """A random rotation with rational entries: R(q) / |q|^2 of an integer quaternion."""
    while True:
        w, x, y, z = (rng.randint(-6, 6) for _ in range(4))
        n = w * w + x * x + y * y + z * z
        if n:
            break
    return [[F(w * w + x * x - y * y - z * z, n), F(2 * (x * y - w * z), n), F(2 * (x * z + w * y), n)],
            [F(2 * (x * y + w * z), n), F(w * w - x * x + y * y - z * z, n), F(2 * (y * z - w * x), n)],
            [F(2 * (x * z - w * y), n), F(2 * (y * z + w * x), n), F(w * w - x * x - y * y + z * z, n)]]


def apply(R, shift, p):
    return [sum(R[i][j] * p[j] for j in range(3)) + shift[i] for i in range(3)]


def place(rng, q, shift=None):
    """The same random rigid map on all 8 vertices: contacts are preserved exactly."""
    R = rotation(rng)
    s = shift if shift is not None else point(rng, 8)
    return [apply(R, s, p) for p in q]


def planted(at, vel, ts):
    """Vertices at positions `at` at time ts, moving with velocities `vel`: (t = 0 list, t = 1 list)."""
    return [sub(at[k], mul(ts, vel[k])) for k in range(4)], [add(at[k], mul(1 - ts, vel[k])) for k in range(4)]


def query(t0, t1):
    return list(t0) + list(t1)


def rtime(rng):
    return F(rng.randint(1, 999), rng.randint(1000, 1999)) if rng.random() < 0.5 else F(rng.randint(1, 99), 100)


TINY = F(1, 10**15)


def in_face(rng, a, b, c, where):
    """A point of triangle abc: 'in' the interior, 'edge' on edge ab, 'out' beyond ab by TINY in-plane."""
    if where == "in":
        w = [F(rng.randint(1, 50)) for _ in range(3)]
        s = sum(w)
        return [(w[0] * a[i] + w[1] * b[i] + w[2] * c[i]) / s for i in range(3)]
    s = F(rng.randint(1, 99), 100)
    p = lerp(a, b, s)
    if where == "edge":
        return p
    n = cross3(sub(b, a), sub(c, a))
    out = cross3(sub(b, a), n)  # in the plane, away from c
    if dot3(out, sub(c, a)) > 0:
        out = mul(-1, out)
    scale = TINY / max(abs(x) for x in out)
    return add(p, mul(scale, out))


# ---------------------------------------------------------------- families
#
# Each returns (kind, 8 vertices); the mode cycles through a few variants.


def fam_parallel_edges(rng, i):
    """Edges sliding along parallel edges: collinear overlap, touching ends, 1e-15 apart."""
    d = point(rng)
    off = point(rng)
    off = sub(off, mul(dot3(off, d) / dot3(d, d), d))  # perpendicular to d
    mode = i % 6
    a0, a1 = [F(0)] * 3, d
    s0, s1 = rat(rng, 100) * 3, rat(rng, 100) * 3  # slide along d
    gap = {0: F(0), 1: TINY, 2: F(0), 3: TINY, 4: F(0), 5: F(0)}[mode]
    unit = mul(1 / max(abs(x) for x in off), off) if any(off) else [F(1), F(0), F(0)]
    if mode in (0, 1):  # one line (or 1e-15 beside it) throughout, sliding into overlap or not
        length = F(rng.randint(1, 9), 10)
        g = mul(gap, unit)
        t0 = [a0, a1, add(lerp(a0, a1, s0), g), add(lerp(a0, a1, s0 + length), g)]
        t1 = [a0, a1, add(lerp(a0, a1, s1), g), add(lerp(a0, a1, s1 + length), g)]
    elif mode in (2, 3):  # parallel lines approaching each other, sliding
        ts = rtime(rng) if mode == 2 else F(1)
        at = [a0, a1, lerp(a0, a1, s0), lerp(a0, a1, s0 + F(1, 2))]
        vel = [point(rng, 10), None, None, None]
        vel[1] = vel[0]
        vel[2] = add(vel[0], add(mul(rat(rng, 10), d), mul(rat(rng, 10), unit)))
        vel[3] = vel[2]
        t0, t1 = planted(at, vel, ts)
        if mode == 3:  # ends 1e-15 short of the line at t = 1
            t1[2], t1[3] = add(t1[2], mul(TINY, unit)), add(t1[3], mul(TINY, unit))
    elif mode == 4:  # end to end along one line at ts
        ts = rtime(rng)
        at = [a0, a1, a1, lerp(a0, a1, F(3, 2))]
        v = point(rng, 10)
        vel = [v, v, add(v, mul(rat(rng, 10), d)), None]
        vel[3] = vel[2]
        t0, t1 = planted(at, vel, ts)
    else:  # parallel, offset shrinking and both sliding: a random start
        at = [a0, a1, add(lerp(a0, a1, s0), mul(rat(rng, 10), unit)), None]
        at[3] = add(at[2], mul(F(rng.randint(1, 9), 10), d))
        v = point(rng, 10)
        vel = [v, v, add(v, mul(rat(rng, 10), unit)), None]
        vel[3] = vel[2]
        t0, t1 = planted(at, vel, rtime(rng))
    return "ee", place(rng, query(t0, t1))


def fam_vertex_on_face(rng, i):
    """A vertex sliding in a face's plane throughout: entering, on the edge, passing 1e-15 outside."""
    a, b, c = point(rng), point(rng), point(rng)
    ts = rtime(rng) if i % 4 != 3 else rng.choice([F(0), F(1)])
    where = ["in", "edge", "out", "edge"][i % 4]
    p = in_face(rng, a, b, c, where)
    vel_face = point(rng, 10)
    n = cross3(sub(b, a), sub(c, a))
    w = point(rng, 10)
    w = sub(w, mul(dot3(w, n) / dot3(n, n), n))  # in the plane
    if where == "out":  # along the edge's line, 1e-15 outside it: never in
        w = mul(rat(rng, 10), sub(b, a))
    at = [p, a, b, c]
    vel = [add(vel_face, w), vel_face, vel_face, vel_face]
    return "vf", place(rng, query(*planted(at, vel, ts)))


def fam_vertex_along_edge(rng, i):
    """A vertex moving along the line of an edge of the face: reaching it, or stopping 1e-15 short."""
    a, b, c = point(rng), point(rng), point(rng)
    vel_face = point(rng, 10)
    mode = i % 3
    start = lerp(a, b, F(-rng.randint(1, 9), 10))
    end = {0: lerp(a, b, F(rng.randint(1, 9), 10)), 1: a, 2: lerp(a, b, -TINY)}[mode]
    t0 = [start, a, b, c]
    t1 = [add(x, vel_face) for x in (end, a, b, c)]
    return "vf", place(rng, query(t0, t1))


def fam_vertex_onto_vertex(rng, i):
    """A vertex meeting a vertex of the face at ts, or missing it by 1e-15."""
    a, b, c = point(rng), point(rng), point(rng)
    ts = rtime(rng)
    target = [a, b, c][i % 3]
    p = target if i % 2 == 0 else add(target, mul(TINY, [F(rng.randint(-3, 3)) for _ in range(3)]))
    vel = [point(rng, 10) for _ in range(4)]
    return "vf", place(rng, query(*planted([p, a, b, c], vel, ts)))


def generic_planted(rng, kind, ts, miss=F(0)):
    """A contact at ts inside the primitives (optionally lifted by `miss` off the contact)."""
    at = [point(rng) for _ in range(4)]
    if kind == "vf":
        at[0] = in_face(rng, at[1], at[2], at[3], "in")
    else:
        x, y = F(rng.randint(1, 50), 51), F(rng.randint(1, 50), 51)
        common = lerp(at[0], at[1], x)
        at[3] = sub(common, mul((1 - y) / y, sub(at[2], common)))
    at[0] = add(at[0], [F(0), F(0), miss])
    vel = [point(rng) for _ in range(4)]
    return planted(at, vel, ts)


def fam_ends(rng, i):
    """Contacts exactly at t = 0 and t = 1, and ending 1e-15 short of one."""
    kind = "vf" if i % 2 == 0 else "ee"
    mode = (i // 2) % 4
    ts = F(0) if mode in (0, 2) else F(1)
    t0, t1 = generic_planted(rng, kind, ts, TINY if mode >= 2 else F(0))
    return kind, query(t0, t1)


def fam_double_root(rng, i):
    """Tangential grazing: a vertex touching the face's plane at a double root (in the face,
    on its edge, outside it), and lifted by 1e-15."""
    a, b, c = point(rng), point(rng), point(rng)
    ts = rtime(rng)
    mode = i % 4
    p = in_face(rng, a, b, c, ["in", "edge", "out", "in"][mode])
    vel = [None] + [point(rng, 10) for _ in range(3)]
    # D(t) = n(t).(v(t) - a(t)), v(ts) = p in the plane: D(ts) = 0. Pick v's velocity with
    # D'(ts) = n'(ts).(p - a) + n(ts).(vel_v - vel_a) = 0.
    n = cross3(sub(b, a), sub(c, a))
    dn = add(cross3(sub(vel[2], vel[1]), sub(c, a)), cross3(sub(b, a), sub(vel[3], vel[1])))
    w = point(rng, 10)
    need = -dot3(dn, sub(p, a)) + dot3(n, vel[1])  # n . vel_v must equal this
    vel[0] = add(w, mul((need - dot3(n, w)) / dot3(n, n), n))
    if mode == 3:
        p = add(p, mul(TINY / max(abs(x) for x in n), n))
    return "vf", place(rng, query(*planted([p, a, b, c], vel, ts)))


def fam_close_roots(rng, i):
    """Two roots of the contact polynomial 1e-13 apart (the vertex in the face at one, both, none)."""
    a, b, c = point(rng), point(rng), point(rng)
    ts = rtime(rng) / 2
    delta = F(1, 10**13)
    p = in_face(rng, a, b, c, ["in", "out", "edge"][i % 3])
    vel = [None] + [point(rng, 10) for _ in range(3)]
    # v(ts) = p (a root at ts); choose vel_v with D(ts + delta) = 0: linear in vel_v.
    t2 = ts + delta
    a2, b2, c2 = (add(x, mul(delta, vx)) for x, vx in ((a, vel[1]), (b, vel[2]), (c, vel[3])))
    n2 = cross3(sub(b2, a2), sub(c2, a2))
    w = point(rng, 10)
    # n2 . (p + delta vel_v - a2) = 0
    need = -dot3(n2, sub(p, a2)) / delta
    vel[0] = add(w, mul((need - dot3(n2, w)) / dot3(n2, n2), n2))
    del t2
    return "vf", place(rng, query(*planted([p, a, b, c], vel, ts)))


def fam_far(rng, i):
    """Coordinates at 1e8, motions of 1e-6: planted contacts, misses by 1e-15, random."""
    kind = "vf" if i % 2 == 0 else "ee"
    mode = (i // 2) % 3
    scale = F(1, 10**6)
    if mode == 2:
        t0, t1 = [point(rng) for _ in range(4)], [point(rng) for _ in range(4)]
    else:
        t0, t1 = generic_planted(rng, kind, rtime(rng), TINY / scale if mode == 1 else F(0))
    base = [F(10**8) + rat(rng, 10) for _ in range(3)]
    q = [add(base, mul(scale, p)) for p in query(t0, t1)]
    return kind, q


def fam_degenerate_triangle(rng, i):
    """Collinear triangles (throughout or at one end) and a repeated vertex, hit or missed."""
    a, b = point(rng), point(rng)
    mode = i % 4
    c = lerp(a, b, F(rng.randint(-9, 19), 10)) if mode != 3 else b  # collinear / repeated vertex
    ts = rtime(rng)
    s = F(rng.randint(-2, 12), 10)  # on the line, inside the hull of a, b, c or not
    p = lerp(a, b, s)
    if mode == 1:
        p = add(p, mul(TINY, [F(1), F(0), F(0)]))
    v = point(rng, 10)
    vel = [point(rng, 10), v, v, v]
    t0, t1 = planted([p, a, b, c], vel, ts)
    if mode == 2:  # collinear at t = 1 only: the third vertex moves onto the line
        t0[3] = add(t0[3], point(rng, 10))
    return "vf", place(rng, query(t0, t1))


def fam_zero_length_edge(rng, i):
    """Edge-edge with one or both edges of length zero (points), touching or 1e-15 apart."""
    mode = i % 4
    b0, b1 = point(rng), point(rng)
    ts = rtime(rng)
    s = F(rng.randint(-2, 12), 10)
    p = lerp(b0, b1, s) if mode != 2 else b0
    if mode == 1:
        p = add(p, mul(TINY, [F(0), F(1), F(0)]))
    vel = [point(rng, 10)] * 2 + [point(rng, 10)] * 2
    if mode == 3:  # both edges points
        at = [p, p, b0, b0]
        vel = [vel[0], vel[0], vel[2], vel[2]]
    else:
        at = [p, p, b0, b1]
    return "ee", place(rng, query(*planted(at, vel, ts)))


def fam_motionless(rng, i):
    """No motion at all: touching (inside, on an edge, at a vertex), 1e-15 apart, random."""
    kind = "vf" if i % 2 == 0 else "ee"
    mode = (i // 2) % 4
    at = [point(rng) for _ in range(4)]
    if kind == "vf":
        where = ["in", "edge", "out", None][mode]
        if where:
            at[0] = in_face(rng, at[1], at[2], at[3], where)
    else:
        if mode < 3:
            common = lerp(at[0], at[1], F(rng.randint(0, 10), 10) if mode != 1 else F(1))
            at[2] = common if mode == 1 else at[2]
            at[3] = sub(common, mul(F(rng.randint(1, 9), 10), sub(at[2], common))) if mode != 1 else at[3]
            if mode == 2:
                at[2], at[3] = add(at[2], [F(0), F(0), TINY]), add(at[3], [F(0), F(0), TINY])
    return kind, place(rng, query(at, at))


def fam_coplanar(rng, i):
    """All eight vertices in one plane over the whole motion (a random rotated plane)."""
    kind = "vf" if i % 2 == 0 else "ee"
    flat = lambda: [rat(rng, 100), rat(rng, 100), F(0)]  # noqa: E731
    q = [flat() for _ in range(8)]
    if i % 4 >= 2:  # planted: the vertex in the face (or the ends on the other edge) at ts
        ts = rtime(rng)
        at = [flat() for _ in range(4)]
        if kind == "vf":
            at[0] = in_face(rng, at[1], at[2], at[3], "edge")
        else:
            at[2] = lerp(at[0], at[1], F(rng.randint(0, 10), 10))
        vel = [flat() for _ in range(4)]
        t0, t1 = planted(at, vel, ts)
        q = query(t0, t1)
    return kind, place(rng, q)


def fam_endpoints(rng, i):
    """Edges meeting at their endpoints at ts (end on end, end on the other's interior), or 1e-15 apart."""
    ts = rtime(rng)
    mode = i % 4
    a0, a1, b1 = point(rng), point(rng), point(rng)
    b0 = a1 if mode in (0, 1) else lerp(a0, a1, F(rng.randint(1, 9), 10))
    if mode in (1, 3):
        b0 = add(b0, mul(TINY, [F(rng.randint(-2, 2)) for _ in range(3)]))
    vel = [point(rng, 10) for _ in range(4)]
    return "ee", place(rng, query(*planted([a0, a1, b0, b1], vel, ts)))


def dbl(rng, x=None):
    """A random double in [-1, 1] (or x rounded to a double), as its exact binary fraction."""
    return F(rng.uniform(-1, 1) if x is None else float(x))


def fam_doubles(rng, i):
    """Random doubles (exact binary fractions): random queries, and planted contacts rounded to doubles."""
    kind = "vf" if i % 2 == 0 else "ee"
    if (i // 2) % 2 == 0:
        return kind, [[dbl(rng) for _ in range(3)] for _ in range(8)]
    t0, t1 = generic_planted(rng, kind, F(rng.random()))
    return kind, [[dbl(rng, x / 1000) for x in p] for p in query(t0, t1)]


FAMILIES = {
    "parallel-edges": fam_parallel_edges,
    "vertex-on-face": fam_vertex_on_face,
    "vertex-along-edge": fam_vertex_along_edge,
    "vertex-onto-vertex": fam_vertex_onto_vertex,
    "contact-at-ends": fam_ends,
    "double-root": fam_double_root,
    "close-roots": fam_close_roots,
    "far-1e8": fam_far,
    "degenerate-triangle": fam_degenerate_triangle,
    "zero-length-edge": fam_zero_length_edge,
    "motionless": fam_motionless,
    "coplanar": fam_coplanar,
    "edge-endpoints": fam_endpoints,
    "doubles": fam_doubles,
}

# ---------------------------------------------------------------- output


def moving(kind, q):
    return [lin(q[k], q[k + 4]) for k in range(4)]


def time_json(truth):
    if truth is None:
        return None
    p, (lo, hi) = truth
    if lo == hi:
        return str(lo)
    return {"root_of": [str(c) for c in p], "interval": [str(lo), str(hi)]}


def generate(family, n, seed):
    """n queries of one family: a list of (kind, 8 vertices, oracle result)."""
    rng = random.Random(f"{family}/{seed}")
    out = []
    for i in range(n):
        kind, q = FAMILIES[family](rng, i)
        out.append((kind, q, oracle(kind, moving(kind, q))))
    return out


def write_family(root, family, queries):
    paths = []
    for kind, sub_dir in (("vf", "vertex-face"), ("ee", "edge-edge")):
        mine = [(q, truth) for k, q, truth in queries if k == kind]
        if not mine:
            continue
        d = os.path.join(root, family, sub_dir)
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, "queries.csv"), "w") as f:
            for q, truth in mine:
                for p in q:
                    f.write(",".join(f"{x.numerator},{x.denominator}" for x in p) + f",{int(truth is not None)}\n")
        with open(os.path.join(d, "first_contact.json"), "w") as f:
            json.dump([time_json(truth) for _, truth in mine], f)
        paths.append((os.path.join(d, "queries.csv"), [truth for _, truth in mine]))
    return paths


# ---------------------------------------------------------------- --check


def check(tmcert, n, seed, kernels, families):
    convert = os.path.join(HERE, "ccd_csv_to_scene.py")
    bad = 0
    total = 0
    with tempfile.TemporaryDirectory() as root:
        files = []  # (family, csv path, oracle results)
        for family in families:
            files += [(family, path, truths) for path, truths in write_family(root, family, generate(family, n, seed))]
        # One scene for all files (one tmcert run per kernel); checks follow the files in order.
        scene = os.path.join(root, "scene.json")
        subprocess.run([sys.executable, convert, *[f for _, f, _ in files], "-o", scene], check=True,
                       capture_output=True)
        for kernel in kernels:
            out = subprocess.run([tmcert, "verify", scene, "--json", "--kernel", kernel], capture_output=True, text=True)
            if out.returncode not in (0, 1, 2):
                print(f"FAIL {kernel}: tmcert exit {out.returncode}: {out.stderr.strip()}")
                bad += 1
                continue
            checks = iter(json.loads(out.stdout)["checks"])
            for family, path, truths in files:
                kind = os.path.basename(os.path.dirname(path))
                msgs = []
                for k, truth in enumerate(truths):
                    c = next(checks)
                    where = f"{family} {kind} query {k} ({kernel})"
                    msgs += xo.mismatches(c, truth, where)
                    # the comparison can fail: the opposite truth must be a mismatch
                    if c["verdict"] in ("safe", "collision"):
                        flipped = None if truth is not None else ([F(0), F(1)], (F(0), F(0)))
                        if not xo.mismatches(c, flipped, ""):
                            msgs.append(f"{where}: a flipped truth is not caught")
                total += len(truths)
                bad += len(msgs)
                for m in msgs[:5]:
                    print("MISMATCH", m)
                coll = sum(t is not None for t in truths)
                print(f"  {family:20s} {kind:12s} {kernel:8s} {len(truths):4d} queries, {coll:4d} colliding, "
                      f"{len(msgs)} mismatches")
    print(f"ccd_degenerate_queries --check: {total} query runs, {bad} mismatches "
          f"(replay: ccd_degenerate_queries.py --check TMCERT --n {n} --seed {seed})")
    return 1 if bad or total == 0 else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", nargs="?")
    ap.add_argument("--n", type=int, default=1000, help="queries per family")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--families", help="comma-separated subset (default: all; see --list)")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--check", metavar="TMCERT")
    ap.add_argument("--kernel", action="append", choices=["filtered", "exact"])
    args = ap.parse_args()
    if args.list:
        for name, f in FAMILIES.items():
            print(f"{name:20s} {f.__doc__.splitlines()[0]}")
        return 0
    families = args.families.split(",") if args.families else list(FAMILIES)
    for f in families:
        if f not in FAMILIES:
            print(f"ccd_degenerate_queries: unknown family '{f}' (see --list)", file=sys.stderr)
            return 3
    if args.check:
        return check(args.check, args.n, args.seed, args.kernel or ["filtered", "exact"], families)
    if not args.out:
        ap.error("give OUT, --check TMCERT or --list")
    for family in families:
        queries = generate(family, args.n, args.seed)
        write_family(args.out, family, queries)
        coll = sum(t is not None for _, _, t in queries)
        print(f"{family:20s} {len(queries):6d} queries, {coll:6d} colliding")
    return 0


if __name__ == "__main__":
    sys.exit(main())
