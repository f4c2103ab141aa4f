"""Shared helpers of the Python package's tests (tests/CMakeLists: ctest -R python).

ctest sets PYTHONPATH to the build's python/ folder, TMCERT_CLI to the
command line and TMCERT_SOURCE_DIR to the repository; run by hand with

    PYTHONPATH=build/python TMCERT_CLI=build/tmcert /usr/bin/python3 -m pytest -q tests/python
"""

from __future__ import annotations

import json
import math
import os
import subprocess
from decimal import Decimal
from fractions import Fraction
from pathlib import Path
from typing import Any, Dict, List, Tuple

import numpy as np
import pytest

import tmcert

SOURCE = Path(os.environ.get("TMCERT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
DATA = SOURCE / "tests" / "data"
CLI = os.environ.get("TMCERT_CLI", str(SOURCE / "build" / "tmcert"))


def expected_verdicts(listing: Path) -> List[Tuple[Path, str]]:
    """(scene, verdict) pairs of an EXPECTED list ("<file><TAB><verdict>")."""
    pairs = []
    for line in listing.read_text().splitlines():
        if line and not line.startswith("#"):
            name, verdict = line.split("\t")
            pairs.append((listing.parent / name, verdict))
    return pairs


def run_cli(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([CLI, *args], capture_output=True, text=True, timeout=120)


_cli_json: Dict[Tuple[str, ...], Tuple[int, dict]] = {}


def cli_result(scene: Path, *options: str) -> Tuple[int, dict]:
    """The exit code and the --json document of `tmcert verify` (cached)."""
    key = (str(scene), *options)
    if key not in _cli_json:
        done = run_cli("verify", str(scene), "--json", *options)
        assert done.returncode in (0, 1, 2), f"{scene}: exit {done.returncode}: {done.stderr}"
        _cli_json[key] = (done.returncode, without_seconds(json.loads(done.stdout)))
    return _cli_json[key]


def without_seconds(document: dict) -> dict:
    """A result document without its wall times (the one field that is not deterministic)."""
    for check in document.get("checks", []):
        check.get("stats", {}).pop("seconds", None)
    return document


def cli_error(*args: str) -> str:
    """The message of a refused `tmcert` run, without its "tmcert: " prefix."""
    done = run_cli(*args)
    assert done.returncode == 3, f"tmcert {' '.join(args)}: exit {done.returncode}, expected 3"
    assert done.stdout == ""
    message = done.stderr.rstrip("\n")
    assert message.startswith("tmcert: ") and "\n" not in message, message
    return message[len("tmcert: "):]


def read_document(path: Path) -> Any:
    """A scene file as Python objects, its decimals kept exact (Decimal)."""
    with open(path) as f:
        return json.load(f, parse_float=Decimal)


# ------------------------------------------------- scene document -> SceneBuilder

def exact(value: Any) -> Any:
    """A document number as an exact Python number (int or Fraction)."""
    if isinstance(value, int):
        return value
    text = str(value)
    if text.lstrip("-").replace("/", "", 1).isdigit():
        return fraction(text)  # "p/q" or "p" of any length
    return Fraction(text)  # a decimal


def points_array(points: Any) -> np.ndarray:
    """(n, 3) points: a float64 array when every coordinate is a double, else an object array of Fractions."""
    values = np.array([[exact(c) for c in p] for p in points], dtype=object).reshape(-1, 3)
    try:
        if all(Fraction(float(v)) == v for v in values.flat):
            return values.astype(np.float64)
    except OverflowError:  # beyond the doubles
        pass
    return values


def rotation(r: Dict[str, Any]) -> tmcert.Rotation:
    (kind, values), = r.items()
    if kind == "quaternion":
        return tmcert.Rotation.quaternion(*[exact(v) for v in values])
    if kind == "rpy":
        return tmcert.Rotation.rpy(*[exact(v) for v in values])
    assert kind == "matrix", kind
    return tmcert.Rotation.matrix(np.array([[exact(v) for v in row] for row in values], dtype=object))


def pose(p: Dict[str, Any]) -> tmcert.Pose:
    assert set(p) <= {"translation", "rotation"}, p
    translation = tuple(exact(v) for v in p.get("translation", [0, 0, 0]))
    if "rotation" in p:
        return tmcert.Pose(translation, rotation(p["rotation"]))
    return tmcert.Pose(translation)


def motion(m: Dict[str, Any]) -> Any:
    kind = m["type"]
    if kind == "rational_bezier":
        assert set(m) <= {"type", "interval", "control_points", "weights"}, m
        control = np.array([[[exact(v) for v in row] for row in cp] for cp in m["control_points"]], dtype=object)
        weights = [exact(w) for w in m["weights"]] if "weights" in m else None
        interval = tuple(exact(t) for t in m.get("interval", [0, 1]))
        return tmcert.RationalBezier(control, weights, interval)
    if kind == "keyframes":
        assert set(m) <= {"type", "interpolation", "times", "poses"}, m
        times = [exact(t) for t in m["times"]] if "times" in m else None
        return tmcert.Keyframes([pose(p) for p in m["poses"]], times, m.get("interpolation", "slerp"))
    assert kind == "piecewise" and set(m) == {"type", "pieces"}, m
    return tmcert.Piecewise([motion(piece) for piece in m["pieces"]])


def builder_from_document(doc: Dict[str, Any], base: Path) -> tmcert.SceneBuilder:
    """The scene of a tmcert-scene/1 document rebuilt through SceneBuilder and NumPy arrays."""
    b = tmcert.SceneBuilder()
    for r in doc.get("robots", []):
        robot = b.add_robot(r["name"], base / r["urdf"])
        if "base" in r:
            robot.base(pose(r["base"]))
        if "path" in r:
            positions = np.array([[exact(v) for v in row] for row in r["path"]["positions"]], dtype=object)
            robot.path(r["joints"], [exact(t) for t in r["path"]["times"]], positions)
            if {"interpolation", "velocities", "accelerations"} & set(r["path"]):
                rows = {key: [[exact(v) for v in row] for row in r["path"].get(key, [])]
                        for key in ("velocities", "accelerations")}
                robot.interpolation(r["path"].get("interpolation", "linear"), rows["velocities"], rows["accelerations"])
            assert set(r["path"]) <= {"times", "positions", "interpolation", "velocities", "accelerations"}, r
        if "self_collision" in r:
            robot.self_collision(r["self_collision"])
        for link_a, link_b in r.get("allowed_pairs", []):
            robot.allow(link_a, link_b)
        if "srdf" in r:
            robot.srdf(os.path.join(str(base), r["srdf"]))
        assert set(r) <= {"name", "urdf", "srdf", "base", "joints", "path", "self_collision", "allowed_pairs"}, r
    for folder in doc.get("package_paths", []):
        b.package_path(os.path.join(str(base), folder))
    for d in doc.get("bodies", []):
        body = b.add_body(d["name"])
        for key, value in d.items():
            if key in ("name", "comment"):
                continue
            if key == "polygons":
                vertices = points_array([v for polygon in value for v in polygon])
                faces, start = [], 0
                for polygon in value:
                    faces.append(list(range(start, start + len(polygon))))
                    start += len(polygon)
                if len({len(f) for f in faces}) == 1:
                    faces = np.array(faces, dtype=np.int64)  # the (m, k) array form
                body.polygons(vertices, faces)
            elif key == "segments":
                body.segments(points_array([p for s in value for p in s]).reshape(-1, 2, 3))
            elif key == "points":
                body.points(points_array(value))
            elif key == "mesh":
                body.mesh(base / value)
            elif key == "solid":
                body.solid(value)
            elif key == "mass":
                assert set(value) == {"points", "weights"}, value
                body.mass(points_array(value["points"]), [exact(w) for w in value["weights"]])
            elif key == "tolerance":
                body.tolerance(exact(value))
            elif key == "motion":
                body.motion(motion(value))
            else:
                raise AssertionError(f"body field {key} not rebuilt")
    assert doc["format"] == "tmcert-scene/1"
    for c in doc.get("checks", []):
        assert len(c) == 2 or isinstance(c, dict) and set(c) <= {"bodies", "clearance"}, c
        if isinstance(c, dict):
            b.check(c["bodies"][0], c["bodies"][1], exact(c["clearance"]) if "clearance" in c else None)
        else:
            b.check(c[0], c[1])
    for key, value in doc.items():
        if key == "epsilon":
            b.epsilon(exact(value))
        elif key == "max_depth":
            b.max_depth(value)
        elif key == "clearance":
            b.clearance(exact(value))
        else:
            assert key in ("format", "comment", "bodies", "robots", "checks", "package_paths"), \
                f"scene field {key} not rebuilt"
    return b


@pytest.fixture(scope="session")
def data() -> Path:
    return DATA


# ------------------------------------------------- exact and float views of a result

def fraction(text: str) -> Fraction:
    """A result's rational string ("p/q", "p") as a Fraction, however long
    (int() stops at 4300 digits: by chunks)."""
    def integer(digits: str) -> int:
        negative = digits.startswith("-")
        digits = digits.lstrip("-")
        value = 0
        for start in range(0, len(digits), 4000):
            chunk = digits[start:start + 4000]
            value = value * 10 ** len(chunk) + int(chunk)
        return -value if negative else value
    numerator, _, denominator = text.partition("/")
    return Fraction(integer(numerator), integer(denominator or "1"))


def nearest_float(x: Fraction) -> float:
    """The float nearest to x (Python rounds Fraction to float correctly), or
    NaN beyond the float range (an infinite float, or 0 for x != 0): the
    library's approximations (docs/scene-format.md "Approximations")."""
    try:
        f = float(x)
    except OverflowError:
        return math.nan
    return math.nan if (f == 0 and x != 0) or math.isinf(f) else f


def same_float(a: float, b: float) -> bool:
    return a == b or (math.isnan(a) and math.isnan(b))


def assert_time(doc: Any, time: tmcert.Time, approx: float) -> None:
    """A result time against its document form and its float view."""
    if isinstance(doc, str):
        assert isinstance(time, Fraction) and time == fraction(doc)
        assert same_float(approx, nearest_float(time))  # both the nearest double (NaN beyond the range)
        return
    assert isinstance(time, tmcert.AlgebraicNumber)
    assert list(time.root_of) == [int(c) for c in doc["root_of"]]
    lo, hi = (fraction(x) for x in doc["interval"])
    assert time.interval == (lo, hi) and lo < hi
    # The interval isolates a root: the polynomial changes sign across it
    # (exact arithmetic, independent of the library).
    def p(x: Fraction) -> Fraction:
        return sum(c * x ** k for k, c in enumerate(time.root_of))
    assert p(lo) * p(hi) < 0
    if math.isnan(approx):
        # Beyond the float range: the 17-digit decimal with exponent, in the
        # isolating interval up to its rounding, and NaN as the float.
        text = doc["approx"]
        assert "e" in text and len(text.lstrip("-").split("e")[0].replace(".", "")) == 17
        value = Fraction(Decimal(text))
        assert math.isnan(nearest_float(value)) and math.isnan(float(time)) and math.isnan(time.approx)
        assert lo - abs(value) / 10 ** 16 <= value <= hi + abs(value) / 10 ** 16
        return
    assert lo <= approx <= hi and approx == float(time) == time.approx
    assert abs(approx - float(doc["approx"])) <= 1e-12 * max(1.0, abs(approx))


def assert_point(doc: List[str], exact_point: Any, floats: Any) -> None:
    assert exact_point == tuple(fraction(c) for c in doc)
    assert all(same_float(f, nearest_float(c)) for f, c in zip(floats, exact_point))


def assert_views_agree(result: tmcert.Result) -> None:
    """Every exact value of `result` equals its to_json() form, and every float view is its nearest double."""
    doc = result.to_dict()
    assert doc["format"] == "tmcert-result/1"
    assert result.verdict == doc["verdict"] and result.kernel == doc["kernel"]
    assert result.certified == doc["certified"]
    assert result.epsilon == fraction(doc["epsilon"]) and same_float(result.epsilon_float, nearest_float(result.epsilon))
    assert len(result.checks) == len(doc["checks"])
    for check, c in zip(result.checks, doc["checks"]):
        assert list(check.bodies) == c["bodies"] and check.verdict == c["verdict"]
        assert check.epsilon == fraction(c["epsilon"]) and check.refined == c["refined"]
        assert check.clearance == fraction(c.get("clearance", "0"))
        assert check.clearance_violated == c.get("clearance_violated", False)
        if "first_contact" in c:
            for k in range(2):
                assert_time(c["first_contact"]["t"][k], check.first_contact[k], check.first_contact_float[k])
            assert not check.first_contact_float[0] > check.first_contact_float[1]
        else:
            assert check.first_contact is None and check.first_contact_float is None
            assert check.verdict == "safe"
        w = c.get("witness")
        assert (w is None) == (check.witness is None) == (check.verdict != "collision")
        if w is not None:
            witness = check.witness
            assert_time(w["t"], witness.t, witness.t_float)
            assert list(witness.features) == w["features"]
            if "point" in w:
                assert_point(w["point"], witness.point, witness.point_float)
            else:
                assert witness.point is None
            if "point_box" in w:
                assert witness.point_box == tuple((fraction(lo), fraction(hi)) for lo, hi in w["point_box"])
                for (lo, hi), x in zip(witness.point_box, witness.point_float):
                    assert lo <= hi and float(lo) <= x <= float(hi)
            if "points" in w:
                for k in range(2):
                    assert_point(w["points"][k], witness.points[k], witness.points_float[k])
            else:
                assert witness.points is None and witness.points_float is None
            if "displacement" in w:
                assert_point(w["displacement"], witness.displacement, witness.displacement_float)
                assert witness.displaced == w["displaced"]
            else:
                assert witness.displacement is None and witness.displaced is None
            if "displacement_other" in w:
                assert_point(w["displacement_other"], witness.displacement_other, witness.displacement_other_float)
                assert witness.displaced_other == w["displaced_other"]
            else:
                assert witness.displacement_other is None and witness.displaced_other is None
        assert len(check.undecided) == len(c["undecided"])
        for u, d in zip(check.undecided, c["undecided"]):
            assert u.t == (fraction(d["t"][0]), fraction(d["t"][1])) and u.reason == d["reason"]
            assert all(same_float(f, nearest_float(x)) for f, x in zip(u.t_float, u.t))
        if "not_searched" in c:
            assert check.witness is not None and check.not_searched[1] == check.interval[1]
            for k in range(2):
                assert_time(c["not_searched"][k], check.not_searched[k], check.not_searched_float[k])
        else:
            assert check.not_searched is None and check.not_searched_float is None and check.witness is None
        for key in ("nodes", "max_depth", "predicate_calls", "exact_fallbacks", "stops", "exact_pieces",
                    "exact_undecided", "prefiltered"):
            assert getattr(check.stats, key) == c["stats"][key], key
