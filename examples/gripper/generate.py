"""Generate the gripper-in-a-fixture mesh example (examples/gripper/).

A parallel-jaw gripper (one closed triangle mesh, 438 triangles) moves by a
pure translation along a rational cubic Bezier curve through a cluttered
fixture (one mesh of three closed, disjoint components -- three fixture
plates with posts, pins, blocks, clamps and V-blocks unioned into them --
5294 triangles).  The gripper comes down from above and behind, passes
over a tall tower, slides its fingers into a slot between two rows of posts
(straddling a row of rest blocks) and stops at a pick pose 8 mm above the
plate.  This script writes

  gripper.off              the gripper (body frame: fingertips at z = 0)
  fixture.off              the fixture (world frame, plate tops at z = 0)
  gripper-safe.json        the motion: never touches, clearance exactly 3 mm
  gripper-collision.json   the same motion with the last control point moved
                           6 mm in +x: the right finger runs into the posts,
                           the left one into a rest block
  EXPECTED                 <file><TAB><verdict> per scene

and VERIFIES every claim exactly (fractions.Fraction / integers), exiting
non-zero if a check fails:

  meshes   every triangle non-degenerate (cross product != 0); every directed
           edge used exactly once and its reverse exactly once (closed,
           consistently oriented, no T-junctions); no vertex on the open
           interior of an edge; every component has positive signed volume
           (outward orientation); every two triangles without a common vertex
           are disjoint as closed sets (no self-intersection, components
           pairwise disjoint), and the components' bounding boxes are
           pairwise disjoint; all coordinates on the 1e-5 grid.
  safe     the translation d(t) is a rational Bezier curve with positive
           weights, so on every parameter piece d lies in the axis-aligned
           box of the piece's control points (de Casteljau subdivision in
           homogeneous coordinates).  For every piece and every gripper part
           (finger, finger, palm, wrist), the box  AABB(part) + box(d)  is at
           Euclidean distance >= 3 mm from the AABB of every fixture triangle.
           The gripper surface lies in the union of the part boxes, so the
           bodies stay >= 3 mm apart for all t in [0, 1]; at t = 1 a point of
           the right finger and a point of a post are exactly 3 mm apart, so
           the minimum clearance is exactly 3 mm.  The fingers pass ten posts
           and four rest blocks at exactly 3 mm (points on both meshes
           verified at grid times).
  collision  at t = 1 (and at every t = k/64 from the earliest printed one
           on) an edge of one mesh crosses the open interior of a triangle of
           the other transversally: an exact common point.  The same box
           proof with clearance > 0 clears [0, T] for the printed T, which
           brackets the first contact.

Only the standard library is used; all geometry is exact.  Circle points are
computed with decimal arithmetic (60 digits) and rounded to the 1e-5 grid, so
the output does not depend on the platform's libm: running

  python3 examples/gripper/generate.py

regenerates every file byte-identically.  Units are metres.
"""

import json
import os
import sys
from collections import defaultdict
from decimal import Decimal, localcontext
from fractions import Fraction as Fr
from math import comb

HERE = os.path.dirname(os.path.abspath(__file__))

UNIT = 10 ** 5            # every coordinate is a multiple of 1/UNIT (0.01 mm)


def D(s):
    """An exact decimal."""
    return Fr(s)


# ---------------------------------------------------------------------------
# Exact small helpers
# ---------------------------------------------------------------------------

def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def orient2(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def snap(x):
    """Round an exact number to the 1/UNIT grid (deterministic, half-even)."""
    return Fr(round(Fr(x) * UNIT), UNIT)


def dec(x):
    """An exact grid number as a short decimal string ("0.027", "-0.06", "0")."""
    x = Fr(x)
    for k in range(0, 9):
        if (x * 10 ** k).denominator == 1:
            n = x * 10 ** k
            break
    else:
        raise ValueError("not a short decimal: %s" % x)
    n = int(n)
    sign = "-" if n < 0 else ""
    n = abs(n)
    if k == 0:
        return sign + str(n)
    s = str(n).rjust(k + 1, "0")
    return sign + s[:-k] + "." + s[-k:]


_PI = Decimal("3.14159265358979323846264338327950288419716939937510582097494459")


def cos_sin(num, den):
    """(cos, sin) of 2*pi*num/den as Fractions accurate to ~1e-45."""
    with localcontext() as ctx:
        ctx.prec = 60
        x = 2 * _PI * num / den
        c, s = Decimal(0), Decimal(0)
        term = Decimal(1)            # x^k / k!
        for k in range(0, 120):
            if k % 4 == 0:
                c += term
            elif k % 4 == 1:
                s += term
            elif k % 4 == 2:
                c -= term
            else:
                s -= term
            term = term * x / (k + 1)
        return Fr(c), Fr(s)


def ngon(cx, cy, r, n):
    """Regular n-gon (CCW) around (cx, cy) with radius r, vertex 0 at angle 0,
    coordinates snapped to the grid."""
    pts = []
    for k in range(n):
        c, s = cos_sin(k, n)
        pts.append((snap(cx + r * c), snap(cy + r * s)))
    return pts


def arc(cx, cy, r, degs):
    """Points of a circle at the given angles in degrees (snapped)."""
    out = []
    for a in degs:
        c, s = cos_sin(a, 360)
        out.append((snap(cx + r * c), snap(cy + r * s)))
    return out


# ---------------------------------------------------------------------------
# Planar triangulation (exact)
# ---------------------------------------------------------------------------

def area2(poly):
    return sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
               for i in range(len(poly)))


def in_closed_tri(p, a, b, c):
    return orient2(a, b, p) >= 0 and orient2(b, c, p) >= 0 and orient2(c, a, p) >= 0


def ear_clip(poly):
    """Triangulate a simple CCW polygon (collinear vertices allowed); index triples."""
    assert area2(poly) > 0, "polygon not counter-clockwise"
    idx = list(range(len(poly)))
    tris = []
    while len(idx) > 3:
        n = len(idx)
        for k in range(n):
            a, b, c = idx[k - 1], idx[k], idx[(k + 1) % n]
            A, B, C = poly[a], poly[b], poly[c]
            if orient2(A, B, C) <= 0:
                continue
            if any(in_closed_tri(poly[m], A, B, C) for m in idx
                   if m not in (a, b, c) and poly[m] not in (A, B, C)):
                continue
            tris.append((a, b, c))
            idx.pop(k)
            break
        else:
            raise AssertionError("ear clipping failed")
    a, b, c = idx
    assert orient2(poly[a], poly[b], poly[c]) > 0
    tris.append((a, b, c))
    return tris


def annulus(outer, inner):
    """Triangulate the region between a convex CCW loop `outer` and a CCW
    loop `inner` strictly inside it and convex: bridge the rightmost inner
    vertex M to the outer vertex of largest x (then smallest y) -- every
    point of that segment but M lies right of the hole, so it crosses
    nothing -- and ear-clip the resulting weakly simple polygon.  Every
    triangle is verified positive and their areas must add up to
    area(outer) - area(inner): with the edge pairing checked later this
    proves an exact tiling.  Returns CCW point triangles."""
    O, I = list(outer), list(inner)
    m = max(range(len(I)), key=lambda k: (I[k][0], -I[k][1]))
    c = max(range(len(O)), key=lambda k: (O[k][0], -O[k][1]))
    assert O[c][0] > I[m][0]
    hole = [I[(m - k) % len(I)] for k in range(len(I))]           # clockwise from M
    poly = O[:c + 1] + hole + [I[m]] + O[c:]
    tris = [(poly[a], poly[b], poly[cc]) for (a, b, cc) in ear_clip(poly)]
    total = 0
    for t in tris:
        ar = orient2(*t)
        assert ar > 0, "annulus triangle not positive"
        total += ar
    assert total == area2(outer) - area2(inner), "annulus does not tile"
    return tris


# ---------------------------------------------------------------------------
# Mesh builder
# ---------------------------------------------------------------------------

class Mesh:
    def __init__(self):
        self.index = {}
        self.verts = []
        self.tris = []
        self.tags = []
        self.tag = None

    def v(self, p):
        p = tuple(Fr(c) for c in p)
        assert all((c * UNIT).denominator == 1 for c in p), "off-grid coordinate %s" % (p,)
        i = self.index.get(p)
        if i is None:
            i = self.index[p] = len(self.verts)
            self.verts.append(p)
        return i

    def tri(self, a, b, c):
        self.tris.append((self.v(a), self.v(b), self.v(c)))
        self.tags.append(self.tag)

    def tri_out(self, a, b, c, out):
        """Triangle oriented so that its normal points along `out`."""
        n = cross(sub(b, a), sub(c, a))
        s = dot(n, out)
        assert s != 0, "cannot orient triangle"
        if s > 0:
            self.tri(a, b, c)
        else:
            self.tri(a, c, b)

    def quad_out(self, a, b, c, d, out):
        """Planar or not, the quad a-b-c-d as two triangles facing `out`."""
        self.tri_out(a, b, c, out)
        self.tri_out(a, c, d, out)


def lift(axis, level, p2):
    """Point of the plane (coordinate `axis` = level) from its 2D coordinates
    (coordinates (axis+1)%3, (axis+2)%3, so that CCW in 2D faces +axis)."""
    p = [None, None, None]
    p[axis] = level
    p[(axis + 1) % 3] = p2[0]
    p[(axis + 2) % 3] = p2[1]
    return tuple(p)


def drop(axis, p3):
    return (p3[(axis + 1) % 3], p3[(axis + 2) % 3])


def face(mesh, loop3, axis, sign):
    """Axis-aligned planar face (simple polygon, any orientation), outward
    normal sign * e_axis."""
    level = loop3[0][axis]
    assert all(p[axis] == level for p in loop3)
    poly = [drop(axis, p) for p in loop3]
    if (area2(poly) > 0) != (sign > 0):
        poly = poly[::-1]
    assert area2(poly) != 0
    if sign < 0:                       # CCW in 2D faces +axis; triangulate the mirror
        tris = ear_clip(poly[::-1])
        poly = poly[::-1]
        for (i, j, k) in tris:
            mesh.tri(lift(axis, level, poly[i]), lift(axis, level, poly[k]), lift(axis, level, poly[j]))
    else:
        for (i, j, k) in ear_clip(poly):
            mesh.tri(lift(axis, level, poly[i]), lift(axis, level, poly[j]), lift(axis, level, poly[k]))


def grid_face(mesh, level, sign, xs, ys, holes):
    """Face z = level (outward normal sign * e_z) over the rectangle
    [xs[0], xs[-1]] x [ys[0], ys[-1]], split at the breakpoints xs, ys into
    cells.  holes maps a cell (i, j) to a CCW convex loop strictly inside
    the cell, cut out of the face.  Every cell is bounded by
    its four corners only, so neighbouring cells match without T-junctions."""
    for (i, j), loop in holes.items():
        assert xs[i] < min(p[0] for p in loop) and max(p[0] for p in loop) < xs[i + 1]
        assert ys[j] < min(p[1] for p in loop) and max(p[1] for p in loop) < ys[j + 1]
    for i in range(len(xs) - 1):
        for j in range(len(ys) - 1):
            cell = [(xs[i], ys[j]), (xs[i + 1], ys[j]), (xs[i + 1], ys[j + 1]), (xs[i], ys[j + 1])]
            if (i, j) in holes:
                tris = annulus(cell, holes[(i, j)])
            else:
                tris = [(cell[0], cell[1], cell[2]), (cell[0], cell[2], cell[3])]
            for (a, b, cc) in tris:
                A, B, C = ((a[0], a[1], level), (b[0], b[1], level), (cc[0], cc[1], level))
                if sign > 0:
                    mesh.tri(A, B, C)
                else:
                    mesh.tri(A, C, B)


def slab(mesh, xs, ys, z0, z1, holes_top, xs_bot=None, ys_bot=None, holes_bot=None):
    """Axis-aligned box [xs[0],xs[-1]] x [ys[0],ys[-1]] x [z0,z1] whose top
    (and optionally bottom) face is a grid face with holes; side faces carry
    the grid vertices of both rims (no T-junctions)."""
    xb = xs_bot or [xs[0], xs[-1]]
    yb = ys_bot or [ys[0], ys[-1]]
    assert xb[0] == xs[0] and xb[-1] == xs[-1] and yb[0] == ys[0] and yb[-1] == ys[-1]
    grid_face(mesh, z1, +1, xs, ys, holes_top)
    grid_face(mesh, z0, -1, xb, yb, holes_bot or {})
    for (y, s) in ((ys[0], -1), (ys[-1], +1)):
        loop = [(x, y, z1) for x in xs] + [(x, y, z0) for x in reversed(xb)]
        face(mesh, loop, 1, s)
    for (x, s) in ((xs[0], -1), (xs[-1], +1)):
        loop = [(x, y, z1) for y in ys] + [(x, y, z0) for y in reversed(yb)]
        face(mesh, loop, 0, s)


def revolve(mesh, cx, cy, z0, n, profile, up=+1):
    """Solid of 'revolution' (n-gon rings) standing on the face z = z0
    (up = +1) or hanging from it (up = -1).  profile: [(r, h), ...] from the
    attachment ring (h = 0) to the last ring, which is closed by a fan around
    its centre.  Returns the attachment loop (CCW, 2D) for the hole."""
    rings = []
    for (r, h) in profile:
        rings.append([(x, y, z0 + up * h) for (x, y) in ngon(cx, cy, r, n)])
    for k in range(len(rings) - 1):
        (r0, h0), (r1, h1) = profile[k], profile[k + 1]
        dr, dh = r1 - r0, h1 - h0
        for i in range(n):
            a, b = rings[k][i], rings[k][(i + 1) % n]
            c, d = rings[k + 1][(i + 1) % n], rings[k + 1][i]
            mid = (a[0] + b[0] - 2 * cx, a[1] + b[1] - 2 * cy)
            # outward normal of the profile edge in the (radial, up) plane
            nr, nh = dh, -dr
            out = (nr * mid[0], nr * mid[1], up * nh * (abs(mid[0]) + abs(mid[1]) + 1))
            if nr == 0:
                out = (Fr(0), Fr(0), Fr(up * nh))
            mesh.quad_out(a, b, c, d, out)
    top = rings[-1]
    ctr = (cx, cy, top[0][2])
    for i in range(n):
        mesh.tri_out(ctr, top[i], top[(i + 1) % n], (0, 0, up))
    return [(p[0], p[1]) for p in rings[0]]


def box_on(mesh, x0, x1, y0, y1, z0, h, up=+1):
    """Box standing on (up=+1) or hanging from (up=-1) the face z = z0."""
    lo = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    z1 = z0 + up * h
    for i in range(4):
        a, b = lo[i], lo[(i + 1) % 4]
        mid = ((a[0] + b[0]) / 2 - (x0 + x1) / 2, (a[1] + b[1]) / 2 - (y0 + y1) / 2, 0)
        mesh.quad_out((a[0], a[1], z0), (b[0], b[1], z0), (b[0], b[1], z1), (a[0], a[1], z1), mid)
    face(mesh, [(x, y, z1) for (x, y) in lo], 2, up)
    return lo


def extrude(mesh, prof, axes, w0, w1, attach_edge):
    """Prism of the simple CCW profile prof (points (u, v)) extruded along w
    from w0 to w1.  axes = (iu, iv, iw): world axes of u, v, w (a
    permutation).  The profile edge attach_edge (index i: prof[i] ->
    prof[i+1]) lies in the face the prism is attached to and gets no wall.
    Returns the 3D corners of the attachment rectangle."""
    iu, iv, iw = axes
    assert sorted(axes) == [0, 1, 2]
    assert area2(prof) > 0

    def P(u, v, w):
        p = [None] * 3
        p[iu], p[iv], p[iw] = u, v, w
        return tuple(p)

    def vec(u, v, w):
        return P(Fr(u), Fr(v), Fr(w))
    n = len(prof)
    for i in range(n):
        if i == attach_edge:
            continue
        (u0, v0), (u1, v1) = prof[i], prof[(i + 1) % n]
        out = vec(v1 - v0, -(u1 - u0), 0)      # right of the edge: outside of a CCW profile
        mesh.quad_out(P(u0, v0, w0), P(u1, v1, w0), P(u1, v1, w1), P(u0, v0, w1), out)
    for (w, s) in ((w0, -1), (w1, +1)):
        face(mesh, [P(u, v, w) for (u, v) in prof], iw, s)
    (ua, va), (ub, vb) = prof[attach_edge], prof[(attach_edge + 1) % n]
    return [P(ua, va, w0), P(ub, vb, w0), P(ub, vb, w1), P(ua, va, w1)]


# ---------------------------------------------------------------------------
# Mesh checks (exact, integer coordinates in units of 1/UNIT)
# ---------------------------------------------------------------------------

def icoords(mesh):
    return [tuple(int(c * UNIT) for c in p) for p in mesh.verts]


def seg_hits_tri(p, q, a, b, c):
    """Closed segment pq meets closed triangle abc (exact, integers)."""
    n = cross(sub(b, a), sub(c, a))
    dp, dq = dot(n, sub(p, a)), dot(n, sub(q, a))
    if (dp > 0 and dq > 0) or (dp < 0 and dq < 0):
        return False
    if dp == 0 and dq == 0:                      # coplanar: 2D test
        ax = max(range(3), key=lambda i: abs(n[i]))
        P2 = [tuple(v[i] for i in range(3) if i != ax) for v in (p, q, a, b, c)]
        p2, q2, a2, b2, c2 = P2
        if orient2(a2, b2, c2) < 0:
            b2, c2 = c2, b2
        if in_closed_tri(p2, a2, b2, c2) or in_closed_tri(q2, a2, b2, c2):
            return True
        for (e0, e1) in ((a2, b2), (b2, c2), (c2, a2)):
            if segs_meet2(p2, q2, e0, e1):
                return True
        return False

    def vol(u, v, w, x):
        return dot(cross(sub(v, u), sub(w, u)), sub(x, u))
    s1, s2, s3 = vol(p, q, a, b), vol(p, q, b, c), vol(p, q, c, a)
    return (s1 >= 0 and s2 >= 0 and s3 >= 0) or (s1 <= 0 and s2 <= 0 and s3 <= 0)


def segs_meet2(p, q, r, s):
    o1, o2, o3, o4 = orient2(p, q, r), orient2(p, q, s), orient2(r, s, p), orient2(r, s, q)
    if ((o1 > 0 and o2 < 0) or (o1 < 0 and o2 > 0)) and ((o3 > 0 and o4 < 0) or (o3 < 0 and o4 > 0)):
        return True

    def on(a, b, x):
        return (orient2(a, b, x) == 0 and min(a[0], b[0]) <= x[0] <= max(a[0], b[0])
                and min(a[1], b[1]) <= x[1] <= max(a[1], b[1]))
    return on(p, q, r) or on(p, q, s) or on(r, s, p) or on(r, s, q)


def tris_meet(T1, T2):
    for (X, Y) in ((T1, T2), (T2, T1)):
        for k in range(3):
            if seg_hits_tri(X[k], X[(k + 1) % 3], Y[0], Y[1], Y[2]):
                return True
    return False


def tri_box(T):
    return (tuple(min(v[i] for v in T) for i in range(3)), tuple(max(v[i] for v in T) for i in range(3)))


def check_mesh(name, mesh):
    """All exact mesh checks; returns a dict of facts."""
    V = icoords(mesh)
    T = mesh.tris
    # non-degenerate
    for (a, b, c) in T:
        assert len({a, b, c}) == 3
        assert cross(sub(V[b], V[a]), sub(V[c], V[a])) != (0, 0, 0), "degenerate triangle"
    # closed, oriented, two-manifold at edges
    directed = defaultdict(int)
    for (a, b, c) in T:
        for (u, v) in ((a, b), (b, c), (c, a)):
            directed[(u, v)] += 1
    for (u, v), k in directed.items():
        assert k == 1, "directed edge used %d times" % k
        assert directed.get((v, u), 0) == 1, "edge without opposite half-edge (open or T-junction)"
    edges = [e for e in directed if e[0] < e[1]]
    assert 2 * len(edges) == 3 * len(T)
    used = {i for t in T for i in t}
    assert used == set(range(len(V))), "unused vertex"
    # components (union-find over edges)
    parent = list(range(len(V)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    for (u, v) in edges:
        parent[find(u)] = find(v)
    comps = defaultdict(list)
    for ti, t in enumerate(T):
        comps[find(t[0])].append(ti)
    vols = []
    cboxes = []
    for root, tis in sorted(comps.items(), key=lambda kv: min(kv[1])):
        vs = [V[i] for ti in tis for i in T[ti]]
        cboxes.append((tuple(min(p[k] for p in vs) for k in range(3)),
                       tuple(max(p[k] for p in vs) for k in range(3))))
        vol6 = sum(dot(V[T[ti][0]], cross(V[T[ti][1]], V[T[ti][2]])) for ti in tis)
        assert vol6 > 0, "component not outward oriented"
        vols.append(Fr(vol6, 6 * UNIT ** 3))
    # Euler characteristic per component (sphere: V - E + F = 2), information only
    genus = []
    for root, tis in sorted(comps.items(), key=lambda kv: min(kv[1])):
        vs = {i for ti in tis for i in T[ti]}
        es = {(min(u, v), max(u, v)) for ti in tis for (u, v) in
              ((T[ti][0], T[ti][1]), (T[ti][1], T[ti][2]), (T[ti][2], T[ti][0]))}
        chi = len(vs) - len(es) + len(tis)
        genus.append((2 - chi) // 2)
    # no vertex on the open interior of an edge (spatial hash of vertices)
    cellsz = UNIT // 100                          # 1 cm buckets
    vb = defaultdict(list)
    for i, p in enumerate(V):
        vb[tuple(c // cellsz for c in p)].append(i)
    for (u, v) in edges:
        lo = [min(V[u][i], V[v][i]) for i in range(3)]
        hi = [max(V[u][i], V[v][i]) for i in range(3)]
        d = sub(V[v], V[u])
        for bx in range(lo[0] // cellsz, hi[0] // cellsz + 1):
            for by in range(lo[1] // cellsz, hi[1] // cellsz + 1):
                for bz in range(lo[2] // cellsz, hi[2] // cellsz + 1):
                    for w in vb.get((bx, by, bz), ()):
                        if w == u or w == v:
                            continue
                        e = sub(V[w], V[u])
                        if cross(d, e) == (0, 0, 0) and 0 < dot(d, e) < dot(d, d):
                            raise AssertionError("vertex on an edge (T-junction)")
    # triangles without a common vertex are disjoint (closed sets)
    boxes = [tri_box([V[i] for i in t]) for t in T]
    tb = defaultdict(list)
    cs = UNIT // 50                               # 2 cm buckets
    for ti, (lo, hi) in enumerate(boxes):
        for bx in range(lo[0] // cs, hi[0] // cs + 1):
            for by in range(lo[1] // cs, hi[1] // cs + 1):
                for bz in range(lo[2] // cs, hi[2] // cs + 1):
                    tb[(bx, by, bz)].append(ti)
    seen = set()
    pairs = 0
    for lst in tb.values():
        for x in range(len(lst)):
            i = lst[x]
            for y in range(x + 1, len(lst)):
                j = lst[y]
                key = (i, j) if i < j else (j, i)
                if key in seen:
                    continue
                seen.add(key)
                if set(T[i]) & set(T[j]):
                    continue
                (l1, h1), (l2, h2) = boxes[i], boxes[j]
                if any(l1[k] > h2[k] or l2[k] > h1[k] for k in range(3)):
                    continue
                pairs += 1
                if tris_meet([V[k] for k in T[i]], [V[k] for k in T[j]]):
                    raise AssertionError("%s: triangles %d and %d intersect" % (name, i, j))
    # components: pairwise disjoint bounding boxes (so no component lies
    # inside another; surface disjointness is the triangle test above)
    for i in range(len(cboxes)):
        for j in range(i + 1, len(cboxes)):
            (l1, h1), (l2, h2) = cboxes[i], cboxes[j]
            assert any(l1[k] > h2[k] or l2[k] > h1[k] for k in range(3)), "component boxes overlap"
    return {"vertices": len(V), "triangles": len(T), "edges": len(edges),
            "components": len(comps), "volumes": vols, "genus": genus, "pairs": pairs}


def write_off(path, mesh):
    lines = ["OFF", "%d %d 0" % (len(mesh.verts), len(mesh.tris))]
    for p in mesh.verts:
        lines.append(" ".join(dec(c) for c in p))
    for t in mesh.tris:
        lines.append("3 %d %d %d" % t)
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


def read_off(path):
    """Exact re-read (the scene contract: coordinates are exact decimals)."""
    with open(path) as f:
        tok = f.read().split()
    assert tok[0] == "OFF"
    nv, nf = int(tok[1]), int(tok[2])
    pos = 4
    verts = []
    for _ in range(nv):
        verts.append(tuple(Fr(tok[pos + k]) for k in range(3)))
        pos += 3
    tris = []
    for _ in range(nf):
        assert tok[pos] == "3"
        tris.append(tuple(int(tok[pos + 1 + k]) for k in range(3)))
        pos += 4
    assert pos == len(tok)
    return verts, tris


# ---------------------------------------------------------------------------
# The gripper (body frame: fingertips at z = 0, jaw opening along x)
# ---------------------------------------------------------------------------

FINGER_TOP = D("0.07")       # fingers hang from the palm's bottom face
PALM = (D("-0.045"), D("0.045"), D("-0.025"), D("0.025"), D("0.07"), D("0.1"))
WRIST_N = 32


def finger_profile():
    """Right finger profile in the (x, z) plane, CCW, convex: inner face
    x = 0.015, rounded tip (radius 4 mm arcs in 30 degree steps), outer face
    tapering from x = 0.027 (above z = 0.035) to the tip (chamfer)."""
    inner = arc(D("0.019"), D("0.004"), D("0.004"), [180, 210, 240, 270])
    outer = arc(D("0.020"), D("0.004"), D("0.004"), [270, 300, 330, 350])
    prof = ([(D("0.015"), FINGER_TOP)] + inner + outer
            + [(D("0.027"), D("0.035")), (D("0.027"), FINGER_TOP)])
    n = len(prof)
    for i in range(n):
        assert orient2(prof[i - 1], prof[i], prof[(i + 1) % n]) > 0, "finger profile not strictly convex"
    return prof


def build_gripper():
    m = Mesh()
    x0, x1, y0, y1, z0, z1 = PALM
    fy0, fy1 = D("-0.01"), D("0.01")
    prof_r = finger_profile()
    # left finger: mirror x -> -x, reversed to stay CCW
    prof_l = [(-x, z) for (x, z) in reversed(prof_r)]
    # palm bottom grid: cells [0.011, 0.031] hold the finger roots
    xs_bot = [x0, D("-0.031"), D("-0.011"), D("0.011"), D("0.031"), x1]
    holes_bot = {}
    m.tag = "finger_right"
    # profile edge 0 of prof_r is from (0.015, top) down the inner face; the
    # attachment edge is the last one, (0.027, top) -> (0.015, top)
    extrude(m, prof_r, (0, 2, 1), fy0, fy1, len(prof_r) - 1)
    holes_bot[(3, 0)] = [(D("0.015"), fy0), (D("0.027"), fy0), (D("0.027"), fy1), (D("0.015"), fy1)]
    m.tag = "finger_left"
    extrude(m, prof_l, (0, 2, 1), fy0, fy1, prof_l.index((D("-0.015"), FINGER_TOP)))
    holes_bot[(1, 0)] = [(D("-0.027"), fy0), (D("-0.015"), fy0), (D("-0.015"), fy1), (D("-0.027"), fy1)]
    m.tag = "wrist"
    # wrist: 32-gon prism r = 20 mm, flange r = 30 mm with a 2 mm chamfer
    loop = revolve(m, D(0), D(0), z1, WRIST_N,
                   [(D("0.02"), D(0)), (D("0.02"), D("0.03")), (D("0.03"), D("0.03")),
                    (D("0.03"), D("0.05")), (D("0.028"), D("0.053"))])
    m.tag = "palm"
    slab(m, [x0, x1], [y0, y1], z0, z1, {(0, 0): loop},
         xs_bot=xs_bot, ys_bot=[y0, y1], holes_bot=holes_bot)
    return m


# ---------------------------------------------------------------------------
# The fixture (world frame, plate tops at z = 0)
# ---------------------------------------------------------------------------

XP, YP, ZP = D("0.06"), D("0.07"), D("0.008")     # pick pose of the gripper's body origin
PLATE_Z0 = D("-0.02")
POST_R, POST_H = D("0.005"), D("0.074")            # slot posts: 16-gon, r 5 mm, 1 mm chamfer
POST_YS = ("-0.15", "-0.12", "-0.09", "-0.06", "-0.03", "0")   # post rows, relative to YP
BACK_TOWER = (D("-0.195"), D("-0.17"), D("0.125"))  # rail-column tower behind the slot: y0, y1 (rel), height
# rest blocks between the fingers: y (relative to YP) and height
RESTS = (("-0.15", "0.02"), ("-0.12", "0.025"), ("-0.09", "0.02"), ("-0.03", "0.02"), ("0", "0.03"))


def pin(r, h, ch=D("0.001")):
    return [(r, D(0)), (r, h - ch), (r - ch, h)]


def stepped(R, h1, r, h2, ch=D("0.0015")):
    return [(R, D(0)), (R, h1), (r, h1), (r, h2 - ch), (r - ch, h2)]


def plate_A_features():
    """Main plate: the slot along y at x = XP (rail column: rest blocks between
    the fingers; two rows of posts outside the fingers) and its
    surroundings.  Each feature: (name, (kind, params...))."""
    F = []
    x = XP
    rel = lambda v: YP + D(v)
    for yr in POST_YS:
        for sx in (-1, 1):
            F.append(("post %s y%s" % ("right" if sx > 0 else "left", yr),
                      ("rev", x + sx * D("0.035"), rel(yr), 16, pin(POST_R, POST_H))))
    for yr, h in RESTS:
        F.append(("rest block y%s" % yr,
                  ("box", x - D("0.012"), x + D("0.012"), rel(yr) - D("0.01"), rel(yr) + D("0.01"), D(h))))
    F.append(("sensor y-0.06", ("rev", x, rel("-0.06"), 16, pin(D("0.006"), D("0.045"), D("0.002")))))
    y0, y1, h = BACK_TOWER
    F.append(("back tower", ("box", x - D("0.012"), x + D("0.012"), YP + y0, YP + y1, h)))
    F.append(("end stop", ("box", x - D("0.012"), x + D("0.012"), rel("0.029"), rel("0.045"), D("0.09"))))
    # towers beside the slot, 4 mm from the palm's sides
    F.append(("tower right", ("box", x + D("0.049"), x + D("0.07"), rel("-0.07"), rel("-0.05"), D("0.15"))))
    F.append(("tower left", ("box", x - D("0.07"), x - D("0.049"), rel("-0.01"), rel("0.01"), D("0.13"))))
    # low pins in the post columns beyond the end stop
    F.append(("low pin right", ("rev", x + D("0.035"), rel("0.045"), 16, pin(D("0.005"), D("0.03")))))
    F.append(("hex pin left", ("rev", x - D("0.035"), rel("0.045"), 6, pin(D("0.007"), D("0.012"), D("0.0005")))))
    return F


def clutter(xs, ys, skip, seed):
    """Deterministic clutter: one feature per free cell, kind by a fixed
    rotation, sized to the cell with >= 4 mm margins."""
    kinds = ["stepped", "pin", "clamp", "box", "vblock", "hex", "pin", "box", "clampy", "box"]
    F = []
    k = seed
    for i in range(len(xs) - 1):
        for j in range(len(ys) - 1):
            if (i, j) in skip:
                continue
            ax, bx, ay, by = xs[i], xs[i + 1], ys[j], ys[j + 1]
            cx, cy = (ax + bx) / 2, (ay + by) / 2
            w, d = bx - ax, by - ay
            s = min(w, d)
            kind = kinds[k % len(kinds)]
            name = "%s cell %d,%d" % (kind, i, j)
            hvar = D(k % 5) / 100          # 0 .. 0.04
            k += 1
            if kind == "stepped":
                R = snap(s * D("0.3"))
                prof = stepped(R, D("0.012"), snap(R * D("0.55")), D("0.04") + hvar)
                F.append((name, ("rev", cx, cy, 20, prof)))
            elif kind == "pin":
                r = snap(s * D("0.2"))
                F.append((name, ("rev", cx, cy, 16, pin(r, D("0.03") + 2 * hvar))))
            elif kind == "hex":
                r = snap(s * D("0.25"))
                F.append((name, ("rev", cx, cy, 6, pin(r, D("0.014"), D("0.0008")))))
            elif kind == "box":
                F.append((name, ("box", snap(ax + w / 5), snap(bx - w / 5), snap(ay + d / 4), snap(by - d / 4),
                                 D("0.025") + hvar)))
            elif kind in ("clamp", "clampy"):
                F.append((name, ("clamp", ax, bx, ay, by, D("0.05") + hvar, kind == "clampy")))
            elif kind == "vblock":
                F.append((name, ("vblock", ax, bx, ay, by, D("0.03"))))
    return F


def clamp_profile(a, b, H):
    """L-shaped clamp in (u, v): pillar [a + m, a + m + p] x [0, H], arm to
    b - m at heights [H - 10 mm, H].  Non-convex."""
    m = D("0.004")
    L = b - a - 2 * m
    p = snap(L * D("0.35"))
    u0, u1, u2 = a + m, a + m + p, b - m
    t = D("0.01")
    return [(u0, D(0)), (u1, D(0)), (u1, H - t), (u2, H - t), (u2, H), (u0, H)]


def vblock_profile(a, b, H):
    m = D("0.004")
    u0, u1 = a + m, b - m
    c = (u0 + u1) / 2
    dv = snap((u1 - u0) * D("0.3"))
    return [(u0, D(0)), (u1, D(0)), (u1, H), (c + dv, H), (c, H - dv), (c - dv, H), (u0, H)]


def build_plate(m, xs, ys, features, tag):
    """One plate (slab from PLATE_Z0 to 0) with its features standing on it.
    Every feature's footprint lies strictly inside one grid cell; each cell
    holds at most one feature."""
    m.tag = tag
    holes = {}

    def cell_of(loop):
        lx, hx = min(p[0] for p in loop), max(p[0] for p in loop)
        ly, hy = min(p[1] for p in loop), max(p[1] for p in loop)
        cand = [(i, j) for i in range(len(xs) - 1) for j in range(len(ys) - 1)
                if xs[i] < lx and hx < xs[i + 1] and ys[j] < ly and hy < ys[j + 1]]
        assert len(cand) == 1, "footprint not inside one cell"
        assert cand[0] not in holes, "two features in one cell"
        return cand[0]
    for fname, f in features:
        m.tag = tag + " " + fname
        kind = f[0]
        if kind == "rev":
            _, cx, cy, n, prof = f
            loop = revolve(m, cx, cy, D(0), n, prof)
            holes[cell_of(loop)] = loop
        elif kind == "box":
            _, x0, x1, y0, y1, h = f
            loop = box_on(m, x0, x1, y0, y1, D(0), h)
            holes[cell_of(loop)] = loop
        elif kind in ("clamp", "vblock"):
            _, ax, bx, ay, by, H = f[:6]
            along_y = f[6] if kind == "clamp" else False
            if kind == "clamp":
                prof = clamp_profile(ay, by, H) if along_y else clamp_profile(ax, bx, H)
            else:
                prof = vblock_profile(ax, bx, H)
            mw = D("0.006")
            if along_y:      # profile in (y, z), extruded along x
                rect = extrude(m, prof, (1, 2, 0), ax + mw, bx - mw, 0)
            else:            # profile in (x, z), extruded along y
                rect = extrude(m, prof, (0, 2, 1), ay + mw, by - mw, 0)
            loop2 = [(p[0], p[1]) for p in rect]
            if area2(loop2) < 0:
                loop2 = loop2[::-1]
            holes[cell_of(loop2)] = loop2
        else:
            raise ValueError(kind)
    m.tag = tag
    slab(m, xs, ys, PLATE_Z0, D(0), holes)


def build_fixture():
    m = Mesh()
    # plate A: the slot plate
    xa = [D(v) for v in ("-0.08", "-0.02", "0.014", "0.044", "0.076", "0.106", "0.14", "0.2")]
    # rows relative to YP: -0.23 -0.2 -0.165 -0.135 -0.105 -0.075 -0.045 -0.015 0.015 0.06 0.09
    ya = [D(v) for v in ("-0.16", "-0.13", "-0.095", "-0.065", "-0.035", "-0.005", "0.025", "0.055",
                         "0.085", "0.13", "0.16")]
    FA = plate_A_features()
    # cells reserved for the slot (columns 1..5, rows 1..8): only the slot
    # features above go there
    used = set()
    for i in range(1, 6):
        for j in range(1, 9):
            used.add((i, j))
    FA += clutter(xa, ya, used, 0)
    build_plate(m, xa, ya, FA, "plate_A")
    # plate B: left of plate A, 10 mm gap
    xb = [D(v) for v in ("-0.26", "-0.205", "-0.15", "-0.09")]
    yb = [D(v) for v in ("-0.16", "-0.1", "-0.04", "0.02", "0.08", "0.16")]
    build_plate(m, xb, yb, clutter(xb, yb, set(), 3), "plate_B")
    # plate C: behind both, 10 mm gap
    xc = [D(v) for v in ("-0.26", "-0.2", "-0.14", "-0.08", "-0.02", "0.04", "0.1", "0.16", "0.2")]
    yc = [D(v) for v in ("0.17", "0.23", "0.28")]
    build_plate(m, xc, yc, clutter(xc, yc, set(), 6), "plate_C")
    return m


# ---------------------------------------------------------------------------
# Motion: pure translation d(t), a rational cubic Bezier curve
# ---------------------------------------------------------------------------

# control points of d relative to the pick pose (XP, YP, ZP), and weights
PATH_REL = [(D(0), D("-0.17"), D("0.16")),
            (D(0), D("-0.15"), D(0)),
            (D(0), D("-0.05"), D(0)),
            (D(0), D(0), D(0))]
WEIGHTS = [Fr(1), Fr(2), Fr(2), Fr(1)]
COLLISION_SHIFT = (D("0.006"), D(0), D(0))        # added to the last control point
CLEARANCE = D("0.003")
EPSILON = Fr(1, 2000)


def path_points(collide):
    pts = [(XP + p[0], YP + p[1], ZP + p[2]) for p in PATH_REL]
    if collide:
        pts[-1] = add(pts[-1], COLLISION_SHIFT)
    return pts


def homog(pts, ws):
    return [tuple(w * c for c in p) + (w,) for p, w in zip(pts, ws)]


def split(H, s):
    """de Casteljau split of homogeneous control points at s: (left, right)."""
    left, right = [H[0]], [H[-1]]
    cur = list(H)
    while len(cur) > 1:
        cur = [tuple((1 - s) * a + s * b for a, b in zip(cur[i], cur[i + 1])) for i in range(len(cur) - 1)]
        left.append(cur[0])
        right.append(cur[-1])
    return left, right[::-1]


def piece(H, t0, t1):
    """Homogeneous control points of the curve restricted to [t0, t1]."""
    if t1 < 1:
        H, _ = split(H, t1)
    if t0 > 0:
        _, H = split(H, t0 / t1)
    return H


def eval_d(pts, ws, t):
    n = len(pts) - 1
    B = [comb(n, i) * t ** i * (1 - t) ** (n - i) * ws[i] for i in range(n + 1)]
    W = sum(B)
    return tuple(sum(B[i] * pts[i][k] for i in range(n + 1)) / W for k in range(3))


def part_boxes(mesh):
    boxes = {}
    for t, tag in zip(mesh.tris, mesh.tags):
        for i in t:
            p = mesh.verts[i]
            lo, hi = boxes.get(tag, (p, p))
            boxes[tag] = (tuple(min(a, b) for a, b in zip(lo, p)), tuple(max(a, b) for a, b in zip(hi, p)))
    return boxes


class ClearanceProof:
    """Box-sweep proof: gripper part boxes swept by the control-point box of
    each parameter piece, against fixture triangle boxes."""

    def __init__(self, gripper, fixture):
        self.parts = part_boxes(gripper)
        self.ftag = fixture.tags
        self.fbox = [tri_box([fixture.verts[i] for i in t]) for t in fixture.tris]
        self.fbox_int = [(tuple(int(c * UNIT) for c in lo), tuple(int(c * UNIT) for c in hi))
                         for (lo, hi) in self.fbox]

    def piece_ok(self, H, m2, strict, stats):
        pts = [tuple(h[k] / h[3] for k in range(3)) for h in H]
        dlo = tuple(min(p[k] for p in pts) for k in range(3))
        dhi = tuple(max(p[k] for p in pts) for k in range(3))
        worst = None
        near = {}
        m2i = m2 * UNIT * UNIT
        for tag, (plo, phi) in sorted(self.parts.items()):
            slo = tuple(a + b for a, b in zip(plo, dlo))
            shi = tuple(a + b for a, b in zip(phi, dhi))
            # integer outward rounding for the fast filter
            sloi = tuple((c * UNIT).__floor__() for c in slo)
            shii = tuple((c * UNIT).__ceil__() for c in shi)
            for ti, (lo, hi) in enumerate(self.fbox_int):
                g = 0
                for k in range(3):
                    e = max(lo[k] - shii[k], sloi[k] - hi[k], 0)
                    g += e * e
                if g >= 4 * m2i and g > 0:
                    continue               # certainly >= 2 * margin away
                flo, fhi = self.fbox[ti]
                sq = sum(max(flo[k] - shi[k], slo[k] - fhi[k], 0) ** 2 for k in range(3))
                stats["exact"] += 1
                if worst is None or sq < worst[0]:
                    worst = (sq, tag, ti)
                key = (self.ftag[ti], tag)
                if key not in near or sq < near[key]:
                    near[key] = sq
                if (strict and sq == 0) or sq < m2:
                    return False, worst
        for key, sq in near.items():
            if key not in stats["near"] or sq < stats["near"][key]:
                stats["near"][key] = sq
        return True, worst

    def prove(self, H, t0, t1, m2, strict, stats, depth=0, max_depth=12):
        ok, worst = self.piece_ok(H, m2, strict, stats)
        if ok:
            stats["pieces"] += 1
            if worst is not None and (stats["worst"] is None or worst[0] < stats["worst"][0]):
                stats["worst"] = (worst[0], worst[1], worst[2], t0, t1)
            return True
        if depth >= max_depth:
            stats["failed"] = (t0, t1, worst)
            return False
        L, R = split(H, Fr(1, 2))
        tm = (t0 + t1) / 2
        return (self.prove(L, t0, tm, m2, strict, stats, depth + 1, max_depth)
                and self.prove(R, tm, t1, m2, strict, stats, depth + 1, max_depth))


def crossing_witness(gripper, fixture, d, simplest=False):
    """An edge of one body crossing the open interior of a triangle of the
    other transversally, with the gripper translated by d (exact).  The
    first one found, or with simplest=True the one whose point has the
    smallest denominators."""
    best = None
    G = [add(p, d) for p in gripper.verts]
    Fv = fixture.verts
    gbox = [tri_box([G[i] for i in t]) for t in gripper.tris]
    lo = tuple(min(b[0][k] for b in gbox) for k in range(3))
    hi = tuple(max(b[1][k] for b in gbox) for k in range(3))
    fcand = [fi for fi, t in enumerate(fixture.tris)
             if all(min(Fv[i][k] for i in t) <= hi[k] and max(Fv[i][k] for i in t) >= lo[k] for k in range(3))]
    for gi, gt in enumerate(gripper.tris):
        (glo, ghi) = gbox[gi]
        for fi in fcand:
            ft = fixture.tris[fi]
            FT = [Fv[i] for i in ft]
            flo, fhi = tri_box(FT)
            if any(flo[k] > ghi[k] or glo[k] > fhi[k] for k in range(3)):
                continue
            GT = [G[i] for i in gt]
            for (X, Y, who) in ((GT, FT, "gripper"), (FT, GT, "fixture")):
                for k in range(3):
                    p, q = X[k], X[(k + 1) % 3]
                    x = proper_crossing(p, q, Y)
                    if x is not None:
                        w = {"gripper_triangle": gi, "fixture_triangle": fi, "edge_of": who,
                             "edge": k, "point": x, "segment": (p, q)}
                        if not simplest:
                            return w
                        size = max(c.denominator for c in x)
                        if best is None or size < best[0]:
                            best = (size, w)
    return best[1] if best else None


def proper_crossing(p, q, Y):
    a, b, c = Y
    n = cross(sub(b, a), sub(c, a))
    dp, dq = dot(n, sub(p, a)), dot(n, sub(q, a))
    if not (dp * dq < 0):
        return None
    x = tuple(pp + dp / (dp - dq) * (qq - pp) for pp, qq in zip(p, q))
    if all(dot(cross(sub(Y[(j + 1) % 3], Y[j]), sub(x, Y[j])), n) > 0 for j in range(3)):
        return x
    return None


# ---------------------------------------------------------------------------
# Scenes
# ---------------------------------------------------------------------------

def write_scene(path, pts, ws):
    lines = []
    lines.append("{")
    lines.append('  "format": "tmcert-scene/1",')
    lines.append('  "epsilon": "%s",' % EPSILON)
    lines.append('  "bodies": [')
    lines.append('    { "name": "fixture", "mesh": "fixture.off" },')
    lines.append('    { "name": "gripper", "mesh": "gripper.off",')
    lines.append('      "motion": {')
    lines.append('        "type": "rational_bezier",')
    lines.append('        "interval": [0, 1],')
    lines.append('        "control_points": [')
    cps = []
    for p in pts:
        cps.append("          [[1, 0, 0, %s], [0, 1, 0, %s], [0, 0, 1, %s]]" % tuple(dec(c) for c in p))
    lines.append(",\n".join(cps))
    lines.append("        ],")
    lines.append('        "weights": [' + ", ".join(dec(w) for w in ws) + "] } }")
    lines.append("  ],")
    lines.append('  "checks": [ ["gripper", "fixture"] ]')
    lines.append("}")
    text = "\n".join(lines) + "\n"
    json.loads(text)
    with open(path, "w", newline="\n") as f:
        f.write(text)


def read_scene_motion(path):
    with open(path) as f:
        doc = json.loads(f.read(), parse_float=Fr, parse_int=Fr)
    body = [b for b in doc["bodies"] if b["name"] == "gripper"][0]
    mot = body["motion"]
    pts = []
    for M in mot["control_points"]:
        M = [[Fr(x) for x in row] for row in M]
        assert [row[:3] for row in M] == [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "linear part not identity"
        pts.append(tuple(row[3] for row in M))
    ws = [Fr(w) for w in mot["weights"]]
    return pts, ws


# ---------------------------------------------------------------------------
# Main
# ---------------------------------------------------------------------------

def num(x):
    """Short decimal if there is one, else p/q."""
    try:
        return dec(x)
    except ValueError:
        return str(Fr(x))


def mm(x):
    return "%.4f mm" % (float(x) * 1000)


def main():
    ok = True
    gripper = build_gripper()
    fixture = build_fixture()
    for name, mesh, rng in (("gripper", gripper, (300, 800)), ("fixture", fixture, (2000, 6000))):
        path = os.path.join(HERE, name + ".off")
        write_off(path, mesh)
        verts, tris = read_off(path)
        assert verts == mesh.verts and tris == mesh.tris, "OFF round trip"
        facts = check_mesh(name, mesh)
        lo = tuple(min(p[k] for p in mesh.verts) for k in range(3))
        hi = tuple(max(p[k] for p in mesh.verts) for k in range(3))
        print("%s.off: %d triangles, %d vertices, %d edges, %d component(s), genus %s, "
              "volume(s) %s m^3; closed, oriented, no T-junctions, non-degenerate; "
              "%d non-adjacent close triangle pairs disjoint"
              % (name, facts["triangles"], facts["vertices"], facts["edges"], facts["components"],
                 facts["genus"], ", ".join("%.6g" % float(v) for v in facts["volumes"]), facts["pairs"]))
        print("    bounding box %s .. %s" % (tuple(dec(c) for c in lo), tuple(dec(c) for c in hi)))
        if not rng[0] <= facts["triangles"] <= rng[1]:
            print("  FAIL: triangle count outside %s" % (rng,))
            ok = False
        counts = defaultdict(int)
        for tg in mesh.tags:
            counts[tg.split()[0]] += 1
        print("    triangles per %s: %s" % ("part" if name == "gripper" else "plate (component)",
                                            ", ".join("%s %d" % kv for kv in sorted(counts.items()))))
        if name == "fixture":
            print("    component bounding boxes pairwise disjoint")
    # --- scenes ---
    proof = ClearanceProof(gripper, fixture)
    for tag, (lo, hi) in sorted(proof.parts.items()):
        print("    gripper part %-13s box %s .. %s" % (tag, tuple(dec(c) for c in lo), tuple(dec(c) for c in hi)))
    for key in ("safe", "collision"):
        path = os.path.join(HERE, "gripper-%s.json" % key)
        write_scene(path, path_points(key == "collision"), WEIGHTS)
        pts, ws = read_scene_motion(path)
        assert pts == path_points(key == "collision") and ws == WEIGHTS, "scene round trip"
        assert all(w > 0 for w in ws)
        H = homog(pts, ws)
        if key == "safe":
            stats = {"pieces": 0, "exact": 0, "worst": None, "failed": None, "near": {}}
            good = proof.prove(H, Fr(0), Fr(1), CLEARANCE ** 2, False, stats)
            if not good:
                print("  FAIL: clearance proof failed on %s" % (stats["failed"],))
                ok = False
                continue
            sq, tag, ti, t0, t1 = stats["worst"]
            print("gripper-safe.json: PROVEN clearance >= %s for all t in [0, 1] (%d parameter pieces, "
                  "%d exact box distances); smallest box distance^2 = %s m^2 (%s), gripper %s vs "
                  "fixture triangle %d, t in [%s, %s]"
                  % (mm(CLEARANCE), stats["pieces"], stats["exact"], sq, mm(float(sq) ** 0.5), tag, ti, t0, t1))
            # exact attained distance at t = 1: right finger outer face vs the
            # post at y = YP (its 16-gon vertex at angle 180 deg, x = XP + 0.03)
            d1 = eval_d(pts, ws, Fr(1))
            a = add((D("0.027"), D(0), D("0.05")), d1)           # on the finger's outer face
            b = (XP + D("0.035") - POST_R, YP, a[2])               # on the post's vertical edge
            assert a[2] <= POST_H
            assert point_on_mesh(gripper, sub(a, d1)) and point_on_mesh(fixture, b)
            dist2 = dot(sub(a, b), sub(a, b))
            assert dist2 == CLEARANCE ** 2
            print("    at t = 1 the gripper point %s and the fixture point %s are exactly %s apart:"
                  % (tuple(dec(c) for c in a), tuple(dec(c) for c in b), mm(CLEARANCE)))
            print("    the minimum clearance over the motion is exactly %s" % mm(CLEARANCE))
            # lower bounds per fixture feature (from the accepted pieces)
            per = {}
            for (ftag, part), sq in stats["near"].items():
                if ftag not in per or sq < per[ftag][0]:
                    per[ftag] = (sq, part)
            close = sorted((sq, ftag, part) for (ftag, part), sq in stats["near"].items()
                           if sq < 4 * CLEARANCE ** 2)
            print("    proven lower bounds below %s (all other features: >= %s):"
                  % (mm(2 * CLEARANCE), mm(2 * CLEARANCE)))
            for sq, ftag, part in close:
                print("      %-32s vs %-13s >= %s" % (ftag, part, mm(float(sq) ** 0.5)))
            # the fingers pass the slot posts and rest blocks at exactly 3 mm
            passes = exact_passes(gripper, fixture, pts, ws)
            print("    exactly %s (surface points verified on both meshes) at grid times t = k/256:"
                  % mm(CLEARANCE))
            for name, (ta, tb) in passes:
                print("      %-24s t in [%s, %s]" % (name, ta, tb))
            if len(passes) < 8:
                print("  FAIL: fewer near passes than designed")
                ok = False
            # information (floating point, sampled): the time-dependent distance
            # between the palm's lower back edge and the back tower's upper front
            # edge (they overlap in x), as the palm descends past the tower
            best = None
            px = proof.parts["palm"]
            fp, fw = [tuple(float(c) for c in p) for p in pts], [float(w) for w in ws]
            for k in range(0, 20001):
                t = k / 20000
                B = [comb(3, i) * t ** i * (1 - t) ** (3 - i) * fw[i] for i in range(4)]
                dd = [sum(B[i] * fp[i][c] for i in range(4)) / sum(B) for c in range(3)]
                dy = max(0.0, float(px[0][1]) + dd[1] - float(YP + BACK_TOWER[1]))
                dz = max(0.0, float(px[0][2]) + dd[2] - float(BACK_TOWER[2]))
                dist = (dy * dy + dz * dz) ** 0.5
                if best is None or dist < best[0]:
                    best = (dist, t)
            print("    (sampled, t = k/20000: the palm passes the back tower at %s, near t = %.4f; "
                  "proven >= the bound listed above)" % (mm(best[0]), best[1]))
        else:
            d1 = eval_d(pts, ws, Fr(1))
            wit = crossing_witness(gripper, fixture, d1, simplest=True)
            if wit is None:
                print("  FAIL: no exact witness at t = 1")
                ok = False
                continue
            gi, fi = wit["gripper_triangle"], wit["fixture_triangle"]
            GT = [add(gripper.verts[i], d1) for i in gripper.tris[gi]]
            FT = [fixture.verts[i] for i in fixture.tris[fi]]
            # re-check the witness from scratch: the point is on the segment and
            # strictly inside the other triangle
            x = wit["point"]
            p, q = wit["segment"]
            Y = FT if wit["edge_of"] == "gripper" else GT
            assert proper_crossing(p, q, Y) == x
            print("gripper-collision.json: at t = 1 an edge of %s triangle %d (%s) crosses the interior of "
                  "%s triangle %d (%s) at the exact point"
                  % (wit["edge_of"], gi if wit["edge_of"] == "gripper" else fi,
                     gripper.tags[gi] if wit["edge_of"] == "gripper" else fixture.tags[fi],
                     "fixture" if wit["edge_of"] == "gripper" else "gripper",
                     fi if wit["edge_of"] == "gripper" else gi,
                     fixture.tags[fi] if wit["edge_of"] == "gripper" else gripper.tags[gi]))
            print("      (%s)" % ", ".join(num(c) for c in x))
            print("    edge (%s) -> (%s)" % (", ".join(num(c) for c in p), ", ".join(num(c) for c in q)))
            print("    triangle %s" % (", ".join("(%s)" % ", ".join(num(c) for c in v) for v in Y)))
            # second contact at t = 1: the left finger's inner face meets the top
            # face of the rest block at y = YP (a common point of both meshes)
            h0 = D(dict(RESTS)["0"])
            c = (XP - D("0.015") + COLLISION_SHIFT[0], YP, h0)
            assert point_on_mesh(gripper, sub(c, d1)) and point_on_mesh(fixture, c)
            print("    and the point (%s) lies on both meshes (left finger inner face, top of rest block y0)"
                  % ", ".join(num(v) for v in c))
            # earliest k/64 from which on every grid time has a witness
            first = Fr(1)
            for k in range(63, 0, -1):
                t = Fr(k, 64)
                w2 = crossing_witness(gripper, fixture, eval_d(pts, ws, t))
                if w2 is None:
                    break
                first = t
            print("    exact witnesses at every t = k/64 in [%s, 1]" % first)
            # certified contact-free prefix
            T = None
            for k in range(64, 0, -1):
                t1 = Fr(k, 64)
                if t1 >= first:
                    continue
                stats = {"pieces": 0, "exact": 0, "worst": None, "failed": None, "near": {}}
                if proof.prove(piece(H, Fr(0), t1), Fr(0), t1, Fr(0), True, stats, max_depth=8):
                    T = t1
                    break
            print("    box proof: no contact for t in [0, %s]; first contact in (%s, %s]" % (T, T, first))
            if T is None:
                ok = False
    with open(os.path.join(HERE, "EXPECTED"), "w", newline="\n") as f:
        f.write("gripper-safe.json\tsafe\ngripper-collision.json\tcollision\n")
    if not ok:
        print("SELF-CHECK FAILED")
        return 1
    print("all self-checks passed")
    return 0


def exact_passes(gripper, fixture, pts, ws):
    """For each slot post and rest block, the grid times t = k/256 at which a
    finger surface point and a point of that feature are exactly CLEARANCE
    apart (same y and z, x differing by CLEARANCE), both verified to lie on
    the meshes."""
    feats = []
    for yr in POST_YS:
        for sx in (-1, 1):
            # finger outer face x = +-0.027, y in [-0.01, 0.01], z in [0.035, 0.07];
            # post edge x = XP +- 0.030, y = yc, z in [0, POST_H - 0.001]
            feats.append(("post %s y%s" % ("right" if sx > 0 else "left", yr), sx, D("0.027"), D("0.03"),
                          YP + D(yr), YP + D(yr), D("0.035"), POST_H - D("0.001")))
    for yr, h in RESTS:
        for sx in (-1, 1):
            # finger inner face x = +-0.015, z in [0.004, 0.07]; block face x = XP +- 0.012
            feats.append(("rest block y%s (%s finger)" % (yr, "right" if sx > 0 else "left"), sx, D("0.015"),
                          D("0.012"), YP + D(yr) - D("0.01"), YP + D(yr) + D("0.01"), D("0.004"), D(h)))
    out = []
    for (name, sx, xg, xf, ylo, yhi, zg0, zfh) in feats:
        hits = []
        for k in range(257):
            t = Fr(k, 256)
            d = eval_d(pts, ws, t)
            y = max(d[1] - D("0.01"), ylo)
            if y > min(d[1] + D("0.01"), yhi):
                continue
            z = max(d[2] + zg0, D(0))
            if z > min(d[2] + D("0.07"), zfh):
                continue
            a = (XP + sx * xg, y, z)
            b = (XP + sx * xf, y, z)
            if not hits or hits[-1] != Fr(k - 1, 256):       # verify the first of each run
                assert point_on_mesh(gripper, sub(a, d)) and point_on_mesh(fixture, b), name
            assert dot(sub(a, b), sub(a, b)) == CLEARANCE ** 2
            hits.append(t)
        if hits:
            out.append((name, (hits[0], hits[-1])))
    return out


def point_on_mesh(mesh, p):
    """p lies on some triangle of the mesh (exact)."""
    for t in mesh.tris:
        a, b, c = (mesh.verts[i] for i in t)
        n = cross(sub(b, a), sub(c, a))
        if dot(n, sub(p, a)) != 0:
            continue
        if all(dot(cross(sub(Y1, Y0), sub(p, Y0)), n) >= 0 for (Y0, Y1) in ((a, b), (b, c), (c, a))):
            return True
    return False


if __name__ == "__main__":
    sys.exit(main())
