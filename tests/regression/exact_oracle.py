#!/usr/bin/env python3
"""Exact resolution against an independent exact oracle (pure Python).

Random rational vertex-face and edge-edge queries with planted contacts
(a vertex placed in the face, or two edges through one point, at a random
rational time), planted tangential contacts (a double root: a vertex on a
parabola touching the face's plane), and near misses (the planted contact
moved off by 1e-15, and a tangential contact lifted by 1e-15 off the
plane: a miss by 1e-15), and unplanted random queries. tmcert decides them (`verify --json`); the oracle
computes the exact first contact itself with Python Fractions: the
coplanarity polynomial, Sturm isolation of its roots, and the containment
signs at each root (zero by a gcd, else by exact interval bisection). It
shares no code with tmcert. Every verdict must agree, a rational first
contact must be equal, an irrational one must be a root of tmcert's
polynomial inside tmcert's interval.

Usage: exact_oracle.py TMCERT [COUNT] [SEED]   (exit 0: all agree)
"""
import json
import random
import subprocess
import sys
import tempfile
from fractions import Fraction as F

# ---------------------------------------------------------------- polynomials (constant term first)


def trim(p):
    p = list(p)
    while p and p[-1] == 0:
        p.pop()
    return p


def padd(a, b):
    n = max(len(a), len(b))
    return trim([(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(n)])


def psub(a, b):
    return padd(a, [-x for x in b])


def pmul(a, b):
    if not a or not b:
        return []
    r = [F(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            r[i + j] += x * y
    return trim(r)


def pmod(a, b):
    a = list(a)
    while len(a) >= len(b) and a:
        c = a[-1] / b[-1]
        s = len(a) - len(b)
        for i, y in enumerate(b):
            a[s + i] -= c * y
        a = trim(a)
    return a


def pdiv(a, b):
    a = list(a)
    q = [F(0)] * max(len(a) - len(b) + 1, 1)
    while len(a) >= len(b) and a:
        c = a[-1] / b[-1]
        s = len(a) - len(b)
        q[s] = c
        for i, y in enumerate(b):
            a[s + i] -= c * y
        a = trim(a)
    return trim(q)


def pgcd(a, b):
    a, b = trim(a), trim(b)
    while b:
        a, b = b, pmod(a, b)
    return [x / a[-1] for x in a] if a else []


def deriv(p):
    return trim([i * p[i] for i in range(1, len(p))])


def ev(p, x):
    r = F(0)
    for c in reversed(p):
        r = r * x + c
    return r


def sgn(x):
    return (x > 0) - (x < 0)


def sturm(p):
    s = [p, deriv(p)]
    while s[-1] and len(s[-1]) > 1:
        r = pmod(s[-2], s[-1])
        if not r:
            break
        s.append([-x for x in r])
    return [q for q in s if q]


def variations(s, x):
    signs = [sgn(ev(q, x)) for q in s]
    signs = [v for v in signs if v]
    return sum(1 for i in range(1, len(signs)) if signs[i] != signs[i - 1])


def roots(p, a, b):
    """Distinct roots of p in [a, b], increasing: (lo, hi) with lo == hi for an exact root."""
    p = trim(p)
    if len(p) <= 1:
        return []
    p = pdiv(p, pgcd(p, deriv(p)))  # square-free
    s = sturm(p)
    out = []
    if ev(p, a) == 0:
        out.append((a, a))
    stack = [(a, b)]
    found = []
    while stack:
        lo, hi = stack.pop()
        n = variations(s, lo) - variations(s, hi)  # roots in (lo, hi]
        if n == 0:
            continue
        if ev(p, hi) == 0 and n == 1:
            found.append((hi, hi))
            continue
        if n == 1 and ev(p, lo) != 0:
            found.append((lo, hi))
            continue
        m = (lo + hi) / 2
        stack += [(lo, m), (m, hi)]
    return out + sorted(found), p


def sign_at(q, p, root):
    """Sign of q at the root of square-free p isolated in root = (lo, hi)."""
    lo, hi = root
    if lo == hi:
        return sgn(ev(q, lo))
    g = pgcd(p, q) if q else [F(1)]
    if not q:
        return 0
    if len(g) > 1 and sgn(ev(g, lo)) != sgn(ev(g, hi)):
        return 0
    plo = sgn(ev(p, lo))
    for _ in range(400):
        m = (lo + hi) / 2
        pm = sgn(ev(p, m))
        if pm == 0:
            return sgn(ev(q, m))
        if pm == plo:
            lo = m
        else:
            hi = m
        # q has one sign on [lo, hi] when its interval Horner excludes 0
        a, b = F(q[-1]), F(q[-1])
        for c in reversed(q[:-1]):
            prods = [a * lo, a * hi, b * lo, b * hi]
            a, b = min(prods) + c, max(prods) + c
        if a > 0:
            return 1
        if b < 0:
            return -1
    raise RuntimeError("sign_at: no decision")


# ---------------------------------------------------------------- moving points: 3 polynomials in t


def vsub(a, b):
    return [psub(a[i], b[i]) for i in range(3)]


def cross(a, b):
    return [psub(pmul(a[1], b[2]), pmul(a[2], b[1])), psub(pmul(a[2], b[0]), pmul(a[0], b[2])),
            psub(pmul(a[0], b[1]), pmul(a[1], b[0]))]


def dot(a, b):
    return padd(padd(pmul(a[0], b[0]), pmul(a[1], b[1])), pmul(a[2], b[2]))


def first_contact(kind, pts):
    """The exact first contact in [0, 1] of a generic query (coplanarity not
    identically zero, directions not parallel at the roots): (roots poly, root) or None."""
    if kind == "vf":
        v, a, b, c = pts
        n = cross(vsub(b, a), vsub(c, a))
        d = dot(n, vsub(v, a))
        conds = [dot(cross(vsub(q1, q0), vsub(v, q0)), n) for q0, q1 in ((a, b), (b, c), (c, a))]
    else:
        a0, a1, b0, b1 = pts
        da, db = vsub(a1, a0), vsub(b1, b0)
        n = cross(da, db)
        d = dot(n, vsub(b0, a0))
        # each segment's ends on opposite sides of the other's line: s(x0) s(x1) <= 0
        conds = [("pair", dot(cross(db, vsub(a0, b0)), n), dot(cross(db, vsub(a1, b0)), n)),
                 ("pair", dot(cross(da, vsub(b0, a0)), n), dot(cross(da, vsub(b1, a0)), n))]
    if not d:
        return "degenerate"
    rs, p = roots(d, F(0), F(1))
    for r in rs:
        if kind == "vf":
            if sign_at(dot(n, n), p, r) == 0:
                return "degenerate"
            if all(sign_at(c, p, r) >= 0 for c in conds):
                return p, r
        else:
            if sign_at(dot(n, n), p, r) == 0:
                return "degenerate"
            if all(sign_at(x, p, r) * sign_at(y, p, r) <= 0 for _, x, y in conds):
                return p, r
    return None


# ---------------------------------------------------------------- random queries


def rnd(rng, k=1000):
    return F(rng.randint(-k, k), rng.randint(1, k))


def rpoint(rng):
    return [rnd(rng) for _ in range(3)]


def linear(p0, p1):
    return [trim([p0[i], p1[i] - p0[i]]) for i in range(3)]


def make_query(rng, mode):
    kind = rng.choice(["vf", "ee"])
    ts = F(rng.randint(1, 99), 100) if rng.random() < 0.5 else F(rng.randint(1, 999), rng.randint(1000, 1999))
    vel = [rpoint(rng) for _ in range(4)]
    at = [rpoint(rng) for _ in range(4)]  # positions at ts
    if kind == "vf":
        w = [F(rng.randint(1, 50)) for _ in range(3)]
        s = sum(w)
        at[0] = [sum(w[k] * at[k + 1][i] for k in range(3)) / s for i in range(3)]  # inside the face at ts
    else:
        x = [F(rng.randint(1, 50), 51), F(rng.randint(1, 50), 51)]
        common = [(1 - x[0]) * at[0][i] + x[0] * at[1][i] for i in range(3)]
        at[2] = [common[i] + (at[2][i] - common[i]) for i in range(3)]
        at[3] = [common[i] - (at[2][i] - common[i]) * (1 - x[1]) / x[1] for i in range(3)]
    if mode == "near":
        off = F(1, 10**15)
        at[0] = [at[0][0], at[0][1], at[0][2] + off]
    if mode == "random":
        at = [rpoint(rng) for _ in range(4)]
    pts = []
    deg2 = mode in ("double", "graze_miss") and kind == "vf"
    for k in range(4):
        p0 = [at[k][i] - ts * vel[k][i] for i in range(3)]
        p1 = [at[k][i] + (1 - ts) * vel[k][i] for i in range(3)]
        pts.append(linear(p0, p1))
    if deg2:
        # the face moves linearly; the vertex stays at height (t - ts)^2 above
        # its plane along the normal: a double root at ts.
        a, b, c = pts[1], pts[2], pts[3]
        n = [at[2][i] - at[1][i] for i in range(3)]
        m = [at[3][i] - at[1][i] for i in range(3)]
        normal = [n[1] * m[2] - n[2] * m[1], n[2] * m[0] - n[0] * m[2], n[0] * m[1] - n[1] * m[0]]
        # all four points translate by the same velocity: the plane keeps its
        # normal; the vertex adds (t - ts)^2 * normal.
        v = vel[1]
        for k in range(4):
            pts[k] = linear([at[k][i] - ts * v[i] for i in range(3)], [at[k][i] + (1 - ts) * v[i] for i in range(3)])
        sq = [ts * ts + (F(1, 10**15) if mode == "graze_miss" else 0), -2 * ts, F(1)]
        pts[0] = [padd(pts[0][i], [x * normal[i] for x in sq]) for i in range(3)]
    return kind, pts


def bezier(poly):
    """Power-basis polynomial (degree <= 2) to Bernstein control values of degree 2."""
    p = list(poly) + [F(0)] * (3 - len(poly))
    return [p[0], p[0] + p[1] / 2, p[0] + p[1] + p[2]]


def body(name, kind, pts):
    """A body whose 1, 2 or 3 vertices follow pts (quadratic Bezier in t), as
    the canonical point/segment/triangle under [v1 - v0, v2 - v0, 0 | v0]."""
    cps = []
    for j in range(3):
        rows = []
        for i in range(3):
            o = bezier(pts[0][i])[j]
            c1 = bezier(pts[1][i])[j] - o if len(pts) > 1 else F(0)
            c2 = bezier(pts[2][i])[j] - o if len(pts) > 2 else F(0)
            rows.append([str(c1), str(c2), "0", str(o)])
        cps.append(rows)
    b = {"name": name, "motion": {"type": "rational_bezier", "control_points": cps}}
    if len(pts) == 1:
        b["points"] = [[0, 0, 0]]
    elif len(pts) == 2:
        b["segments"] = [[[0, 0, 0], [1, 0, 0]]]
    else:
        b["polygons"] = [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]]
    return b


def mismatches(c, truth, where):
    """Mismatch messages for one tmcert check against the oracle's first contact."""
    if truth is None:
        return [] if c["verdict"] == "safe" else [f"{where}: oracle no contact, tmcert {c['verdict']}"]
    p, r = truth
    if c["verdict"] != "collision":
        return [f"{where}: oracle contact at {float(r[0]):.17g}, tmcert {c['verdict']}"]
    fc = c["first_contact"]["t"]
    if fc[0] != fc[1]:
        return [f"{where}: first contact not exact"]
    t = fc[0]
    if isinstance(t, str):
        x = F(t)
        ok = x == r[0] if r[0] == r[1] else (r[0] < x < r[1] and ev(p, x) == 0)
        return [] if ok else [f"{where}: oracle first contact in [{r[0]}, {r[1]}], tmcert {t}"]
    if r[0] == r[1]:
        return [f"{where}: oracle first contact {r[0]}, tmcert an irrational root"]
    poly, lo, hi = [F(int(x)) for x in t["root_of"]], F(t["interval"][0]), F(t["interval"][1])
    rlo, rhi = r
    for _ in range(300):
        if lo <= rlo and rhi <= hi:
            break
        m = (rlo + rhi) / 2
        if ev(p, m) == 0:
            rlo = rhi = m
            break
        if sgn(ev(p, m)) == sgn(ev(p, rlo)):
            rlo = m
        else:
            rhi = m
    inside = lo <= rlo and rhi <= hi and (rlo < rhi or lo < rlo < hi)
    if not inside or sign_at(poly, p, (rlo, rhi)) != 0:
        return [f"{where}: oracle root in ({float(r[0])}, {float(r[1])}) is not tmcert's root in ({lo}, {hi})"]
    return []


def main():
    tmcert = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 150
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 2026
    rng = random.Random(seed)
    print(f"exact_oracle: {count} queries, seed {seed} (replay: exact_oracle.py TMCERT {count} {seed})")
    queries, bodies, checks = [], [], []
    for q in range(count):
        mode = ["plant", "double", "near", "graze_miss", "random"][q % 5]
        kind, pts = make_query(rng, mode)
        truth = first_contact(kind, pts)
        if truth == "degenerate":
            continue
        i = len(queries)
        if kind == "vf":
            bodies += [body(f"q{i}a", kind, pts[:1]), body(f"q{i}b", kind, pts[1:])]
        else:
            bodies += [body(f"q{i}a", kind, pts[:2]), body(f"q{i}b", kind, pts[2:])]
        checks.append([f"q{i}a", f"q{i}b"])
        queries.append((mode, kind, truth))
    scene = {"format": "tmcert-scene/1", "epsilon": "1/1000000", "bodies": bodies, "checks": checks}
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(scene, f)
        path = f.name
    out = subprocess.run([tmcert, "verify", path, "--json"], capture_output=True, text=True)
    if out.returncode not in (0, 1, 2):
        print(f"tmcert failed (exit {out.returncode}): {out.stderr}")
        return 1
    result = json.loads(out.stdout)
    bad = 0
    stats = {}
    for (mode, kind, truth), c in zip(queries, result["checks"]):
        key = (mode, kind, "contact" if truth else "free")
        stats[key] = stats.get(key, 0) + 1
        for m in mismatches(c, truth, f"{c['bodies'][0]} ({mode} {kind})"):
            print(f"MISMATCH {m}")
            bad += 1
    for k in sorted(stats):
        print(f"  {k[0]:6s} {k[1]} {k[2]:7s} {stats[k]}")
    print(f"exact_oracle: {len(queries)} queries, {bad} mismatches")
    return 1 if bad or len(queries) < count // 2 else 0


if __name__ == "__main__":
    sys.exit(main())
