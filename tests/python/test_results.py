"""Result objects: exact values where the scenes' comments derive them, the
human summary of the CLI, scenes' properties, and verify() from threads."""

from __future__ import annotations

import re
from concurrent.futures import ThreadPoolExecutor
from fractions import Fraction

import numpy as np
import pytest

import tmcert
from conftest import DATA, SOURCE, assert_views_agree, run_cli, without_seconds

SCENES = DATA / "scenes"


def test_rational_witness() -> None:
    # README: a point through a sliding triangle, collision at t = 1/2.
    result = tmcert.verify(SOURCE / "examples" / "vertex-face-linear.json")
    (check,) = result.checks
    assert check.verdict is tmcert.Verdict.COLLISION and check.witness.t == Fraction(1, 2)
    assert check.witness.t_float == 0.5 and isinstance(check.witness.point_float, np.ndarray)
    assert check.first_contact[0] <= check.witness.t <= check.first_contact[1]
    assert_views_agree(result)


def test_irrational_first_contact() -> None:
    # The comment of the scene: the contact is at the real root of t^3 + t - 1.
    result = tmcert.verify(SCENES / "cubic-crossing-irrational.json")
    (check,) = result.checks
    t = check.witness.t
    assert isinstance(t, tmcert.AlgebraicNumber) and t.root_of == (-1, 1, 0, 1)
    assert str(t) == "root of [-1, 1, 0, 1] in (0, 1)"
    assert abs(float(t) ** 3 + float(t) - 1) < 1e-12
    assert check.first_contact_exact and check.first_contact == (t, t)
    assert check.witness.point is None and check.witness.point_box is not None
    assert_views_agree(result)


def test_clearance_and_undecided_intervals() -> None:
    result = tmcert.verify(SCENES / "planner-clearance-violated.json")
    (check,) = result.checks
    assert check.clearance == Fraction(1, 2) and check.clearance_violated
    # Between the plate's slerp keyframes (an enclosed pose): a box per body,
    # every two points of the boxes within the clearance.
    assert check.witness.points is None
    w = result.to_dict()["checks"][0]["witness"]
    far2 = sum(max(abs(Fraction(a[1]) - Fraction(b[0])), abs(Fraction(b[1]) - Fraction(a[0]))) ** 2
               for a, b in zip(*w["points_box"]))
    assert far2 <= check.clearance ** 2
    # The first violation: the pin at x = -2 + 4t comes within 1/2 of the
    # plate when (|x| - 1/2)^2 + (3/10)^2 <= (1/2)^2, i.e. from t = 11/40 on;
    # the one undecided interval (reason epsilon) holds it, before the witness.
    assert [u.reason for u in check.undecided] == ["epsilon"]
    (u,) = check.undecided
    assert u.t[0] <= Fraction(11, 40) <= u.t[1] <= check.witness.t
    assert_views_agree(result)


def test_partition_after_an_undecided_stop() -> None:
    # Issue 21: the point is inside the solid cube for every t in (2/3, 1]; the
    # crossing at an enclosed (rpy) pose stops undecided, and nothing after the
    # stop may be claimed cleared (reason "after_undecided").
    result = tmcert.verify(SCENES / "solid-entered-after-undecided-rpy.json")
    (check,) = result.checks
    assert check.verdict is tmcert.Verdict.UNDECIDED and check.not_searched is None
    assert check.interval == (0, 1)
    assert check.undecided[-1].reason == "after_undecided" and check.undecided[-1].t[1] == 1
    covered = lambda t: any(u.t[0] <= t <= u.t[1] for u in check.undecided)
    assert all(covered(Fraction(2, 3) + Fraction(k, 300)) for k in range(1, 101))
    assert_views_agree(result)
    # A collision: nothing after the witness is claimed.
    result = tmcert.verify(SCENES / "solid-entered-rational.json")
    (check,) = result.checks
    assert check.witness.t == Fraction(2, 3) and check.not_searched == (Fraction(2, 3), Fraction(1))
    assert check.not_searched_float == (2 / 3, 1.0)
    assert_views_agree(result)


def test_tolerance_displacement() -> None:
    result = tmcert.verify(SCENES / "planner-tolerance-collision.json")
    (check,) = result.checks
    assert check.witness.displaced == "pin" and check.witness.displacement == (Fraction(1, 22), Fraction(1, 50), 0)
    assert_views_agree(result)


def test_two_displacements() -> None:
    result = tmcert.verify(SCENES / "tolerance-both-translation-violated.json")
    (check,) = result.checks
    w = check.witness
    assert w.displaced == "box" and w.displaced_other == "wall"
    assert sum(x * x for x in w.displacement) * 8 <= Fraction(1, 100)
    assert sum(x * x for x in w.displacement_other) * 8 <= Fraction(1, 100)
    assert_views_agree(result)


def test_summary_is_the_cli_output() -> None:
    seconds = re.compile(r"[0-9.e+-]+ s\)")
    for scene in (SCENES / "cubic-crossing-irrational.json", SOURCE / "examples" / "octagons-near.json"):
        done = run_cli("verify", str(scene))
        result = tmcert.verify(scene)
        assert seconds.sub("S s)", str(result)) == seconds.sub("S s)", done.stdout)
        assert result.summary() == str(result)
    result = tmcert.verify(SCENES / "cubic-crossing-irrational.json")
    assert repr(result) == "<tmcert.Result collision (1 collision), kernel filtered>"


def test_scene_properties() -> None:
    scene = tmcert.Scene.from_file(str(SCENES / "robots" / "arm-swing-collision.json"))
    assert scene.body_names[0] == "block" and all(n.startswith("arm/") for n in scene.body_names[1:])
    assert len(scene) == len(scene.body_names)
    assert not scene.moves(0)
    assert all(b == "block" for _, b in scene.checks)
    assert scene.epsilon is None and scene.max_depth == 40
    assert all(scene.default_epsilon(a, b) > 0 for a, b in scene.checks)
    near = tmcert.Scene.from_file(str(SOURCE / "examples" / "octagons-near.json"))
    assert near.checks == [("moving", "fixed")] and near.body_names == ["fixed", "moving"]
    assert near.moves(1) and not near.moves(0)
    result = tmcert.verify(near)
    defaults = [near.default_epsilon(a, b) for a, b in near.checks]
    assert [c.epsilon for c in result.checks] == ([near.epsilon] * len(defaults) if near.epsilon else defaults)
    assert result.epsilon == (near.epsilon or max(defaults))
    with pytest.raises(IndexError):
        near.default_epsilon("moving", "no such body")


def test_verify_from_threads_gives_the_same_results() -> None:
    scenes = [SOURCE / "examples" / "octagons-collision.json", SCENES / "planner-wall1-screw.json",
              SCENES / "cubic-crossing-irrational.json", SCENES / "planner-piecewise-second-piece.json"]
    sequential = [without_seconds(tmcert.verify(s).to_dict()) for s in scenes]
    with ThreadPoolExecutor(max_workers=4) as pool:
        parallel = list(pool.map(lambda s: without_seconds(tmcert.verify(s, threads=2).to_dict()), scenes))
    assert parallel == sequential


def test_to_json_is_the_cli_text() -> None:
    seconds = re.compile(r'"seconds": [0-9.e+-]+')
    for scene in (SCENES / "planner-tolerance-collision.json", SCENES / "cubic-crossing-irrational.json"):
        done = run_cli("verify", str(scene), "--json")
        assert seconds.sub('"seconds": S', tmcert.verify(scene).to_json()) == seconds.sub('"seconds": S', done.stdout)


def test_scenes_from_json_text_name_their_source() -> None:
    text = (SOURCE / "examples" / "octagons-near.json").read_text()
    assert tmcert.Scene.from_json(text).source == "<json>"
    assert tmcert.Scene.from_json(text, "near").source == "near"
    with pytest.raises(tmcert.InputError, match=r"^near: invalid JSON at byte 0"):
        tmcert.Scene.from_json("", "near")
    with pytest.raises(TypeError, match="expected a Scene, SceneBuilder, dict or file path"):
        tmcert.verify(42)


def test_version_is_the_cli_version() -> None:
    assert run_cli("--version").stdout.strip() == f"tmcert {tmcert.__version__}"


def test_decisive_by_default() -> None:
    # Issue 23: without an epsilon the undecided parts are searched again at
    # smaller epsilons (refined); a given epsilon keeps its fixed meaning;
    # "auto" refines.
    scene = SCENES / "decisive-slerp-pass-above.json"
    default = tmcert.load(scene).default_epsilon("probe", "plate")
    result = tmcert.verify(scene)
    (check,) = result.checks
    assert result.verdict == "safe" and check.refined and check.epsilon < default
    assert_views_agree(result)
    fixed = tmcert.verify(scene, epsilon=default)
    assert fixed.verdict == "undecided" and not fixed.checks[0].refined and fixed.checks[0].epsilon == default
    auto = tmcert.verify(scene, epsilon="auto")
    assert auto.verdict == "safe" and auto.checks[0].refined
