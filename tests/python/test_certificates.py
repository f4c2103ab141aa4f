"""Certificates: written by the CLI and checked from Python, written from
Python and checked by the CLI, and rejected alike."""

from __future__ import annotations

from pathlib import Path

import pytest

import tmcert
from conftest import DATA, SOURCE, cli_error, run_cli

CERTIFICATES = DATA / "certificates"


def cli_check_lines(certificate: Path, scene: Path) -> list:
    done = run_cli("check", str(certificate), str(scene))
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == "tmcert: certificate holds: every claim is proven"
    return [line[2:] for line in lines[1:]]


@pytest.mark.parametrize("scene", [SOURCE / "examples" / "octagons-near.json",
                                   SOURCE / "examples" / "vertex-face-linear.json",
                                   DATA / "scenes" / "planner-piecewise-second-piece.json",
                                   DATA / "scenes" / "planner-wall1-slerp.json",
                                   DATA / "scenes" / "cubic-crossing-irrational.json"],
                         ids=lambda p: p.name)
def test_cli_certificate_checked_from_python_and_back(scene: Path, tmp_path: Path) -> None:
    written_by_cli = tmp_path / "cli.cert.json"
    done = run_cli("verify", str(scene), "--certificate", str(written_by_cli))
    assert done.returncode in (0, 1), done.stderr
    proven = cli_check_lines(written_by_cli, scene)

    outcome = tmcert.check(written_by_cli, scene)
    assert outcome and outcome.ok and outcome.message == ""
    assert list(outcome.proven) == proven

    result = tmcert.verify(scene, certificate=True)
    written_by_python = tmp_path / "python.cert.json"
    result.write_certificate(written_by_python)
    assert written_by_python.read_text() == result.certificate()
    assert written_by_python.read_text() == written_by_cli.read_text()
    assert cli_check_lines(written_by_python, scene) == proven
    assert tmcert.check(result, scene).ok


def test_rejected_certificate_same_message_as_cli() -> None:
    certificate, scene = CERTIFICATES / "probe-safe-tampered.cert.json", CERTIFICATES / "probe-safe.json"
    done = run_cli("check", str(certificate), str(scene))
    assert done.returncode != 0 and done.stderr.startswith("tmcert: rejected: ")
    outcome = tmcert.check(certificate, scene)
    assert not outcome and outcome.message == done.stderr.rstrip("\n")[len("tmcert: rejected: "):]
    assert outcome.proven == ()


def test_malformed_certificate_is_an_input_error() -> None:
    certificate, scene = CERTIFICATES / "garbage.cert.json", CERTIFICATES / "probe-safe.json"
    message = cli_error("check", str(certificate), str(scene))
    with pytest.raises(tmcert.InputError) as error:
        tmcert.check(certificate, scene)
    assert str(error.value) == message


def test_certificate_needs_the_option() -> None:
    result = tmcert.verify(SOURCE / "examples" / "octagons-collision.json")
    with pytest.raises(tmcert.InputError, match="certificate"):
        result.certificate()


def test_write_certificate_output_paths(tmp_path: Path) -> None:
    # docs/scene-format.md "Output paths": an empty path, a directory or
    # the scene file itself is an InputError before anything is written; a
    # write that fails is a ResourceLimit naming the path, leaving no file.
    scene_text = (SOURCE / "examples" / "octagons-near.json").read_text()
    scene = tmp_path / "scene.json"
    scene.write_text(scene_text)
    result = tmcert.verify(scene, certificate=True)
    with pytest.raises(tmcert.InputError, match="empty"):
        result.write_certificate("")
    with pytest.raises(tmcert.InputError, match="directory"):
        result.write_certificate(tmp_path)
    with pytest.raises(tmcert.InputError, match="is the input file"):
        result.write_certificate(scene)
    with pytest.raises(tmcert.InputError, match="is the input file"):
        result.write_certificate(tmp_path / "." / "scene.json")
    assert scene.read_text() == scene_text
    if Path("/dev/full").exists():
        with pytest.raises(tmcert.ResourceLimit, match="/dev/full"):
            result.write_certificate("/dev/full")
    written = tmp_path / "written.cert.json"
    result.write_certificate(written)
    assert written.read_text() == result.certificate()


def test_write_report_and_batch_output_paths(tmp_path: Path) -> None:
    # The same rules for the report and batch outputs; an empty file name
    # is refused in Python (None is absent), never taken as the standard
    # output.
    scene_text = (SOURCE / "examples" / "octagons-near.json").read_text()
    scene = tmp_path / "scene.json"
    scene.write_text(scene_text)
    result = tmcert.verify(scene)
    with pytest.raises(tmcert.InputError, match="empty"):
        result.write_report("")
    with pytest.raises(tmcert.InputError, match="is the input file"):
        result.write_report(scene)
    assert scene.read_text() == scene_text
    if Path("/dev/full").exists():
        with pytest.raises(tmcert.ResourceLimit, match="/dev/full"):
            result.write_report("/dev/full")
    batch = SOURCE / "examples" / "batch"
    requests = tmp_path / "requests.jsonl"
    requests.write_bytes((batch / "requests.jsonl").read_bytes())
    with pytest.raises(tmcert.InputError, match="output: the file name is empty"):
        tmcert.batch(requests, scene=batch / "environment.json", output="")
    with pytest.raises(tmcert.InputError, match="scene: the file name is empty"):
        tmcert.batch(requests, scene="")
    with pytest.raises(tmcert.InputError, match="is the input file"):
        tmcert.batch(requests, scene=batch / "environment.json", output=requests)
    assert requests.read_bytes() == (batch / "requests.jsonl").read_bytes()
    with pytest.raises(tmcert.InputError, match="output: the file name is empty"):
        tmcert.batch_merge([requests], output="")
