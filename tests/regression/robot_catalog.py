#!/usr/bin/env python3
"""Every robot description of Gepetto/example-robot-data, unmodified, loads.

    robot_catalog.py TMCERT DATA_DIR

For each plain URDF under DATA_DIR/robots, a scene moves every joint that
is not a mimic (nor the master of one) from its lower limit clamped to 0 a
tenth of the way to its upper limit, with a far triangle as the obstacle,
and `tmcert verify` must say safe (exit 0).  xacro files must be refused
with the command to expand them, the few published files that are broken
(listed below with the reason) with a message naming the fault, and a
robot without collision geometry with "nothing to check";
anything else is a failure.  Without the data the test is skipped (exit
77) with a message saying how to fetch it.  The environment variable
TMCERT_EXAMPLE_ROBOT_DATA overrides DATA_DIR.
"""
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

# Published files that are not valid robot descriptions, and the words of
# tmcert's refusal (exit 3) for each.
BROKEN = {
    "robots/ur_description/urdf/ur3.urdf": "no <link>",  # an empty <robot>
    "robots/falcon_description/urdf/falcon.urdf": 'unknown child link "Z_propeller"',
    "robots/alex_description/urdf/alex_psyonic_hands.urdf": 'mimic: unknown joint "index_q1"',
}


def scene_for(data, rel):
    root = ET.parse(os.path.join(data, rel)).getroot()
    masters = {j.find("mimic").get("joint") for j in root.findall("joint") if j.find("mimic") is not None}
    joints, start, end = [], [], []
    for j in root.findall("joint"):
        kind = j.get("type")
        if kind not in ("revolute", "continuous", "prismatic") or j.find("mimic") is not None:
            continue
        limit = j.find("limit")
        lo = float(limit.get("lower", "0")) if limit is not None else 0.0
        hi = float(limit.get("upper", "0")) if limit is not None else 0.0
        if kind == "continuous":
            lo, hi = -1.0, 1.0
        a = min(max(0.0, lo), hi)
        b = a if j.get("name") in masters else a + round(0.1 * (hi - a), 4)
        b = min(b, hi)
        joints.append(j.get("name"))
        start.append(repr(a))
        end.append(repr(b))
    robot = {"name": "r", "urdf": "example-robot-data/" + rel, "joints": joints,
             "path": {"times": [0, 1], "positions": [start, end]}}
    return {"format": "tmcert-scene/1", "package_paths": ["example-robot-data"], "robots": [robot],
            "bodies": [{"name": "far", "polygons": [[[100, 100, 100], [101, 100, 100], [100, 101, 100]]]}]}, joints


def main():
    tmcert = os.path.abspath(sys.argv[1])
    data = os.environ.get("TMCERT_EXAMPLE_ROBOT_DATA") or sys.argv[2]
    if not os.path.isdir(os.path.join(data, "robots", "panda_description")):
        print(f"robot_catalog: skipped: example-robot-data not found at {data} "
              "(fetch it with: bash scripts/fetch_example_robot_data.sh, or set TMCERT_EXAMPLE_ROBOT_DATA)")
        return 77
    data = os.path.abspath(data)
    urdfs = sorted(os.path.relpath(os.path.join(d, f), data)
                   for d, _, files in os.walk(os.path.join(data, "robots")) for f in files if f.endswith(".urdf"))
    failures = loaded = refused = 0
    with tempfile.TemporaryDirectory() as work:
        os.symlink(data, os.path.join(work, "example-robot-data"))
        for rel in urdfs:
            text = open(os.path.join(data, rel), errors="replace").read()
            scene, joints = scene_for(data, rel)
            if not joints and "<xacro:" not in text:
                continue  # nothing moves: no path to verify
            path = os.path.join(work, "scene.json")
            with open(path, "w") as f:
                json.dump(scene, f)
            run = subprocess.run([tmcert, "verify", path], capture_output=True, text=True, timeout=600)
            err = run.stderr.strip().splitlines()[-1] if run.stderr.strip() else ""
            if "<xacro:" in text or rel in BROKEN or "<collision" not in text:
                if "<xacro:" in text:
                    want = "this is xacro (URDF macros), not plain URDF: run xacro first"
                elif rel in BROKEN:
                    want = BROKEN[rel]
                else:  # no collision geometry: nothing to check, which is never "safe" vacuously
                    want = "checks: nothing to check"
                if run.returncode == 3 and want in run.stderr:
                    refused += 1
                    continue
                print(f"FAIL {rel}: expected exit 3 with '{want}', got exit {run.returncode}: {err[:300]}")
                failures += 1
            elif run.returncode != 0:
                print(f"FAIL {rel}: exit {run.returncode}, expected 0 (safe): {err[:300]}")
                failures += 1
            else:
                loaded += 1
    print(f"robot_catalog: {loaded} robots loaded and verified safe, {refused} refused as expected, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
