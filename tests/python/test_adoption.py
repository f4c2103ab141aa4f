"""What a new user reaches from Python: progress and cancellation (the
callback, KeyboardInterrupt), batch runs and their merge, the visual
report, the reader's notes and warnings, and the package without NumPy."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path
from typing import List

import pytest

import tmcert
from conftest import CLI, DATA, SOURCE

GRIPPER = SOURCE / "examples" / "gripper" / "gripper-safe.json"
BATCH = SOURCE / "examples" / "batch"


def test_progress_reports_are_honest() -> None:
    reports: List[tmcert.Progress] = []
    result = tmcert.verify(GRIPPER, progress=lambda p: reports.append(p), progress_interval=0.001)
    assert result.verdict == "safe"
    assert reports and isinstance(reports[0], tmcert.Progress)
    last = reports[-1]
    assert last.fraction == 1.0 and last.checks_done == last.checks == len(result.checks)
    for before, after in zip(reports, reports[1:]):
        assert before.fraction < 1.0 or before.checks_done == before.checks, "100% with a check left"
        assert before.fraction <= after.fraction and before.seconds <= after.seconds


def test_a_callback_cancels() -> None:
    with pytest.raises(tmcert.Cancelled):
        tmcert.verify(GRIPPER, progress=lambda p: False, progress_interval=0.001)

    def broken(p: tmcert.Progress) -> None:
        raise LookupError("from the callback")

    with pytest.raises(LookupError, match="from the callback"):
        tmcert.verify(GRIPPER, progress=broken, progress_interval=0.001)
    with pytest.raises(TypeError):
        tmcert.verify(GRIPPER, progress=42)  # type: ignore[arg-type]
    with pytest.raises(tmcert.InputError, match="progress_interval"):
        tmcert.verify(GRIPPER, progress_interval=0)


def test_keyboard_interrupt_cancels_a_running_verify() -> None:
    # Ctrl-C while verify runs: the SIGINT handler's KeyboardInterrupt comes
    # out of verify (the run is cancelled), never a result.
    seen: List[float] = []

    def interrupt(p: tmcert.Progress) -> None:
        if not seen:
            seen.append(p.fraction)
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        tmcert.verify(GRIPPER, progress=interrupt, progress_interval=0.001)
    assert seen and seen[0] < 1.0, "the signal came after the run"


def test_ctrl_c_in_a_python_process() -> None:
    # As a person presses Ctrl-C: SIGINT to a Python process inside a long
    # verify (the exact kernel on the gripper, many seconds): it stops with
    # KeyboardInterrupt, long before the verification would have ended.
    script = textwrap.dedent(f"""
        import sys, time, tmcert
        start = time.monotonic()
        printed = []
        def started(p):
            if not printed:
                printed.append(p)
                print("running", flush=True)
        try:
            tmcert.verify({str(GRIPPER)!r}, kernel="exact", progress=started, progress_interval=0.05)
            print("finished", time.monotonic() - start)
        except KeyboardInterrupt:
            print("interrupted", time.monotonic() - start)
    """)
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True, env=os.environ)
    assert child.stdout is not None
    assert child.stdout.readline().strip() == "running"
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=120)
    waited = time.monotonic() - sent
    assert out.strip().splitlines()[-1].startswith("interrupted"), out
    # The run is cancelled, not waited for: a generous bound (the exact
    # kernel on this scene runs far longer; bench/ measures the latency).
    assert waited < 20, f"{waited:.1f} s after SIGINT"


def test_batch_and_merge(tmp_path: Path) -> None:
    cli = subprocess.run([CLI, "batch", str(BATCH / "requests.jsonl"), "--scene", str(BATCH / "environment.json")],
                         capture_output=True, text=True)
    summary = tmcert.batch(BATCH / "requests.jsonl", scene=BATCH / "environment.json")
    assert summary.exit_code == cli.returncode == 1
    assert (summary.requests, summary.safe, summary.collision, summary.undecided, summary.errors) == (5, 4, 1, 0, 0)
    assert summary.results == tuple(json.loads(line) for line in cli.stdout.splitlines())
    # Shards merged: the bytes of the unsharded run.
    shards = []
    for i in range(3):
        out = tmp_path / f"shard-{i}.jsonl"
        assert tmcert.batch(BATCH / "requests.jsonl", scene=BATCH / "environment.json", shard=f"{i}/3",
                            output=out).results is None
        shards.append(out)
    assert tmcert.batch_merge(reversed(shards)) == cli.stdout
    tmcert.batch_merge(shards, tmp_path / "merged.jsonl")
    assert (tmp_path / "merged.jsonl").read_text() == cli.stdout
    # Requests given as dicts; the environment as the first line.
    lines = [json.loads(line) for line in (BATCH / "requests.jsonl").read_text().splitlines() if line.strip()]
    env = json.loads((BATCH / "environment.json").read_text())
    again = tmcert.batch([env] + lines)
    assert again.results == summary.results
    with pytest.raises(tmcert.InputError, match="shard"):
        tmcert.batch(BATCH / "requests.jsonl", scene=BATCH / "environment.json", shard="3/3")


def test_report(tmp_path: Path) -> None:
    result = tmcert.verify(SOURCE / "examples" / "octagons-collision.json")
    page = result.report_html()
    assert page.startswith("<!DOCTYPE html>") and "tmcert-result/1" in page
    result.write_report(tmp_path / "r.html")
    assert (tmp_path / "r.html").read_text(encoding="utf-8") == page


def test_notes_and_warnings() -> None:
    plate = tmcert.verify(DATA / "scenes" / "pipeline-quad-off-plane.json")
    assert len(plate.notes) == 1 and "not exactly planar" in plate.notes[0] and plate.warnings == ()
    assert plate.to_dict()["notes"] == list(plate.notes)
    degrees = tmcert.load(DATA / "scenes" / "pipeline-rpy-degrees.json")
    assert len(degrees.warnings) == 1 and "rpy[2]: the angle 90 is more than 2 pi" in degrees.warnings[0]
    assert tmcert.verify(degrees).warnings == tuple(degrees.warnings)
    assert tmcert.verify(SOURCE / "examples" / "octagons-near.json").notes == ()


def test_without_numpy() -> None:
    # NumPy is optional: blocked, the package imports, builds scenes from
    # lists and gives tuples of floats.
    script = textwrap.dedent(f"""
        import sys
        sys.modules["numpy"] = None  # import numpy fails
        import tmcert
        r = tmcert.verify({str(SOURCE / "examples" / "vertex-face-linear.json")!r})
        w = r.checks[0].witness
        print(r.verdict, w.t, w.point_float)
        b = tmcert.SceneBuilder()
        b.add_body("table").triangles([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
        b.add_body("p").points([[0.25, 0.25, 1]]).motion(tmcert.Motion.translation((0, 0, 0), (0, 0, -2)))
        print(tmcert.verify(b).verdict)
    """)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=os.environ)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == ["collision 1/2 (0.2, 0.2, 0.0)", "collision"]
