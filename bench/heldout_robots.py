#!/usr/bin/env python3
"""Clearance scenes on real robot descriptions whose verdict is known by construction.

    bench/heldout_robots.py EXAMPLE_ROBOT_DATA OUT_DIR

The robot (the Panda, the UR5 of Gepetto/example-robot-data, unmodified)
stands at the origin; only its first joint moves, about the vertical axis
through the origin, from q0 to q1 (the other joints keep a fixed pose). Every
point of a moving link then keeps its distance rho from that axis, so a
vertical segment (the post) at radius R from the axis, covering the robot's
height, at an angle that the link point farthest from the axis (rho_max, a
mesh vertex or box corner) passes during the turn, is at distance exactly
R - rho_max from the robot at that instant and no closer at any instant.
rho_max is computed from the exact scene numbers (the STL floats, the URDF
decimals, the joint values) in 60-digit arithmetic (mpmath), far below every
margin used. The first link (fixed) stays farther from the post (checked).

Per robot and margin m (relative to the scene's size, 2 m): clearance
R - rho_max - m (safe) and R - rho_max + m (collision).

OUT_DIR/MANIFEST lists "<file>\\t<truth>\\t<margin>\\t<family>" as
bench/heldout_scenes.py does; run them with
HELDOUT_ROBOTS=EXAMPLE_ROBOT_DATA bench/heldout_sweep.sh build/tmcert OUT_DIR.
"""
import json
import os
import struct
import sys
import xml.etree.ElementTree as ET
from fractions import Fraction as F

import mpmath as mp

mp.mp.dps = 60


def rpy_matrix(r, p, y):
    cr, sr, cp, sp, cy, sy = mp.cos(r), mp.sin(r), mp.cos(p), mp.sin(p), mp.cos(y), mp.sin(y)
    return mp.matrix([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                      [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                      [-sp, cp * sr, cp * cr]])


def axis_angle(ax, a):
    x, y, z = ax
    n = mp.sqrt(x * x + y * y + z * z)
    x, y, z = x / n, y / n, z / n
    c, s, C = mp.cos(a), mp.sin(a), 1 - mp.cos(a)
    return mp.matrix([[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
                      [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
                      [z * x * C - y * s, z * y * C + x * s, c + z * z * C]])


def mpf(s):
    return mp.mpf(str(s))


def origin(el):
    o = el.find("origin") if el is not None else None
    xyz = [mpf(v) for v in (o.get("xyz", "0 0 0").split() if o is not None else "0 0 0".split())]
    rpy = [mpf(v) for v in (o.get("rpy", "0 0 0").split() if o is not None else "0 0 0".split())]
    return rpy_matrix(*rpy), mp.matrix(xyz)


def stl_vertices(path):
    data = open(path, "rb").read()
    if data[:5].lower() == b"solid" and b"facet" in data[:400]:
        out = []
        for line in data.decode().splitlines():
            t = line.split()
            if t and t[0] == "vertex":
                out.append(tuple(mpf(repr(float(struct.unpack("f", struct.pack("f", float(v)))[0]))) for v in t[1:4]))
        return out
    n = struct.unpack("<I", data[80:84])[0]
    out = set()
    for i in range(n):
        off = 84 + 50 * i
        for k in range(3):
            out.add(struct.unpack("<3f", data[off + 12 + 12 * k: off + 24 + 12 * k]))
    # a float32 converted to a double is exact; repr of the double is its exact-enough decimal
    return [tuple(mp.mpf(v) for v in p) for p in out]


def link_points(urdf_path, data_dir, positions):
    """World points (mpmath) of every link's collision geometry at joint positions (dict);
    returns {link: [points]} and the name of the root link."""
    root = ET.parse(urdf_path).getroot()
    joints = {j.get("name"): j for j in root.findall("joint")}
    child_joint = {j.find("child").get("link"): j for j in joints.values()}
    links = {l.get("name"): l for l in root.findall("link")}
    root_link = [l for l in links if l not in child_joint][0]

    def value(j):
        m = j.find("mimic")
        if m is not None:
            return mpf(m.get("multiplier", "1")) * value(joints[m.get("joint")]) + mpf(m.get("offset", "0"))
        return mpf(positions.get(j.get("name"), "0"))

    cache = {}

    def pose(link):
        if link in cache:
            return cache[link]
        if link not in child_joint:
            res = (mp.eye(3), mp.matrix([0, 0, 0]))
        else:
            j = child_joint[link]
            PR, Pt = pose(j.find("parent").get("link"))
            R, t = origin(j)
            R, t = PR * R, PR * t + Pt
            ax = [mpf(v) for v in (j.find("axis").get("xyz").split() if j.find("axis") is not None else "1 0 0".split())]
            typ = j.get("type")
            if typ in ("revolute", "continuous"):
                R = R * axis_angle(ax, value(j))
            elif typ == "prismatic":
                n = mp.sqrt(sum(a * a for a in ax))
                t = t + R * mp.matrix([a / n * value(j) for a in ax])
            res = (R, t)
        cache[link] = res
        return res

    def moves(link, joint_name):
        while link in child_joint:
            j = child_joint[link]
            if j.get("name") == joint_name:
                return True
            link = j.find("parent").get("link")
        return False

    out = {}
    link_points.moves = moves
    for name, l in links.items():
        pts = []
        for c in l.findall("collision"):
            R0, t0 = origin(c)
            g = c.find("geometry")
            local = []
            if g.find("mesh") is not None:
                fn = g.find("mesh").get("filename")
                rel = fn.split("package://example-robot-data/", 1)[1]
                sc = [mpf(v) for v in g.find("mesh").get("scale", "1 1 1").split()]
                local = [tuple(p[i] * sc[i] for i in range(3)) for p in stl_vertices(os.path.join(data_dir, rel))]
            elif g.find("box") is not None:
                sx, sy, sz = [mpf(v) / 2 for v in g.find("box").get("size").split()]
                local = [(a, b, cc) for a in (-sx, sx) for b in (-sy, sy) for cc in (-sz, sz)]
            else:
                raise SystemExit(f"{urdf_path}: link {name}: only meshes and boxes are handled here")
            LR, Lt = pose(name)
            for p in local:
                v = LR * (R0 * mp.matrix(p) + t0) + Lt
                pts.append(v)
        if pts:
            out[name] = pts
    return out, root_link


def q(x):
    x = F(x)
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def rational_direction(phi):
    """A rational unit vector (cos, sin) within 1e-6 of the angle phi: u = tan(phi/2) rounded."""
    u = F(int(mp.nint(mp.tan(phi / 2) * 10**6)), 10**6)
    return (1 - u * u) / (1 + u * u), 2 * u / (1 + u * u), u


ROBOTS = [
    ("panda", "robots/panda_description/urdf/panda.urdf",
     ["panda_joint1", "panda_joint2", "panda_joint3", "panda_joint4", "panda_joint5", "panda_joint6",
      "panda_joint7", "panda_finger_joint1"],
     ["0", "-0.785", "0", "-2.356", "0", "1.571", "0.785", "0.04"], "panda_joint1", ("-0.4", "0.6")),
    ("ur5", "robots/ur_description/urdf/ur5_robot.urdf",
     ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint", "wrist_2_joint", "wrist_3_joint"],
     ["0", "-1.2", "1.5", "-1.9", "-1.571", "0.3"], "shoulder_pan_joint", ("0.5", "1.5")),
]


def main():
    data, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    os.makedirs(out_dir, exist_ok=True)
    link = os.path.join(out_dir, "example-robot-data")
    if not os.path.exists(link):
        os.symlink(os.path.abspath(data), link)
    lines = []
    for name, urdf, joints, pos, turning, (q0, q1) in ROBOTS:
        positions = dict(zip(joints, pos))
        pts, root_link = link_points(os.path.join(data, urdf), data, positions)
        rho = lambda v: mp.sqrt(v[0] ** 2 + v[1] ** 2)
        moving = {l for l in pts if link_points.moves(l, turning)}
        fixed_max = max((rho(v) for l in pts if l not in moving for v in pts[l]), default=mp.mpf(0))
        best = max(((rho(v), v, l) for l, vs in pts.items() if l in moving for v in vs),
                   key=lambda x: x[0])
        rmax, v, lmax = best
        zs = [p[2] for vs in pts.values() for p in vs]
        psi = mp.atan2(v[1], v[0])
        # the configuration above has the turning joint at 0: the point's angle runs over
        # psi + [q0, q1]; the post sits near psi + (3 q0 + q1)/4 (between waypoints).
        phi = psi + (3 * mpf(q0) + mpf(q1)) / 4
        c, s, u = rational_direction(phi)
        D = F(1, 10)
        R = F(int(mp.nint((rmax + mpf(D)) * 10**9)), 10**9)  # the post's radius (rational)
        Dtrue = mpf(R.numerator) / R.denominator - rmax
        assert mpf(R.numerator) / R.denominator - fixed_max > Dtrue + mpf("0.01"), "the fixed link is too near"
        path_pos = [[p if j != turning else q0 for j, p in zip(joints, pos)],
                    [p if j != turning else q1 for j, p in zip(joints, pos)]]
        z0, z1 = min(zs) - 1, max(zs) + 1
        size = mpf(2)
        for rm in ("1e-2", "1e-4", "1e-5", "2e-6"):
            m = mpf(rm) * size
            for kind, clr, truth in (("safe", Dtrue - m, "safe"), ("violated", Dtrue + m, "collision")):
                cl = F(int(mp.floor(clr * 10**12)) if truth == "safe" else int(mp.ceil(clr * 10**12)), 10**12)
                post = {"name": "post", "segments": [[[q(c * R), q(s * R), q(F(int(mp.floor(z0 * 100)), 100))],
                                                      [q(c * R), q(s * R), q(F(int(mp.ceil(z1 * 100)), 100))]]]}
                scene = {"format": "tmcert-scene/1",
                         "comment": f"{name}: {turning} from {q0} to {q1}, the rest fixed; the farthest point from the axis "
                                    f"({lmax}) at radius {mp.nstr(rmax, 20)}; the post at radius {q(R)}: distance "
                                    f"{mp.nstr(Dtrue, 20)}, clearance {q(cl)}: {truth}",
                         "package_paths": ["example-robot-data"],
                         "robots": [{"name": name, "urdf": "example-robot-data/" + urdf, "joints": joints,
                                     "path": {"times": [0, 1], "positions": path_pos}}],
                         "bodies": [post],
                         "clearance": q(cl)}
                fn = f"robot-{name}-{kind}-m{rm}.json"
                with open(os.path.join(out_dir, fn), "w") as f:
                    json.dump(scene, f, indent=1)
                lines.append(f"{fn}\t{truth}\t{float(rm):.0e}\trobot-{name}")
        print(f"{name}: rho_max {mp.nstr(rmax, 15)} ({lmax}), fixed link {mp.nstr(fixed_max, 6)}, z {mp.nstr(min(zs), 4)}..{mp.nstr(max(zs), 4)}")
    with open(os.path.join(out_dir, "MANIFEST"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
