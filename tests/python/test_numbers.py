"""Numbers are exact: a float is its binary value, Fraction/Decimal/str what they spell.

The scene: a fixed triangle in the plane z = 1/10 and a point coming down
from z = 1 to z = `end` over t in [0, 1].  With end = 1/10 exactly the point
touches the triangle at t = 1 (collision, witness (0, 0, 1/10)); the double
0.1 is 0.1000000000000000055..., above the plane, so the point never
touches (safe): a tool that rounded would get one of the two wrong.
"""

from __future__ import annotations

import json
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import tmcert
from conftest import assert_views_agree, without_seconds

TENTH = Fraction(1, 10)


def scene_dict(end):
    return {
        "format": "tmcert-scene/1",
        "bodies": [
            {"name": "plate", "polygons": [[[-1, -1, "1/10"], [1, -1, "1/10"], [0, 1, "1/10"]]]},
            {"name": "probe", "points": [[0, 0, 0]],
             "motion": {"type": "rational_bezier",
                        "control_points": [[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 1]],
                                           [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, end]]]}},
        ],
    }


def scene_builder(end):
    b = tmcert.SceneBuilder()
    b.add_body("plate").polygons(np.array([[-1, -1, TENTH], [1, -1, TENTH], [0, 1, TENTH]], dtype=object),
                                 np.array([[0, 1, 2]]))
    b.add_body("probe").points(np.zeros((1, 3))).motion(tmcert.Motion.translation((0, 0, 1), (0, 0, end)))
    return b


def assert_touches_at_one(result: tmcert.Result) -> None:
    assert result.verdict == tmcert.Verdict.COLLISION == "collision"
    (check,) = result.checks
    assert check.witness.t == 1 and check.witness.point == (0, 0, TENTH)
    assert check.first_contact[1] == 1
    assert_views_agree(result)


@pytest.mark.parametrize("end", [TENTH, "0.1", "1/10", Decimal("0.1"), Decimal("1E-1")],
                         ids=["Fraction", "str-decimal", "str-fraction", "Decimal", "Decimal-exponent"])
def test_exact_tenth_touches(end) -> None:
    assert_touches_at_one(tmcert.verify(scene_dict(end)))
    assert_touches_at_one(tmcert.verify(scene_builder(end)))


@pytest.mark.parametrize("end", [0.1, np.float64(0.1)], ids=["float", "numpy-float64"])
def test_the_double_nearest_a_tenth_stays_above(end) -> None:
    assert Fraction(end) > TENTH  # the premise: 0.1 as a double is above 1/10
    for result in (tmcert.verify(scene_dict(end)), tmcert.verify(scene_builder(end))):
        assert result.verdict == "safe"
        assert_views_agree(result)


def test_float_is_its_binary_value_in_dicts_and_builders() -> None:
    b = scene_builder(0.1)
    doc = json.loads(b.to_json())
    written = doc["bodies"][1]["motion"]["control_points"][1][2][3]
    assert Fraction(written) == Fraction(0.1) != TENTH
    # A dict with the float and one with its exact value give the same scene.
    exact_value = Fraction(0.1)
    assert without_seconds(tmcert.verify(scene_dict(exact_value)).to_dict()) == \
        without_seconds(tmcert.verify(scene_dict(0.1)).to_dict())


def test_json_text_reads_decimals_exactly(tmp_path) -> None:
    path = tmp_path / "tenth.json"
    path.write_text(json.dumps(scene_dict(0.1)))  # the JSON number 0.1 is one tenth
    assert_touches_at_one(tmcert.verify(path))
    assert_touches_at_one(tmcert.verify(tmcert.Scene.from_json(path.read_text())))


def test_integers_beyond_64_bits_stay_exact() -> None:
    huge = 10 ** 30
    doc = scene_dict(TENTH)
    doc["bodies"][0]["polygons"][0][2][1] = huge  # a huge but exact triangle
    result = tmcert.verify(doc)
    assert result.verdict == "collision"
    assert tmcert.scene_from_dict(doc).body_names == ["plate", "probe"]


def test_numbers_beyond_pythons_int_string_limit() -> None:
    # Python's str(int) stops at 4300 digits; scenes allow 10 000 digits.
    tiny = Fraction(1, 10 ** 5000)
    doc = scene_dict(TENTH + tiny)  # ends just above the plate: no contact
    assert tmcert.verify(doc).verdict == "safe"
    b = scene_builder(TENTH - tiny)  # ends just below it: through the plate
    written = json.loads(b.to_json())["bodies"][1]["motion"]["control_points"][1][2][3]
    assert written.endswith("/" + "1" + "0" * 5000)
    result = tmcert.verify(b)
    assert result.verdict == "collision" and result.checks[0].witness.t < 1


def test_non_finite_and_non_numbers_are_input_errors() -> None:
    with pytest.raises(tmcert.InputError, match=r"^<dict>: bodies\[1\]\.motion\.control_points\[1\]\[2\]\[3\]: "):
        tmcert.scene_from_dict(scene_dict(float("nan")))
    with pytest.raises(tmcert.InputError, match=r"^SceneBuilder: .*not a number"):
        scene_builder(float("inf")).build()
    with pytest.raises(tmcert.InputError, match=r"^<dict>: bodies\[1\]\.motion\.control_points\[1\]\[2\]\[3\]: "):
        tmcert.scene_from_dict(scene_dict(object()))
    with pytest.raises(TypeError):
        tmcert.Motion.translation((0, 0, 1), (0, 0, None))


def test_approximations_beyond_the_float_range_are_nan_never_inf() -> None:
    # A contact at the irrational t = 6.8232780382801933e+400 (issue 21): the
    # exact root, its 17-digit decimal in the document (a string), and NaN
    # as its float (no float is near it); an epsilon of 1e400 likewise.
    from conftest import DATA
    import math
    result = tmcert.verify(DATA / "scenes" / "numbers-root-1e400.json", epsilon="1e400")
    (check,) = result.checks
    assert check.verdict == "collision"
    assert isinstance(check.witness.t, tmcert.AlgebraicNumber)
    assert math.isnan(check.witness.t.approx) and math.isnan(check.witness.t_float)
    assert math.isnan(check.first_contact_float[0]) and math.isnan(result.epsilon_float)
    assert result.epsilon == 10 ** 400
    doc = result.to_dict()["checks"][0]
    assert doc["witness"]["t"]["approx"] == "6.8232780382801933e+400"
    assert doc["witness"]["t_approx"] == "6.8232780382801933e+400"
    assert doc["epsilon_approx"] == "1.0000000000000000e+400"
    # A tiny irrational time: its nearest double.
    tiny = tmcert.verify(DATA / "scenes" / "numbers-root-1e-20.json").checks[0]
    assert tiny.witness.t_float == 6.823278038280193e-21 == float(tiny.witness.t)
