"""Bad input raises tmcert.InputError (a ValueError) with the command line's
message (without its "tmcert: " prefix), whichever way the scene comes in."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

import tmcert
from conftest import DATA, SOURCE, builder_from_document, cli_error, run_cli

BAD = [(DATA / "bad" / name, substring)
       for name, substring in (line.split("\t") for line in (DATA / "bad" / "EXPECTED").read_text().splitlines()
                               if line and not line.startswith("#"))]
BAD_CLI = [(DATA / "bad-cli" / name, substring)
           for name, substring in (line.split("\t") for line in
                                   (DATA / "bad-cli" / "EXPECTED").read_text().splitlines()
                                   if line and not line.startswith("#"))]


def test_input_error_is_a_value_error() -> None:
    assert issubclass(tmcert.InputError, ValueError)
    assert issubclass(tmcert.ResourceLimit, RuntimeError)


@pytest.mark.parametrize("path,substring", BAD, ids=[p.name for p, _ in BAD])
def test_bad_scene_file_same_message_as_cli(path: Path, substring: str) -> None:
    message = cli_error("verify", str(path))
    assert substring in message
    with pytest.raises(tmcert.InputError) as error:
        tmcert.Scene.from_file(str(path))
    assert str(error.value) == message
    with pytest.raises(tmcert.InputError) as error:
        tmcert.verify(path)
    assert str(error.value) == message


def _no_duplicate_keys(pairs):
    keys = [k for k, _ in pairs]
    if len(keys) != len(set(keys)):
        raise ValueError("duplicate key")
    return dict(pairs)


def _as_document(path: Path):
    """The bad file as Python objects, when Python's JSON reader keeps everything the file says."""
    try:
        text = path.read_text()
        doc = json.loads(text, object_pairs_hook=_no_duplicate_keys,
                         parse_float=lambda s: __import__("decimal").Decimal(s),
                         parse_constant=lambda s: (_ for _ in ()).throw(ValueError(s)))
    except (ValueError, UnicodeDecodeError, RecursionError):
        return None
    return doc if isinstance(doc, dict) else None


DICT_BAD = [(path, doc) for path, _ in BAD if (doc := _as_document(path)) is not None]


@pytest.mark.parametrize("path,doc", DICT_BAD, ids=[p.name for p, _ in DICT_BAD])
def test_bad_dict_and_builder_same_message_as_cli(path: Path, doc) -> None:
    message = cli_error("verify", str(path))
    assert message.startswith(f"{path}: ")
    field_and_what = message[len(f"{path}: "):]
    with pytest.raises(tmcert.InputError) as error:
        tmcert.scene_from_dict(doc, base_dir=path.parent)
    assert str(error.value) == f"<dict>: {field_and_what}"
    # Through SceneBuilder where the document can be written with it (a
    # malformed document, e.g. a missing field, cannot).
    try:
        builder = builder_from_document(doc, path.parent)
    except (KeyError, TypeError, ValueError, AssertionError, AttributeError, IndexError, ArithmeticError):
        return
    with pytest.raises(tmcert.InputError) as error:
        builder.build()
    # The builder adds the body's name, e.g. ' (body "table")'.
    message = str(error.value)
    assert message == f"SceneBuilder: {field_and_what}" or \
        re.fullmatch(re.escape(f"SceneBuilder: {field_and_what}") + r' \((body|robot) "[^"]*"\)', message), message


@pytest.mark.parametrize("path,substring", BAD_CLI, ids=[p.name for p, _ in BAD_CLI])
def test_scene_the_verifier_refuses_same_message_as_cli(path: Path, substring: str) -> None:
    message = cli_error("verify", str(path))
    assert substring in message
    scene = tmcert.Scene.from_file(str(path))
    with pytest.raises(tmcert.InputError) as error:
        tmcert.verify(scene)
    assert str(error.value) == message


def test_missing_file_same_message_as_cli(tmp_path: Path) -> None:
    missing = tmp_path / "missing.json"
    message = cli_error("verify", str(missing))
    with pytest.raises(tmcert.InputError) as error:
        tmcert.verify(missing)
    assert str(error.value) == message


@pytest.mark.parametrize("kwargs,cli_options,field", [
    ({"epsilon": "-1/10"}, ("--epsilon", "-1/10"), "epsilon"),
    ({"epsilon": "x"}, ("--epsilon", "x"), "epsilon"),
    ({"max_depth": 0}, ("--max-depth", "0"), "max-depth"),
    ({"threads": 0}, ("--threads", "0"), "threads"),
    ({"time_limit": -1.0}, ("--time-limit", "-1"), "time-limit"),
])
def test_bad_options(kwargs, cli_options, field) -> None:
    scene = SOURCE / "examples" / "octagons-near.json"
    done = run_cli("verify", str(scene), *cli_options)
    assert done.returncode == 3 and done.stdout == ""
    cli_message = done.stderr
    with pytest.raises(tmcert.InputError) as error:
        tmcert.verify(scene, **kwargs)
    assert field.replace("-", "_") in str(error.value).replace("-", "_")
    assert field in cli_message


def test_options_beyond_c_integers() -> None:
    scene = SOURCE / "examples" / "octagons-near.json"
    with pytest.raises(tmcert.InputError, match=r"^max_depth: must be between 1 and 200, got 10{30}$"):
        tmcert.verify(scene, max_depth=10 ** 30)
    with pytest.raises(tmcert.InputError, match=r"^threads: must be between 1 and 256, got 1099511627776$"):
        tmcert.verify(scene, threads=2 ** 40)
    with pytest.raises(TypeError, match="max_depth: expected an integer"):
        tmcert.verify(scene, max_depth=2.5)


def test_bad_kernel() -> None:
    with pytest.raises(tmcert.InputError, match="kernel"):
        tmcert.verify(SOURCE / "examples" / "octagons-near.json", kernel="approximate")


def test_bad_arrays_name_the_argument() -> None:
    b = tmcert.SceneBuilder()
    body = b.add_body("box")
    with pytest.raises(tmcert.InputError, match=r"^box: vertices: expected an \(n, 3\) array"):
        body.polygons(np.zeros((4, 2)), [[0, 1, 2]])
    with pytest.raises(tmcert.InputError, match=r"^box: faces\[0\]\[1\]: negative vertex index -1"):
        body.polygons(np.zeros((4, 3)), [[0, -1, 2]])
    with pytest.raises(tmcert.InputError, match=r"^box: faces: expected an \(m, k\) integer array"):
        body.polygons(np.zeros((4, 3)), np.array([[0.0, 1.0, 2.0]]))
    with pytest.raises(tmcert.InputError, match=r"^box: segments: expected an \(m, 2, 3\) array"):
        body.segments(np.zeros((2, 3)))
    with pytest.raises(tmcert.InputError, match=r"^box: triangles: expected three vertex indices"):
        body.triangles(np.zeros((4, 3)), [[0, 1, 2, 3]])


def test_builder_index_out_of_range_and_duplicates() -> None:
    b = tmcert.SceneBuilder()
    with pytest.raises(tmcert.InputError,
                       match=r'^SceneBuilder: body "box": polygons: face 0: vertex index 7 is out of range'):
        b.add_body("box").polygons(np.eye(3), [[0, 1, 7]])
    b = tmcert.SceneBuilder()
    b.add_body("a").points(np.zeros((1, 3)))
    b.add_body("a").points(np.ones((1, 3)))
    with pytest.raises(tmcert.InputError, match=r"^SceneBuilder: bodies\[1\]\.name: "):
        b.build()


def test_bad_pose_and_interpolation() -> None:
    with pytest.raises(tmcert.InputError, match="interpolation"):
        tmcert.Keyframes([tmcert.Pose()], None, "linear")
    b = tmcert.SceneBuilder()
    b.add_body("wall").polygon([[1, 0, 0], [1, 1, 0], [1, 0, 1]])
    b.add_body("bar").segments([[[0, 0, 0], [1, 0, 0]]]).motion(tmcert.Keyframes(
        [tmcert.Pose(), tmcert.Pose((0, 0, 1), tmcert.Rotation.quaternion(0, 0, 0, 0))]))
    with pytest.raises(tmcert.InputError, match=r"^SceneBuilder: bodies\[1\]\.motion\.poses\[1\]\.rotation"):
        b.build()
