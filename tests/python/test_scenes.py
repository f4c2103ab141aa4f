"""Scenes with known verdicts, read three ways (file, dict, SceneBuilder with
NumPy arrays), give the verdict of their EXPECTED list and the very result
document `tmcert verify --json` prints (up to the wall times)."""

from __future__ import annotations

import copy

from pathlib import Path

import pytest

import tmcert
from conftest import DATA, SOURCE, assert_views_agree, builder_from_document, cli_result, expected_verdicts, \
    read_document, without_seconds

EXIT_CODES = {"safe": 0, "collision": 1, "undecided": 2}

# Every scene of the lists.  The slowest (several seconds each through the
# CLI and three times here) stay with the CLI's own regression test; each
# feature they use is covered by the others (motion types, robots, solids,
# meshes, tolerances, clearances, irrational contact times).
SLOW = {"hover-grid-10.json", "robots/arm3-self-collision.json", "robots/arm3-self-collision-allowed.json",
        "robots/wand-cylinder-collision.json", "robots/wand-sphere-safe.json"}
SCENES = [(scene, verdict)
          for listing in (DATA / "scenes" / "EXPECTED", SOURCE / "examples" / "EXPECTED")
          for scene, verdict in expected_verdicts(listing)
          if str(scene.relative_to(listing.parent)) not in SLOW]
IDS = [str(scene.relative_to(SOURCE)) for scene, _ in SCENES]


def test_the_lists_cover_every_motion_type_and_feature() -> None:
    seen = set()

    def motions(m):
        seen.add(m["type"] + ("/" + m.get("interpolation", "slerp") if m["type"] == "keyframes" else ""))
        for piece in m.get("pieces", []):
            motions(piece)

    for scene, _ in SCENES:
        doc = read_document(scene)
        seen.update(key for key in ("robots", "checks", "clearance") if key in doc)
        for body in doc.get("bodies", []):
            seen.update(key for key in ("mesh", "solid", "mass", "tolerance", "segments", "points") if key in body)
            if "motion" in body:
                motions(body["motion"])
    assert seen >= {"rational_bezier", "keyframes/slerp", "keyframes/screw", "keyframes/nlerp", "piecewise",
                    "robots", "checks", "clearance", "mesh", "solid", "mass", "tolerance", "segments", "points"}


@pytest.mark.parametrize("scene,verdict", SCENES, ids=IDS)
def test_file_dict_and_builder_agree_with_the_cli(scene: Path, verdict: str) -> None:
    code, expected = cli_result(scene)
    assert code == EXIT_CODES[verdict] and expected["verdict"] == verdict

    from_file = tmcert.verify(scene)
    assert from_file.verdict == verdict
    assert without_seconds(from_file.to_dict()) == expected
    assert_views_agree(from_file)

    # Notes and warnings name their source ("<dict>", "SceneBuilder"), not the file.
    def same_but_source(document: dict) -> dict:
        for key in ("notes", "warnings"):
            if key in document:
                document[key] = [note.split(": ", 1)[1] for note in document[key]]
        return document

    expected = same_but_source(copy.deepcopy(expected))
    doc = read_document(scene)
    from_dict = tmcert.verify(tmcert.scene_from_dict(doc, base_dir=scene.parent))
    assert same_but_source(without_seconds(from_dict.to_dict())) == expected

    built = builder_from_document(doc, scene.parent)
    from_arrays = tmcert.verify(built)
    assert same_but_source(without_seconds(from_arrays.to_dict())) == expected
    # The builder's own document is the same scene again.
    assert same_but_source(without_seconds(tmcert.verify(tmcert.Scene.from_json(built.to_json())).to_dict())) == expected


def test_options_agree_with_the_cli() -> None:
    scene = SOURCE / "examples" / "octagons-near.json"
    for kwargs, options in (
            ({"epsilon": "1/100"}, ("--epsilon", "1/100")),
            ({"max_depth": 5}, ("--max-depth", "5")),
            ({"kernel": "exact"}, ("--kernel", "exact")),
            ({"kernel": "fast"}, ("--kernel", "fast")),
            ({"threads": 2}, ("--threads", "2"))):
        _, expected = cli_result(scene, *options)
        result = tmcert.verify(scene, **kwargs)
        assert without_seconds(result.to_dict()) == expected, kwargs
        assert result.certified == (kwargs.get("kernel") != "fast")
