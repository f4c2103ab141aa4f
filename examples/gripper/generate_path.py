"""Write the planner-path scenes of the gripper example (issue 12, item 8).

The gripper (gripper.off) moves through its fixture (fixture.off) along a
20-keyframe SE(3) path, as a sampling-based planner would return it: it
comes in from behind and above turned by about 90 degrees, untwists and
levels out on the way down (16 to 22 degrees of rotation between
consecutive keyframes), passes over the back tower, drops past the tower's
far top edge into the slot (the palm's back edge clears it by about 1 mm),
descends between the posts and slides along the slot to the pick pose with a
few degrees of wobble about all three axes (the fingers pass the posts and
rest blocks at about 3 mm, the palm the side towers at about 4 mm).

Every keyframe is exact: a translation in short decimals (metres) and a
rotation given by a quaternion [w, x, y, z] of short decimals, not
normalised (tmcert uses the rotation of q/|q|, whose matrix is rational).
Times are evenly spaced over [0, 1] (the default).

Files, one per interpolation of the same keyframes:

  gripper-path-slerp.json            gripper-path-collision-slerp.json
  gripper-path-screw.json            gripper-path-collision-screw.json
  gripper-path-nlerp.json            gripper-path-collision-nlerp.json

The collision variant differs in one keyframe only (keyframe 10, 2 mm
further back in y): the palm's back edge then cuts about 1 mm deep through
the back tower's far top edge, for about 2 mm of travel between keyframes 9
and 10 -- less than the step of OMPL's default resolution there (7.3 mm), so
that a discrete check of OMPL's poses misses it (bench/planner_path.cpp).

Only the standard library is used; the output is deterministic:

  python3 examples/gripper/generate_path.py

It prints, per segment, the translation length and the rotation angle
between the keyframes (floating point, information only).
"""

import json
import math
import os
import sys
from fractions import Fraction as Fr

HERE = os.path.dirname(os.path.abspath(__file__))

# (translation [x, y, z] of the body origin = the fingertips' centre, in the
# world frame; quaternion [w, x, y, z]); world z up, plate tops at z = 0.
KEYFRAMES = [
    (("-0.1", "-0.3", "0.4"), ("1", "0.3", "-0.2", "1")),
    (("-0.07", "-0.27", "0.37"), ("1", "0.25", "-0.15", "0.7")),
    (("-0.04", "-0.24", "0.34"), ("1", "0.2", "-0.1", "0.45")),
    (("-0.01", "-0.21", "0.31"), ("1", "0.12", "-0.05", "0.25")),
    (("0.02", "-0.18", "0.28"), ("1", "0.05", "0.03", "0.1")),
    (("0.04", "-0.16", "0.25"), ("1", "-0.05", "0.06", "0")),
    (("0.055", "-0.14", "0.22"), ("1", "-0.12", "0.03", "-0.06")),
    (("0.06", "-0.12", "0.19"), ("1", "-0.08", "0", "-0.03")),
    (("0.06", "-0.1", "0.14"), ("1", "-0.04", "0", "0")),
    (("0.06", "-0.09", "0.09"), ("1", "-0.02", "0", "0")),
    (("0.06", "-0.072", "0.05"), ("1", "0", "0", "0")),
    (("0.06", "-0.072", "0.008"), ("1", "0", "0", "0")),
    (("0.06", "-0.05", "0.008"), ("1", "0", "0", "0.03")),
    (("0.06", "-0.03", "0.008"), ("1", "0.01", "0", "-0.02")),
    (("0.06", "-0.01", "0.008"), ("1", "0", "0.01", "0.02")),
    (("0.06", "0.01", "0.008"), ("1", "-0.01", "0", "-0.02")),
    (("0.06", "0.03", "0.008"), ("1", "0", "-0.01", "0.02")),
    (("0.06", "0.045", "0.008"), ("1", "0.01", "0", "-0.01")),
    (("0.06", "0.06", "0.008"), ("1", "0", "0", "0.01")),
    (("0.06", "0.07", "0.008"), ("1", "0", "0", "0")),
]
COLLISION = {10: (("0.06", "-0.074", "0.05"), ("1", "0", "0", "0"))}
EPSILON = "1/5000"          # 0.2 mm


def keyframes(collide):
    ks = list(KEYFRAMES)
    if collide:
        for i, k in COLLISION.items():
            ks[i] = k
    return ks


def scene_text(ks, interpolation):
    poses = []
    for t, q in ks:
        poses.append('          {"translation": [%s], "rotation": {"quaternion": [%s]}}'
                     % (", ".join(t), ", ".join(q)))
    lines = [
        "{",
        '  "format": "tmcert-scene/1",',
        '  "epsilon": "%s",' % EPSILON,
        '  "bodies": [',
        '    { "name": "fixture", "mesh": "fixture.off" },',
        '    { "name": "gripper", "mesh": "gripper.off",',
        '      "motion": {',
        '        "type": "keyframes",',
        '        "interpolation": "%s",' % interpolation,
        '        "poses": [',
        ",\n".join(poses),
        "        ] } }",
        "  ],",
        '  "checks": [ ["gripper", "fixture"] ]',
        "}",
    ]
    text = "\n".join(lines) + "\n"
    doc = json.loads(text)
    assert len(doc["bodies"][1]["motion"]["poses"]) == len(ks)
    return text


def qmul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return (w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2)


def angle_deg(q):
    """Rotation angle of a quaternion (any norm), degrees."""
    w = abs(float(q[0]))
    v = math.sqrt(sum(float(c) ** 2 for c in q[1:]))
    return math.degrees(2 * math.atan2(v, w))


def main():
    for collide in (False, True):
        ks = keyframes(collide)
        for t, q in ks:
            assert any(Fr(c) != 0 for c in q), "zero quaternion"
        for interp in ("slerp", "screw", "nlerp"):
            name = "gripper-path-%s%s.json" % ("collision-" if collide else "", interp)
            with open(os.path.join(HERE, name), "w", newline="\n") as f:
                f.write(scene_text(ks, interp))
            print("wrote", name)
    print("segment  translation [mm]  rotation between keyframes [deg]  (safe variant)")
    for i in range(len(KEYFRAMES) - 1):
        (t0, q0), (t1, q1) = KEYFRAMES[i], KEYFRAMES[i + 1]
        d = math.sqrt(sum((float(Fr(b)) - float(Fr(a))) ** 2 for a, b in zip(t0, t1)))
        conj = (Fr(q0[0]), -Fr(q0[1]), -Fr(q0[2]), -Fr(q0[3]))
        rel = qmul(conj, tuple(Fr(c) for c in q1))
        print("%2d-%2d    %8.1f          %6.1f" % (i, i + 1, 1000 * d, angle_deg(rel)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
