#!/usr/bin/env python3
"""Writes the continuous-collision query files of this folder, in the
rational CSV format of the large CCD benchmark (Wang et al. 2021; see
scripts/ccd_csv_to_scene.py), with ground truth known by construction:

  vertex-face/queries.csv  truth in the seventh column
  edge-edge/queries.csv    truth in edge-edge/mma_bool.json

Constructions (every number an exact rational; coplanarity of the four
points is linear in t under a common translation, so a relative motion
that is a translation has one coplanar instant, placed at a known time):
contacts at t = 1/2, 1/4, 3/4, 0 and 1 inside, on an edge, at a vertex;
coplanar sliding; a deforming triangle whose point meets it at t = 1/2;
misses at the coplanar instant (outside by 1/4 or by 2^-20), parallel
motion at distance 2^-10, far apart. Each is also written scaled by the
double nearest 0.1 and translated by the double nearest 12345.678 (a
similarity: the truth is unchanged), as the benchmark's data are doubles.
Run it from anywhere; it rewrites the three files next to it.
"""
import json
import os
from fractions import Fraction as F

HERE = os.path.dirname(os.path.abspath(__file__))
SCALE = F(0.1)            # exactly the double 0.1
SHIFT = F(12345.678)      # exactly the double 12345.678


def add(a, b): return tuple(x + y for x, y in zip(a, b))
def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def mul(s, a): return tuple(s * x for x in a)
def comb(ws, ps): return tuple(sum(w * p[i] for w, p in zip(ws, ps)) for i in range(3))


def vf_query(tri0, tri_velocity, bary, tc, w, velocities=None):
    """Point p crossing the triangle's plane at time tc at barycentric `bary`
    of the triangle T(tc), moving with velocity w; the triangle translates by
    tri_velocity (or each vertex by its own velocity)."""
    vel = velocities or [tri_velocity] * 3
    tri1 = [add(v, u) for v, u in zip(tri0, vel)]
    at_tc = [add(v, mul(tc, u)) for v, u in zip(tri0, vel)]
    c = comb(bary, at_tc)
    p0 = sub(c, mul(tc, w))
    p1 = add(p0, w)
    return [p0] + tri0 + [p1] + tri1


def ee_query(a, va, b_rel, vb, tc):
    """Edge a (two points at t = 0) translating by va; edge b translating by
    vb and placed at time tc at b_rel in a's frame (b_rel + tc va)."""
    b0 = [sub(add(x, mul(tc, va)), mul(tc, vb)) for x in b_rel]
    return [a[0], a[1], b0[0], b0[1], add(a[0], va), add(a[1], va), add(b0[0], vb), add(b0[1], vb)]


def similar(q):
    return [add(mul(SCALE, v), (SHIFT, -SHIFT, SHIFT / 2)) for v in q]


tri = [(F(0), F(0), F(0)), (F(1), F(0), F(0)), (F(0), F(1), F(0))]
up = (F(0), F(0), F(1))
slide = (F(1, 8), F(-1, 16), F(0))
vf = [
    (vf_query(tri, slide, (F(1, 4), F(1, 4), F(1, 2)), F(1, 2), (F(1, 8), F(0), F(-2))), True),   # crossing inside
    (vf_query(tri, slide, (F(1, 2), F(1, 2), F(0)), F(1, 4), (F(0), F(1, 16), F(-1))), True),      # on an edge
    (vf_query(tri, slide, (F(1), F(0), F(0)), F(3, 4), (F(0), F(0), F(1))), True),                 # at a vertex
    (vf_query(tri, slide, (F(1, 4), F(1, 2), F(1, 4)), F(0), (F(0), F(0), F(1))), True),           # at t = 0
    (vf_query(tri, slide, (F(1, 4), F(1, 2), F(1, 4)), F(1), (F(1, 4), F(0), F(-1))), True),       # at t = 1
    (vf_query(tri, (F(0),) * 3, (F(1, 8), F(1, 8), F(3, 4)), F(1, 2), (F(1, 4), F(-1, 4), F(0))), True),  # coplanar sliding
    (vf_query(tri, slide, (F(1, 4), F(1, 4), F(1, 2)), F(1, 2), (F(0), F(0), F(-1)),
              velocities=[(F(0), F(0), F(1, 2)), (F(1, 4), F(0), F(-1, 4)), (F(0), F(-1, 8), F(1, 8))]), True),  # deforming
    (vf_query(tri, slide, (F(-1, 4), F(1, 4), F(1)), F(1, 2), (F(0), F(0), F(-2))), False),        # outside by 1/4
    (vf_query(tri, slide, (-F(1, 2**20), F(1, 2), F(1, 2) + F(1, 2**20)), F(1, 3), (F(0), F(0), F(-1))), False),  # miss by 2^-20
    ([add(tri[0], (F(1, 4), F(1, 4), F(1, 1024)))] + tri + [add(tri[0], (F(1, 2), F(1, 4), F(1, 1024)))] + tri, False),  # parallel
    ([(F(5), F(5), F(5))] + tri + [(F(6), F(5), F(4))] + [add(v, slide) for v in tri], False),       # far apart
]
seg_a = [(F(0), F(0), F(0)), (F(1), F(0), F(0))]
va = (F(0), F(1, 8), F(0))
ee = [
    (ee_query(seg_a, va, [(F(1, 4), F(-1, 2), F(-1, 2)), (F(1, 4), F(1, 2), F(1, 2))], (F(0), F(0), F(1)), F(1, 2)), True),
    (ee_query(seg_a, va, [(F(1, 2), F(0), F(0)), (F(1, 2), F(1), F(1))], (F(1, 4), F(0), F(-1)), F(0)), True),       # end on edge at t = 0
    (ee_query(seg_a, va, [(F(1), F(0), F(0)), (F(1), F(1), F(1))], (F(0), F(0), F(1)), F(1)), True),       # end on end at t = 1
    (ee_query(seg_a, (F(0),) * 3, [(F(1, 2), F(0), F(0)), (F(3, 2), F(0), F(0))], (F(1, 4), F(0), F(0)), F(1, 2)), True),  # collinear overlap
    (ee_query(seg_a, va, [(F(3, 4), F(-1, 2), F(1, 4)), (F(3, 4), F(1, 2), F(-1, 4))], (F(0), F(0), F(-1, 2)), F(3, 4)), True),
    (ee_query(seg_a, va, [(F(5, 4), F(-1, 2), F(-1, 2)), (F(5, 4), F(1, 2), F(1, 2))], (F(0), F(0), F(1)), F(1, 2)), False),  # beyond the end
    (ee_query(seg_a, va, [(F(1, 4), F(-1, 2), F(1, 2**20)), (F(1, 4), -F(1, 2**20), F(1, 2**20))], (F(0), F(0), F(0)), F(1, 2)), False),  # near miss
    (ee_query(seg_a, va, [(F(0), F(1, 4), F(1, 1024)), (F(1), F(1, 4), F(1, 1024))], (F(0), F(0), F(0)), F(1, 2)), False),  # parallel above
    (ee_query(seg_a, va, [(F(7), F(7), F(7)), (F(8), F(7), F(6))], (F(1), F(0), F(0)), F(1, 2)), False),                      # far apart
]


def line(v, truth=None):
    fields = []
    for x in v:
        fields += [str(x.numerator), str(x.denominator)]
    if truth is not None:
        fields.append("1" if truth else "0")
    return ",".join(fields)


def write(path, queries, inline_truth):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        for q, truth in queries:
            for v in q:
                f.write(line(v, truth if inline_truth else None) + "\n")


vf_all = vf + [(similar(q), t) for q, t in vf]
ee_all = ee + [(similar(q), t) for q, t in ee]
write(os.path.join(HERE, "vertex-face", "queries.csv"), vf_all, True)
write(os.path.join(HERE, "edge-edge", "queries.csv"), ee_all, False)
with open(os.path.join(HERE, "edge-edge", "mma_bool.json"), "w") as f:
    json.dump([t for _, t in ee_all], f)
