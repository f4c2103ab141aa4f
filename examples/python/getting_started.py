# %% [markdown]
# # tmcert from Python: getting started
#
# Certified collision checks of moving polyhedra.  Run from the repository
# root after building (cells are marked `# %%` for Jupyter, VS Code or
# Spyder; the whole file also runs as a script):
#
#     PYTHONPATH=build/python /usr/bin/python3 examples/python/getting_started.py
#
# Every verdict is a proof about the scene as written: numbers are exact
# (a float is its exact binary value; write "1/10" or Fraction(1, 10) for
# one tenth), "collision" comes with an exact witness, "safe" means no
# common point at any time.

# %%
from fractions import Fraction

import numpy as np

import tmcert

# %% [markdown]
# ## A scene from NumPy arrays
#
# A square table in the plane z = 0 and a tetrahedron falling onto it.
# The motion is a rational Bezier curve of affine maps: control points are
# (k, 3, 4) arrays [A | a] (x -> A x + a); here a straight slanted fall
# from z = 2 to z = -1/2 while x goes from 0 to 1/2 over t in [0, 1], so the
# tip (the body's origin) reaches the table when 2 - 5t/2 = 0, at t = 4/5,
# at the point (2/5, 0, 0).

# %%
table_xyz = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], dtype=np.float64)
tetra_xyz = np.array([[0, 0, 0], [1, 0, 1], [0, 1, 1], [-1, -1, 1]], dtype=np.float64) / 4
tetra_faces = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]])

fall = np.zeros((2, 3, 4), dtype=object)
fall[:, :, :3] = np.eye(3, dtype=int)  # no turn
fall[0, 2, 3] = 2                     # start: z + 2
fall[1, 2, 3] = Fraction(-1, 2)       # end: z - 1/2
fall[1, 0, 3] = Fraction(1, 2)        #      and x + 1/2

builder = tmcert.SceneBuilder()
builder.add_body("table").polygons(table_xyz, [[0, 1, 2, 3]])
builder.add_body("tetra").triangles(tetra_xyz, tetra_faces).motion(tmcert.RationalBezier(fall))
result = tmcert.verify(builder)

# %%
print("verdict:", result.verdict)
check = result.checks[0]
print("check:", " x ".join(check.bodies), "->", check.verdict)
print("first contact (exact):", check.first_contact[0], "to", check.first_contact[1])
print("first contact (float):", check.first_contact_float)
print("witness t:", check.witness.t, "=", check.witness.t_float)
print("witness point (exact):", tuple(str(c) for c in check.witness.point))
print("witness point (float):", check.witness.point_float)
print("features:", ", ".join(check.witness.features))

# %% [markdown]
# ## A scene from a dict
#
# The tmcert-scene/1 document as Python objects: a bar hovering one tenth
# above the table turns a quarter turn about the z axis (keyframes, slerp).
# It never touches the table: "safe" is proven for every t.

# %%
scene = {
    "format": "tmcert-scene/1",
    "bodies": [
        {"name": "table", "polygons": [table_xyz]},
        {"name": "bar", "segments": [[[0, 0, 0], [1, 0, 0]]],
         "motion": {"type": "keyframes", "interpolation": "slerp",
                    "poses": [{"translation": [0, 0, "1/10"]},
                              {"translation": [0, 0, "1/10"], "rotation": {"quaternion": [1, 0, 0, 1]}}]}},
    ],
}
hover = tmcert.verify(scene)
print("hovering bar:", hover.verdict, "| undecided intervals:", len(hover.checks[0].undecided))

# %% [markdown]
# ## Errors
#
# Bad input raises tmcert.InputError (a ValueError) naming the field, with
# the message the command line prints.

# %%
scene["bodies"][1]["motion"]["poses"][1]["rotation"] = {"quaternion": [0, 0, 0, 0]}
try:
    tmcert.verify(scene)
except tmcert.InputError as error:
    print("InputError:", error)
