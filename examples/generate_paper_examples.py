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
byte-identically.  Standard library only; the exact and float helpers shared
with bench/paper_grid.py live in examples/rational_motion.py.

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

from rational_motion import (FPoly, affine_control_points, bernstein_basis, build_motion,
                             cross, dot, eval_motion, exact_witness, float_motion, fmt,
                             matvec, parse_motion, pt, rigidity_error, rot_matrix, runs_of,
                             sample_distances, scale, sub, tilt_matrix)

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
# Scene
# ---------------------------------------------------------------------------


def scene_polygons():
    T = tilt_matrix(Q_TILT)
    moving = [(u, v, Fr(0)) for (u, v) in OCTAGON]
    fixed = [matvec(T, (Fr(0), u, v)) for (u, v) in OCTAGON]
    return fixed, moving


def write_scene(path, fixed, moving, cps, w):
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
# Float check against the quaternion polynomial
# ---------------------------------------------------------------------------


def eval_direct(qs, guide, w, t):
    """(R(q(t)) | d(t)) / |q(t)|^2 straight from the quaternion polynomial."""
    B4 = bernstein_basis(4, t)
    q = [sum(B4[i] * float(qs[i][c]) for i in range(5)) for c in range(4)]
    B8 = bernstein_basis(8, t)
    d = [sum(B8[k] * float(w[k]) * float(guide[k][c]) for k in range(9)) for c in range(3)]
    R = rot_matrix(q)
    n2 = sum(x * x for x in q)
    return [[R[i][j] / n2 for j in range(3)] + [d[i] / n2] for i in range(3)]


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


def main():
    fixed, moving = scene_polygons()
    exact_polygon_checks(fixed)
    exact_polygon_checks(moving)
    qs, guide, w, N = build_motion(Q_TILT, Q_DESIGN, PATH)
    assert all(x > 0 for x in w), "non-positive weight"
    T = tilt_matrix(Q_TILT)
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
        cps_r, ws_r = parse_motion(doc["bodies"][1]["motion"])
        assert cps_r == cps and ws_r == w, "round trip mismatch"
        assert all(x > 0 for x in ws_r)
        cps_f, ws_f = float_motion(cps_r, ws_r)
        shift_f = tuple(float(x) for x in shift)
        err_orth, min_det = rigidity_error(cps_f, ws_f, 2001)
        err_direct = 0.0
        for s in range(2001):
            t = s / 2000
            M = eval_motion(cps_f, ws_f, t)
            D = eval_direct(qs, guide, w, t)
            for i in range(3):
                for j in range(4):
                    ref = D[i][j] + (shift_f[i] if j == 3 else 0.0)
                    err_direct = max(err_direct, abs(M[i][j] - ref))
        ds = sample_distances(cps_f, ws_f, Pf_loc, F, 2001)
        dmin = min(ds)
        imin = ds.index(dmin)
        zero = [s for s, d in enumerate(ds) if d == 0.0]
        # rotation swept: angle between the initial and final orientation
        A0 = [row[:3] for row in eval_motion(cps_f, ws_f, 0.0)]
        A1 = [row[:3] for row in eval_motion(cps_f, ws_f, 1.0)]
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
                runs = runs_of(zero)
                longest = max(runs, key=lambda r: r[1] - r[0])
                print("%-24s interpenetrating samples: %d, runs %s (t in [%.4f, %.4f] longest)"
                      % ("", len(zero), [(a / 2000, b / 2000) for a, b in runs],
                         longest[0] / 2000, longest[1] / 2000))
                tm, wit = exact_witness(cps_r, ws_r, longest[0], longest[1], 2001, moving, fixed)
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
