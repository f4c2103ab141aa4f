#!/usr/bin/env python3
"""Scenes whose verdict is known exactly by construction, with a margin.

    bench/heldout_scenes.py OUT_DIR [--seed N]

writes OUT_DIR/*.json and OUT_DIR/MANIFEST (one line per scene:
"<file>\t<truth>\t<margin relative to the scene's box diagonal>\t<family>"),
and bench/heldout_sweep.sh runs them at default settings and tabulates the
results against the truth.

Every scene is a body moving past a vertical post whose minimum distance D
is exact by construction:

* translations: a box translating along x (rational motion) past a vertical
  segment at distance D from its face; also with the post moving along its
  own axis (both bodies moving);
* turns about the z axis (slerp, screw, nlerp, rpy; one or several keyframe
  segments; both bodies turning): the box x in [1/10, 2/5], y in
  [-3/10, 3/10] has its farthest points from the z axis at radius exactly
  1/2 (the corners (2/5, +-3/10)), so a vertical segment at radius 1/2 + D
  whose angle one corner passes (between keyframes or at one) is at
  distance exactly D from the box at that instant and no closer at any other
  (every box point lies within radius 1/2 of the axis). The post covers the
  box's z range at every instant, and translations along z (screw) do not
  change horizontal distances.

Per motion: a clearance d = D - m (truth safe), d = D + m (truth
collision), and, at clearance 0, D = m (safe) and a post m inside the box
(collision, the segment pierces the box's top and bottom faces), with m a
margin relative to the scene's box diagonal S.

Tolerances (the box with its 8 vertices as mass, weights 1, so W = 8 and
G = diag(8 a^2, 8 b^2, 8 c^2, 8) about the centroid): an admissible affine
map moves a point x by at most r sqrt(x^T G^-1 x) (homogeneous, centred),
which is r/sqrt(2) at every vertex and r/sqrt(8) for a translation. The box
passing the post at nominal distance g: g <= r/sqrt(8) - m: collision by a
translation; g >= r/sqrt(2) + m: safe for every admissible map (no point
moves farther than r/sqrt(2)); in between: collision by an affine map (the
vertex nearest the post moved by r/sqrt(2) towards it: the nearest point of
the box is a vertex edge/face point whose reach, r sqrt(x^T G^-1 x), is
largest at the vertices; family "tolerance-band", a documented limit of the
search).
"""
import argparse
import json
import os
import random
from fractions import Fraction as F
from decimal import Decimal, getcontext

getcontext().prec = 60


def q(x):
    x = F(x)
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def box_polys(x0, x1, y0, y1, z0, z1):
    v = lambda x, y, z: [q(x), q(y), q(z)]
    return [
        [v(x0, y0, z0), v(x0, y1, z0), v(x1, y1, z0), v(x1, y0, z0)],
        [v(x0, y0, z1), v(x1, y0, z1), v(x1, y1, z1), v(x0, y1, z1)],
        [v(x0, y0, z0), v(x1, y0, z0), v(x1, y0, z1), v(x0, y0, z1)],
        [v(x0, y1, z0), v(x0, y1, z1), v(x1, y1, z1), v(x1, y1, z0)],
        [v(x0, y0, z0), v(x0, y0, z1), v(x0, y1, z1), v(x0, y1, z0)],
        [v(x1, y0, z0), v(x1, y1, z0), v(x1, y1, z1), v(x1, y0, z1)],
    ]


def box_body(name, b, motion=None, tolerance=None):
    x0, x1, y0, y1, z0, z1 = b
    body = {"name": name, "polygons": box_polys(*b)}
    if tolerance is not None:
        body["tolerance"] = q(tolerance)
        body["mass"] = {"points": [[q(x), q(y), q(z)] for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)],
                        "weights": [1] * 8}
    if motion:
        body["motion"] = motion
    return body


def post_body(name, x, y, z0, z1, motion=None):
    body = {"name": name, "segments": [[[q(x), q(y), q(z0)], [q(x), q(y), q(z1)]]]}
    if motion:
        body["motion"] = motion
    return body


def diag(lo, hi):
    s = sum((Decimal(h.numerator) / h.denominator - Decimal(l.numerator) / l.denominator) ** 2
            for l, h in zip(lo, hi))
    return s.sqrt()


def dec_below(x, digits=12):
    """A short decimal rational <= x (x a Decimal)."""
    s = Decimal(10) ** digits
    return F(int((x * s).to_integral_value(rounding="ROUND_FLOOR")), int(s))


def dec_above(x, digits=12):
    s = Decimal(10) ** digits
    return F(int((x * s).to_integral_value(rounding="ROUND_CEILING")), int(s))


def to_dec(f):
    return Decimal(f.numerator) / f.denominator


# The turning box: corners (2/5, +-3/10) at radius exactly 1/2.
TB = (F(1, 10), F(2, 5), F(-3, 10), F(3, 10), F(-1, 5), F(1, 5))
# Rational directions (cos, sin) of post angles.
DIR = {"90": (F(0), F(1)), "126.87": (F(-3, 5), F(4, 5)), "0": (F(1), F(0)), "180": (F(-1), F(0)),
       "53.13": (F(3, 5), F(4, 5))}


def quat_z(k):
    return {"quaternion": [1, 0, 0, q(k)]}


def turn_motions():
    """(name, motion of the box, motion of the post or None, post angles reached, z range of the box over time,
    angle sweep note)."""
    out = []
    h = F(3, 10)
    for interp in ("slerp", "screw", "nlerp"):
        m = {"type": "keyframes", "interpolation": interp,
             "poses": [{"translation": [0, 0, 0]}, {"translation": [0, 0, q(h)], "rotation": quat_z(1)}]}
        # corner (2/5, 3/10) sweeps 36.87 -> 126.87 degrees, corner (2/5, -3/10) -36.87 -> 53.13
        out.append((f"turn90-{interp}", m, None, ["90", "126.87", "0"], h))
    m = {"type": "keyframes", "interpolation": "slerp",
         "poses": [{"translation": [0, 0, 0]}, {"translation": [0, 0, 0], "rotation": {"rpy": [0, 0, "1.5707963"]}}]}
    out.append(("turn90-rpy-slerp", m, None, ["90", "0"], F(0)))
    m = dict(m, interpolation="screw")
    out.append(("turn90-rpy-screw", m, None, ["90", "0"], F(0)))
    for interp in ("slerp", "screw", "nlerp"):
        m = {"type": "keyframes", "interpolation": interp, "times": [0, "3/10", "1/2", 1],
             "poses": [{"translation": [0, 0, 0]},
                       {"translation": [0, 0, "1/10"], "rotation": quat_z(F(1, 3))},
                       {"translation": [0, 0, "1/5"], "rotation": quat_z(1)},
                       {"translation": [0, 0, "3/10"], "rotation": quat_z(3)}]}
        # rotations 0, 36.87, 90, 143.13: corner (2/5, 3/10) sweeps 36.87 -> 180
        out.append((f"multi-{interp}", m, None, ["90", "126.87", "180"], h))
    for interp in ("slerp", "nlerp"):
        ma = {"type": "keyframes", "interpolation": interp,
              "poses": [{"translation": [0, 0, 0]}, {"translation": [0, 0, 0], "rotation": quat_z(3)}]}
        mb = {"type": "keyframes", "interpolation": interp,
              "poses": [{"translation": [0, 0, 0]}, {"translation": [0, 0, 0], "rotation": quat_z(F(1, 3))}]}
        # relative rotation 0 -> 106.26 degrees (continuous): corner (2/5, 3/10) passes 90 in the post's frame
        out.append((f"both-turn-{interp}", ma, mb, ["90"], F(0)))
    return out


def margin_case(kind, D, m):
    """(distance, clearance, truth) of a case at distance D and margin m:
    a clearance m below or above the distance, or a touch m apart or m deep."""
    if kind == "clear-safe":
        return D, D - m, "safe"
    if kind == "clear-violated":
        return D, D + m, "collision"
    if kind == "touch-safe":
        return m, F(0), "safe"
    return -m, F(0), "collision"


def scenes(rng):
    res = []
    rel_margins = [F(1, 100), F(1, 10**4), F(1, 10**5), F(2, 10**6)]
    # --- translations ---
    a, b, c = F(1, 5), F(3, 10), F(1, 5)
    for variant in ("trans", "trans-both", "trans-diag"):
        D = F(3, 10) + F(rng.randrange(0, 1000), 10**5)
        lo = [F(-2) - a, -b, F(-1)]
        hi = [F(2) + a, b + D + F(1, 10), F(1)]
        if variant == "trans-both":
            lo[2], hi[2] = F(-3, 2), F(3, 2)
        S = diag(lo, hi)
        for rm in rel_margins:
            m = dec_above(to_dec(rm) * S, 14)  # an absolute margin >= rm * S
            for kind in ("clear-safe", "clear-violated", "touch-safe", "touch-collision"):
                dist, clr, truth = margin_case(kind, D, m)
                box = (-a, a, -b, b, -c, c)
                if variant == "trans-diag":
                    # translation along x with a drift in z (the post covers it)
                    mb = {"type": "keyframes", "poses": [{"translation": [-2, 0, "-1/2"]}, {"translation": [2, 0, "1/2"]}]}
                    post = post_body("post", 0, b + dist, F(-1), F(1))
                else:
                    mb = {"type": "keyframes", "poses": [{"translation": [-2, 0, 0]}, {"translation": [2, 0, 0]}]}
                    pm = None
                    if variant == "trans-both":
                        pm = {"type": "keyframes", "poses": [{"translation": [0, 0, "-1/2"]}, {"translation": [0, 0, "1/2"]}]}
                    post = post_body("post", 0, b + dist, F(-1), F(1), pm)
                scene = {"format": "tmcert-scene/1",
                         "comment": f"{variant}: distance {q(dist)}, clearance {q(clr)}, truth {truth}",
                         "bodies": [box_body("box", box, mb), post],
                         "checks": [{"bodies": ["box", "post"], "clearance": q(clr)}]}
                res.append((f"{variant}-{kind}-m{float(rm):.0e}", scene, truth, rm, variant))
    # --- turns ---
    for name, mbox, mpost, angles, h in turn_motions():
        first = rng.randrange(len(angles))
        D = F(3, 20) + F(rng.randrange(0, 1000), 10**5)
        R0 = F(1, 2)
        lo = [-(R0 + D) - F(1, 10), -(R0 + D) - F(1, 10), F(-1)]
        hi = [(R0 + D) + F(1, 10), (R0 + D) + F(1, 10), F(3, 2)]
        S = diag(lo, hi)
        for im, rm in enumerate(rel_margins):
            m = dec_above(to_dec(rm) * S, 14)
            ang = angles[(first + im) % len(angles)]  # every post angle at some margin
            for kind in ("clear-safe", "clear-violated", "touch-safe", "touch-collision"):
                dist, clr, truth = margin_case(kind, D, m)
                co, si = DIR[ang]
                R = R0 + dist
                post = post_body("post", co * R, si * R, F(-1), F(3, 2), mpost)
                scene = {"format": "tmcert-scene/1",
                         "comment": f"{name}: post at angle {ang}, distance {q(dist)}, clearance {q(clr)}, truth {truth}",
                         "bodies": [box_body("box", TB, mbox), post],
                         "checks": [{"bodies": ["box", "post"], "clearance": q(clr)}]}
                res.append((f"{name}-a{ang}-{kind}-m{float(rm):.0e}", scene, truth, rm, name))
    # --- tolerances ---
    r = F(1, 10)
    sq2 = Decimal(2).sqrt()
    reach_t = to_dec(r) / (2 * sq2)   # r / sqrt(8)
    reach_a = to_dec(r) / sq2         # r / sqrt(2)
    for name, motion_kind in (("tol-trans", "trans"), ("tol-turn-slerp", "slerp"), ("tol-turn-screw", "screw")):
        for rm in [F(1, 1000), F(1, 10**4), F(2, 10**6)]:
            for kind in ("collision", "safe", "band"):
                if motion_kind == "trans":
                    box = (-a, a, -b, b, -c, c)
                    lo = [F(-2) - a, -b, F(-1)]
                    hi = [F(2) + a, b + F(1, 5), F(1)]
                else:
                    box = TB
                    lo = [F(-7, 10), F(-7, 10), F(-1)]
                    hi = [F(7, 10), F(7, 10), F(3, 2)]
                S = diag(lo, hi)
                m = to_dec(rm) * S
                if kind == "collision":
                    g, truth = dec_below(reach_t - m), "collision"
                elif kind == "safe":
                    g, truth = dec_above(reach_a + m), "safe"
                else:
                    g, truth = dec_below((reach_t + reach_a) / 2), "collision"
                if motion_kind == "trans":
                    mb = {"type": "keyframes", "poses": [{"translation": [-2, 0, 0]}, {"translation": [2, 0, 0]}]}
                    post = post_body("post", 0, b + g, F(-1), F(1))
                else:
                    mb = {"type": "keyframes", "interpolation": motion_kind,
                          "poses": [{"translation": [0, 0, 0]}, {"translation": [0, 0, "3/10"], "rotation": quat_z(1)}]}
                    post = post_body("post", 0, F(1, 2) + g, F(-1), F(3, 2))
                scene = {"format": "tmcert-scene/1",
                         "comment": f"{name}: nominal distance {q(g)}, tolerance {q(r)} (translation reach r/sqrt 8, affine reach r/sqrt 2), truth {truth}",
                         "bodies": [box_body("box", box, mb, tolerance=r), post],
                         "checks": [["box", "post"]]}
                fam = name if kind != "band" else "tolerance-band"
                res.append((f"{name}-{kind}-m{float(rm):.0e}", scene, truth, rm if kind != "band" else F(1, 1000), fam))
                if kind == "band" and rm != F(1, 1000):
                    res.pop()
    return res



def qmul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return (w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2)


def qmat(qq):
    w, x, y, z = qq
    n = w * w + x * x + y * y + z * z
    return [[(w * w + x * x - y * y - z * z) / n, 2 * (x * y - w * z) / n, 2 * (x * z + w * y) / n],
            [2 * (x * y + w * z) / n, (w * w - x * x + y * y - z * z) / n, 2 * (y * z - w * x) / n],
            [2 * (x * z - w * y) / n, 2 * (y * z + w * x) / n, (w * w - x * x - y * y + z * z) / n]]


def transformed(scene, k, qw, T):
    """The scene in another world frame and unit: every length times k, then the rotation of the
    rational quaternion qw and the translation T (left of every pose, on fixed bodies' coordinates).
    Distances scale by k, so clearances and tolerances do too; verdicts are unchanged (slerp, screw
    and nlerp commute with a fixed rotation on the left)."""
    Q = qmat(qw)
    world = lambda p: [q(sum(Q[i][j] * k * F(p[j]) for j in range(3)) + T[i]) for i in range(3)]
    local = lambda p: [q(k * F(c)) for c in p]
    out = json.loads(json.dumps(scene))
    for body in out["bodies"]:
        motion = body.get("motion")
        f = local if motion else world
        for key in ("polygons",):
            if key in body:
                body[key] = [[f(p) for p in poly] for poly in body[key]]
        if "segments" in body:
            body["segments"] = [[f(p) for p in seg] for seg in body["segments"]]
        if "mass" in body:
            body["mass"]["points"] = [f(p) for p in body["mass"]["points"]]
        if "tolerance" in body:
            body["tolerance"] = q(k * F(body["tolerance"]))
        if motion:
            for pose in motion["poses"]:
                rq = pose.get("rotation", {"quaternion": [1, 0, 0, 0]})["quaternion"]
                nq = qmul(qw, tuple(F(c) for c in rq))
                pose["rotation"] = {"quaternion": [q(c) for c in nq]}
                pose["translation"] = world(pose.get("translation", [0, 0, 0]))
    for c in out.get("checks", []):
        if isinstance(c, dict) and "clearance" in c:
            c["clearance"] = q(k * F(c["clearance"]))
    if "clearance" in out:
        out["clearance"] = q(k * F(out["clearance"]))
    out["comment"] = out.get("comment", "") + f"; lengths times {q(k)}, world rotation {[q(c) for c in qw]}, translation {[q(c) for c in T]}"
    return out


def hard_scenes(rng):
    res = []
    base = [x for x in scenes(rng) if "rpy" not in x[0] and x[4] != "tolerance-band"
            and ("m1e-05" in x[0] or "m2e-06" in x[0] or "m1e-04" in x[0])]
    frames = [(F(1000), (F(1), F(2), F(3), F(4)), (F(1000), F(-20), F(3, 7))),
              (F(1, 1000), (F(3), F(-1), F(1), F(5)), (F(1, 3), F(2), F(-5))),
              (F(1), (F(7), F(1), F(-2), F(2)), (F(10**4), F(10**4), F(0)))]
    for name, scene, truth, rm, fam in base:
        if rng.random() < 0.35:
            i = rng.randrange(len(frames))
            k, qw, T = frames[i]
            res.append((f"frame{i}-{name}", transformed(scene, k, qw, T), truth, rm, f"frame{i}"))
    # Exact clearance d = D (touching at the bound is within d: collision, margin 0) and d = 0 at D = 0.
    for name, mbox, mpost, angles, h in turn_motions():
        if "rpy" in name:
            continue
        ang = angles[0]
        D = F(3, 20)
        co, si = DIR[ang]
        post = post_body("post", co * (F(1, 2) + D), si * (F(1, 2) + D), F(-1), F(3, 2), mpost)
        scene = {"format": "tmcert-scene/1", "comment": f"{name}: distance exactly the clearance {q(D)}",
                 "bodies": [box_body("box", TB, mbox), post],
                 "checks": [{"bodies": ["box", "post"], "clearance": q(D)}]}
        res.append((f"equal-{name}-a{ang}", scene, "collision", F(0), "clear-equal"))
        post = post_body("post", co * F(1, 2), si * F(1, 2), F(-1), F(3, 2), mpost)
        scene = {"format": "tmcert-scene/1", "comment": f"{name}: the post grazes the corner edge (touch)",
                 "bodies": [box_body("box", TB, mbox), post], "checks": [["box", "post"]]}
        res.append((f"graze-{name}-a{ang}", scene, "collision", F(0), "graze"))
    # Many keyframes: rotations 2 atan(i/10), i = 0..30 (0 to 143.13 degrees), uneven times.
    for interp in ("slerp", "screw", "nlerp"):
        poses, times = [], []
        for i in range(31):
            poses.append({"translation": [0, 0, q(F(i, 100))], "rotation": quat_z(F(i, 10))})
            times.append(q(F(i * i, 900)))
        m = {"type": "keyframes", "interpolation": interp, "times": times, "poses": poses}
        for rm in (F(1, 10**4), F(2, 10**6)):
            S = diag([F(-7, 10), F(-7, 10), F(-1)], [F(7, 10), F(7, 10), F(3, 2)])
            mm = dec_above(to_dec(rm) * S, 14)
            D = F(3, 20)
            for kind, clr, truth in (("safe", D - mm, "safe"), ("violated", D + mm, "collision")):
                co, si = DIR["90"]
                post = post_body("post", 0, F(1, 2) + D, F(-1), F(3, 2))
                scene = {"format": "tmcert-scene/1", "comment": f"30 {interp} segments, distance {q(D)}, clearance {q(clr)}",
                         "bodies": [box_body("box", TB, m), post],
                         "checks": [{"bodies": ["box", "post"], "clearance": q(clr)}]}
                res.append((f"many-{interp}-{kind}-m{float(rm):.0e}", scene, truth, rm, f"many-{interp}"))
    # Near half turns per segment: quaternion (1,0,0,50) turns by 177.7 degrees.
    for interp in ("slerp", "screw", "nlerp"):
        m = {"type": "keyframes", "interpolation": interp,
             "poses": [{"translation": [0, 0, 0]}, {"translation": [0, 0, 0], "rotation": quat_z(50)}]}
        for rm in (F(1, 10**4), F(2, 10**6)):
            S = diag([F(-7, 10), F(-7, 10), F(-1)], [F(7, 10), F(7, 10), F(3, 2)])
            mm = dec_above(to_dec(rm) * S, 14)
            D = F(3, 20)
            for kind, clr, truth in (("safe", D - mm, "safe"), ("violated", D + mm, "collision")):
                post = post_body("post", F(-3, 5) * (F(1, 2) + D), F(4, 5) * (F(1, 2) + D), F(-1), F(3, 2))
                scene = {"format": "tmcert-scene/1", "comment": f"{interp} by 177.7 degrees, distance {q(D)}, clearance {q(clr)}",
                         "bodies": [box_body("box", TB, m), post],
                         "checks": [{"bodies": ["box", "post"], "clearance": q(clr)}]}
                res.append((f"halfturn-{interp}-{kind}-m{float(rm):.0e}", scene, truth, rm, f"halfturn-{interp}"))
    # Face to face: a box translating past a box whose face is parallel at distance D.
    a, b, c = F(1, 5), F(3, 10), F(1, 5)
    for rm in (F(1, 100), F(1, 10**4), F(2, 10**6)):
        D = F(1, 4)
        S = diag([F(-11, 5), -b, F(-1, 5)], [F(11, 5), b + D + F(2, 5), F(1, 5)])
        mm = dec_above(to_dec(rm) * S, 14)
        mb = {"type": "keyframes", "poses": [{"translation": [-2, 0, 0]}, {"translation": [2, 0, 0]}]}
        for kind, dist, clr, truth in (("clear-safe", D, D - mm, "safe"), ("clear-violated", D, D + mm, "collision"),
                                       ("touch-safe", mm, 0, "safe"), ("touch-collision", -mm, 0, "collision")):
            other = box_body("wall", (-a, a, b + dist, b + dist + F(2, 5), -c, c))
            scene = {"format": "tmcert-scene/1", "comment": f"face to face at distance {q(dist)}, clearance {q(clr)}",
                     "bodies": [box_body("box", (-a, a, -b, b, -c, c), mb), other],
                     "checks": [{"bodies": ["box", "wall"], "clearance": q(clr)}]}
            res.append((f"face-{kind}-m{float(rm):.0e}", scene, truth, rm, "face-face"))
    # Both bodies toleranced (translations of both add up): boxes face to face, each tolerance r,
    # each with its 8 vertices as mass: translation reach r/sqrt(8) each, affine reach r/sqrt(2) each.
    r = F(1, 10)
    sq8 = Decimal(8).sqrt()
    for rm in (F(1, 1000), F(2, 10**6)):
        S = diag([F(-11, 5), -b, F(-1, 5)], [F(11, 5), b + F(2, 5) + F(1, 5), F(1, 5)])
        mm = to_dec(rm) * S
        mb = {"type": "keyframes", "poses": [{"translation": [-2, 0, 0]}, {"translation": [2, 0, 0]}]}
        cases = (("sum-collision", dec_below(2 * to_dec(r) / sq8 - mm), "collision"),
                 ("one-collision", dec_below(to_dec(r) / sq8 - mm), "collision"),
                 ("safe", dec_above(2 * to_dec(r) * 2 / sq8 + mm), "safe"))
        for kind, g, truth in cases:
            other = box_body("wall", (-a, a, b + g, b + g + F(2, 5), -c, c), tolerance=r)
            scene = {"format": "tmcert-scene/1", "comment": f"both toleranced {q(r)}, nominal distance {q(g)}",
                     "bodies": [box_body("box", (-a, a, -b, b, -c, c), mb, tolerance=r), other],
                     "checks": [["box", "wall"]]}
            res.append((f"tolboth-{kind}-m{float(rm):.0e}", scene, truth, rm, "tol-both"))
    # Tolerance and clearance together: collision iff nominal distance - (reach) <= d.
    for rm in (F(1, 1000), F(2, 10**6)):
        S = diag([F(-11, 5), -b, F(-1)], [F(11, 5), b + F(1, 2), F(1)])
        mm = to_dec(rm) * S
        d = F(1, 10)
        mb = {"type": "keyframes", "poses": [{"translation": [-2, 0, 0]}, {"translation": [2, 0, 0]}]}
        for kind, g, truth in (("collision", dec_below(to_dec(d) + to_dec(r) / sq8 - mm), "collision"),
                               ("safe", dec_above(to_dec(d) + 2 * to_dec(r) / sq8 + mm), "safe")):
            post = post_body("post", 0, b + g, F(-1), F(1))
            scene = {"format": "tmcert-scene/1", "comment": f"tolerance {q(r)} and clearance {q(d)}, nominal distance {q(g)}",
                     "bodies": [box_body("box", (-a, a, -b, b, -c, c), mb, tolerance=r), post],
                     "checks": [{"bodies": ["box", "post"], "clearance": q(d)}]}
            res.append((f"tolclear-{kind}-m{float(rm):.0e}", scene, truth, rm, "tol-clear"))
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=23)
    ap.add_argument("--hard", action="store_true", help="the second set: other frames and units, exact bounds, many keyframes, half turns, faces, two tolerances")
    args = ap.parse_args()
    rng = random.Random(args.seed)
    os.makedirs(args.out, exist_ok=True)
    lines = []
    for name, scene, truth, rm, fam in (hard_scenes(rng) if args.hard else scenes(rng)):
        with open(os.path.join(args.out, name + ".json"), "w") as f:
            json.dump(scene, f, indent=1)
        lines.append(f"{name}.json\t{truth}\t{float(rm):.0e}\t{fam}")
    with open(os.path.join(args.out, "MANIFEST"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{len(lines)} scenes in {args.out}")


if __name__ == "__main__":
    main()
