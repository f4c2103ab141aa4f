#!/usr/bin/env python3
"""scripts/omplapp_to_scene.py end to end on a synthetic OMPL.app problem.

tests/data/omplapp/: a robot of two triangles (COLLADA, Z_UP, a node matrix
that scales by 2 and translates) and a wall of one triangle, with a safe path
beside the wall and a path through it. Checks that the converter writes
OMPL.app's geometry exactly (assimp's Z_UP root rotation and the node
transform applied; the robot shifted by the single-precision mean of its 6
assimp vertices; the wall unshifted), that tmcert certifies the safe path
and finds the collision, and that OMPL's checking (tmcert_omplapp_fcl check)
agrees.

Usage: omplapp_convert.py TMCERT TMCERT_OMPLAPP_FCL SOURCE_DIR
"""
import json
import os
import struct
import subprocess
import sys
import tempfile
from fractions import Fraction


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def main():
    tmcert, tool, src = sys.argv[1:4]
    data = os.path.join(src, "tests", "data", "omplapp")
    failures = []

    def expect(cond, what):
        if not cond:
            failures.append(what)
            print(f"FAIL: {what}")

    with tempfile.TemporaryDirectory() as out:
        subprocess.run([sys.executable, os.path.join(src, "scripts", "omplapp_to_scene.py"), data, out,
                        "--tool", tool], check=True)
        with open(os.path.join(out, "index.json")) as f:
            expect(sorted(json.load(f)["problems"]) == ["smoke", "smoke-collision"], "both problems converted")
        d = os.path.join(out, "smoke")

        def off(name):
            with open(os.path.join(d, name)) as f:
                lines = f.read().split("\n")
            nv, nf, _ = map(int, lines[1].split())
            verts = [tuple(Fraction(x) for x in lines[2 + i].split()) for i in range(nv)]
            return verts, nf

        # The wall: Y_UP, identity node: as written, not shifted.
        env, nf = off("env.off")
        expect(nf == 1 and sorted(env) == sorted([(5, -10, -10), (5, 10, -10), (5, 0, 10)]), "wall as written")

        # The robot: (x, y, z) -> 2 (x, y, z) + (10, 20, 30), then Z_UP -> Y_UP: (x, z, -y).
        world = [(10, 30, -20), (12, 30, -20), (10, 30, -22), (10, 32, -20)]
        # assimp's 6 vertices (two triangles with their own normals share no
        # vertex): 0 1 2 and 0 1 3; sums of small integers are exact in
        # single precision, then multiplied by the single-precision 1/6.
        six = [world[i] for i in (0, 1, 2, 0, 1, 3)]
        inv = f32(1.0 / 6.0)
        center = [f32(f32(sum(v[k] for v in six)) * inv) for k in range(3)]
        with open(os.path.join(d, "problem.json")) as f:
            info = json.load(f)
        expect([Fraction(c) for c in info["robot"]["center"]] == [Fraction(c) for c in center],
               f"robot centre {info['robot']['center']} is the single-precision mean {center}")
        robot, nf = off("robot.off")
        shifted = sorted(tuple(Fraction(f32(w[k] - center[k])) for k in range(3)) for w in world)
        expect(nf == 2 and sorted(robot) == shifted, "robot shifted by its centre in single precision")

        # The path scene: slerp keyframes, times by index, the numbers as written.
        with open(os.path.join(d, "path.json")) as f:
            scene = json.load(f)
        motion = scene["bodies"][1]["motion"]
        expect(motion["times"] == [0, 1, 2] and motion["poses"][1]["rotation"]["quaternion"]
               == ["0.9238795325112867", "0.0", "0.0", "0.3826834323650898"], "keyframes as written")
        expect(len(info["queries"]) == 1 and os.path.isfile(os.path.join(d, "shortcuts", "0-2.json")),
               "one shortcut query 0-2")

        for name, code in (("smoke", 0), ("smoke-collision", 1)):
            for scene_file in ("path.json", "shortcuts/0-2.json"):
                r = subprocess.run([tmcert, "verify", os.path.join(out, name, scene_file)], capture_output=True,
                                   text=True)
                expect(r.returncode == code, f"tmcert verify {name}/{scene_file}: exit {r.returncode}, expected {code}")
            r = subprocess.run([tool, "check", os.path.join(data, name + ".cfg"), os.path.join(data, name + ".path"),
                                "--reps", "1", "--queries"], capture_output=True, text=True, check=True)
            lines = [json.loads(x) for x in r.stdout.splitlines()]
            path = next(x for x in lines if x["kind"] == "path")
            expect(path["valid"] == (code == 0), f"OMPL+FCL on {name}: valid {path['valid']}")

    print("omplapp_convert: " + ("all passed" if not failures else f"{len(failures)} failed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
