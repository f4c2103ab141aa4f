#!/usr/bin/env python3
"""Turn the OMPL.app benchmark problems and their stored paths into tmcert scenes.

OMPL.app (github.com/ompl/omplapp, resources/3D) ships rigid-body problems:
a .cfg ([problem]: robot and world COLLADA meshes, start, goal, volume) and,
for some, a solution path (.path: one SE(3) state `x y z qx qy qz qw` per
line), which OMPL executes linearly in translation and by slerp along the
shorter arc in rotation.

The geometry is exactly what OMPL.app hands FCL: `tmcert_omplapp_fcl mesh`
(bench/omplapp_fcl.cpp, built with Debian's libassimp-dev, libfcl-dev and
libompl-dev) reads the COLLADA files with assimp and OMPL.app's
post-processing flags, applies the node transforms in single precision as
OMPL.app's extractTriangles does, and shifts the robot by the mean of its
vertices (OMPL.app's sceneCenter: all vertices of all meshes after assimp's
JoinIdenticalVertices, summed in single precision); the environment is not
shifted. Every coordinate is the exact value of the single-precision number
assimp gives (written as a decimal, which tmcert reads exactly).

A triangle whose three vertices are exactly collinear (after the transform
and the shift) is not a polygon in a tmcert scene; as a point set it is its
longest side (or a point), written in the body's `segments` (`points`).

The path's numbers are written exactly as the .path file spells them (OMPL
reads them as the nearest doubles; the difference is below 1e-15 relative);
tmcert rotates by q/|q|.

For each problem NAME (a .cfg with a .path whose meshes exist) it writes,
under OUT/NAME/:
  robot.off, env.off   the meshes (OFF, vertices shared by exact value)
  path.json            the stored path as one scene: body "robot" (robot.off)
                       moving by `keyframes` (slerp, times 0, 1, ..., n-1:
                       the part [k, k+1] is the edge from waypoint k), body
                       "env" (env.off) fixed, one check [robot, env]; no
                       epsilon (tmcert's default)
  shortcuts/K-L.json   one scene per shortcut query, waypoint K to L = K+2
                       and K+4 (what OMPL's path simplifier asks its motion
                       validator): the straight slerp edge between the two
                       states, times [0, 1]
  problem.json         what was converted: files, counts, the robot's centre,
                       the .cfg's bounds, start and goal

Usage:
  omplapp_to_scene.py OMPLAPP OUT [--tool build/tmcert_omplapp_fcl] [--only NAME ...]
OMPLAPP is the OMPL.app checkout (or its resources/3D folder). Exit status:
0 when every problem was converted, 3 on bad usage or unreadable input, and
0 with a line "omplapp_to_scene: skipped: ..." on stderr when OMPLAPP does not
exist (nothing to convert).
"""
import argparse
import json
import os
import re
import subprocess
import sys
from decimal import Decimal
from fractions import Fraction


def fail(message):
    print(f"omplapp_to_scene: {message}", file=sys.stderr)
    sys.exit(3)


DECIMAL = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def read_cfg(path):
    """The [problem] section of an OMPL.app .cfg, as a dict of strings."""
    out, section = {}, None
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if line.startswith("["):
                section = line.strip("[]").strip()
                continue
            if section == "problem" and "=" in line:
                key, value = line.split("=", 1)
                out[key.strip()] = value.strip()
    return out


def read_path(path):
    """The states of a .path file: lists of 7 decimal strings."""
    states = []
    with open(path, encoding="utf-8") as f:
        for lineno, line in enumerate(f, 1):
            tokens = line.split()
            if not tokens:
                continue
            if len(tokens) != 7 or not all(DECIMAL.match(t) for t in tokens):
                fail(f"{path}: line {lineno}: expected 7 decimals (x y z qx qy qz qw)")
            if all(Fraction(t) == 0 for t in tokens[3:]):
                fail(f"{path}: line {lineno}: zero quaternion")
            states.append(tokens)
    if len(states) < 2:
        fail(f"{path}: fewer than 2 states")
    return states


def exact_decimal(x):
    """The exact value of a binary floating-point number, as a plain decimal."""
    s = format(Decimal(x), "f")
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def read_mesh(tool, path, robot):
    """OMPL.app's triangles of a COLLADA file: (center, vertex count, triangles as exact Fractions)."""
    cmd = [tool, "mesh", path] + (["--robot"] if robot else [])
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        fail(f"{' '.join(cmd)}: exit {proc.returncode}: {proc.stderr.strip()}")
    lines = proc.stdout.splitlines()
    head = lines[0].split()
    if head[0] != "center" or head[4] != "vertices" or head[6] != "triangles":
        fail(f"{' '.join(cmd)}: unexpected output")
    center = [float.fromhex(h) for h in head[1:4]]
    triangles = []
    for line in lines[1:]:
        v = [float.fromhex(h) for h in line.split()]
        triangles.append((tuple(v[0:3]), tuple(v[3:6]), tuple(v[6:9])))
    if len(triangles) != int(head[7]):
        fail(f"{' '.join(cmd)}: {len(triangles)} triangles, announced {head[7]}")
    return center, int(head[5]), triangles


def collinear(a, b, c):
    """Exactly: are the three points (floats, exact as rationals) collinear?"""
    a, b, c = ([Fraction(x) for x in p] for p in (a, b, c))
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    return (u[1] * w[2] - u[2] * w[1] == 0 and u[2] * w[0] - u[0] * w[2] == 0 and u[0] * w[1] - u[1] * w[0] == 0)


def split_triangles(triangles):
    """Proper triangles, and the degenerate ones as segments (longest side) or points."""
    proper, segments, points = [], [], []
    for t in triangles:
        if not collinear(*t):
            proper.append(t)
            continue
        pairs = [(t[0], t[1]), (t[0], t[2]), (t[1], t[2])]
        d2 = [sum((Fraction(p[i]) - Fraction(q[i])) ** 2 for i in range(3)) for p, q in pairs]
        p, q = pairs[d2.index(max(d2))]
        if p == q:
            points.append(p)
        else:
            segments.append((p, q))
    return proper, segments, points


def write_off(path, triangles):
    index, verts, faces = {}, [], []
    for t in triangles:
        face = []
        for v in t:
            if v not in index:
                index[v] = len(verts)
                verts.append(v)
            face.append(index[v])
        faces.append(face)
    with open(path, "w", encoding="ascii") as f:
        f.write(f"OFF\n{len(verts)} {len(faces)} 0\n")
        for v in verts:
            f.write(" ".join(exact_decimal(x) for x in v) + "\n")
        for a, b, c in faces:
            f.write(f"3 {a} {b} {c}\n")
    return len(verts)


def body(name, mesh, segments, points):
    b = {"name": name, "mesh": mesh}
    if segments:
        b["segments"] = [[[exact_decimal(x) for x in p] for p in s] for s in segments]
    if points:
        b["points"] = [[exact_decimal(x) for x in p] for p in points]
    return b


def pose(state):
    x, y, z, qx, qy, qz, qw = state
    return {"translation": [x, y, z], "rotation": {"quaternion": [qw, qx, qy, qz]}}


def scene(robot_body, env_body, states, times):
    motion = {"type": "keyframes", "interpolation": "slerp", "times": times, "poses": [pose(s) for s in states]}
    return {"format": "tmcert-scene/1",
            "bodies": [dict(env_body), dict(robot_body, motion=motion)],
            "checks": [["robot", "env"]]}


def dump(path, doc):
    with open(path, "w", encoding="ascii") as f:
        json.dump(doc, f, separators=(",", ":"))
        f.write("\n")


def problems(resources):
    """(name, cfg, path) for every .cfg with a .path of the same name."""
    out = []
    for f in sorted(os.listdir(resources)):
        if f.endswith(".cfg") and os.path.isfile(os.path.join(resources, f[:-4] + ".path")):
            out.append((f[:-4], os.path.join(resources, f), os.path.join(resources, f[:-4] + ".path")))
    return out


def convert(tool, name, cfg_path, path_path, out):
    cfg = read_cfg(cfg_path)
    resources = os.path.dirname(cfg_path)
    for key in ("robot", "world"):
        if key not in cfg:
            fail(f"{cfg_path}: [problem] has no {key}")
    robot_dae, env_dae = (os.path.join(resources, cfg[k]) for k in ("robot", "world"))
    missing = [p for p in (robot_dae, env_dae) if not os.path.isfile(p)]
    if missing:
        print(f"omplapp_to_scene: {name}: skipped: missing {', '.join(missing)}", file=sys.stderr)
        return None
    states = read_path(path_path)
    center, robot_vertices, robot_tris = read_mesh(tool, robot_dae, True)
    _, env_vertices, env_tris = read_mesh(tool, env_dae, False)
    rp, rs, rpt = split_triangles(robot_tris)
    ep, es, ept = split_triangles(env_tris)
    d = os.path.join(out, name)
    os.makedirs(os.path.join(d, "shortcuts"), exist_ok=True)
    write_off(os.path.join(d, "robot.off"), rp)
    write_off(os.path.join(d, "env.off"), ep)
    robot = body("robot", "robot.off", rs, rpt)
    env = body("env", "env.off", es, ept)
    dump(os.path.join(d, "path.json"), scene(robot, env, states, list(range(len(states)))))
    sub_robot, sub_env = dict(robot, mesh="../robot.off"), dict(env, mesh="../env.off")
    queries = []
    for step in (2, 4):
        for k in range(len(states) - step):
            f = f"{k}-{k + step}.json"
            dump(os.path.join(d, "shortcuts", f), scene(sub_robot, sub_env, [states[k], states[k + step]], [0, 1]))
            queries.append({"file": f"shortcuts/{f}", "from": k, "to": k + step})
    info = {
        "name": name, "cfg": os.path.abspath(cfg_path), "path": os.path.abspath(path_path),
        "robot_mesh": os.path.abspath(robot_dae), "env_mesh": os.path.abspath(env_dae),
        "states": len(states),
        "robot": {"triangles": len(robot_tris), "degenerate_as_segments": len(rs), "degenerate_as_points": len(rpt),
                  "assimp_vertices": robot_vertices, "center": [exact_decimal(c) for c in center]},
        "env": {"triangles": len(env_tris), "degenerate_as_segments": len(es), "degenerate_as_points": len(ept),
                "assimp_vertices": env_vertices},
        "cfg_problem": cfg,
        "queries": queries,
    }
    dump(os.path.join(d, "problem.json"), info)
    return info


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("omplapp", help="the OMPL.app checkout or its resources/3D folder")
    ap.add_argument("out", help="output folder (one subfolder per problem)")
    ap.add_argument("--tool", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build",
                                                   "tmcert_omplapp_fcl"),
                    help="tmcert_omplapp_fcl (bench/omplapp_fcl.cpp); default build/tmcert_omplapp_fcl")
    ap.add_argument("--only", nargs="*", default=None, help="problem names (default: every .cfg with a .path)")
    a = ap.parse_args()
    resources = a.omplapp
    if os.path.isdir(os.path.join(resources, "resources", "3D")):
        resources = os.path.join(resources, "resources", "3D")
    if not os.path.isdir(resources):
        print(f"omplapp_to_scene: skipped: {a.omplapp} does not exist (fetch github.com/ompl/omplapp)", file=sys.stderr)
        return 0
    if not (os.path.isfile(a.tool) and os.access(a.tool, os.X_OK)):
        fail(f"{a.tool} is not an executable (build the target tmcert_omplapp_fcl: it needs libassimp-dev, "
             "libfcl-dev, libompl-dev)")
    found = problems(resources)
    if a.only:
        names = {n for n, _, _ in found}
        for n in a.only:
            if n not in names:
                fail(f"{resources}: no problem {n} with a stored path")
        found = [p for p in found if p[0] in a.only]
    os.makedirs(a.out, exist_ok=True)
    done = []
    for name, cfg, path in found:
        info = convert(a.tool, name, cfg, path, a.out)
        if info is None:
            continue
        done.append(name)
        print(f"{name}: {info['states']} states, robot {info['robot']['triangles']} triangles "
              f"({info['robot']['degenerate_as_segments']} degenerate), env {info['env']['triangles']} triangles "
              f"({info['env']['degenerate_as_segments']} degenerate), {len(info['queries'])} shortcut queries")
    dump(os.path.join(a.out, "index.json"), {"problems": done})
    return 0


if __name__ == "__main__":
    sys.exit(main())
