#!/usr/bin/env python3
"""What a person watching a long run sees, timed (bench/README.md, "Progress and Ctrl-C").

    bench/progress_phases.py TMCERT_BINARY [--python PYTHON] [--size N] [--work DIR] [--no-terrain]

1. Generates a terrain mesh (an N x N grid of OBJ quads, heights with
   1e-7 of noise, so each quad is a fan of two triangles: 2 (N-1)^2
   triangles; N = 212: 89 042) and a box moving over it, then runs
   `tmcert verify --certificate` with stderr on a pseudo-terminal and
   prints when the first progress line came, and each activity's first and
   last time on the line: no phase of the run is silent.
2. With --python (an interpreter that imports tmcert): verifies the
   gripper scene with the exact kernel in a child process (about 45 s of
   CPU), sends it SIGINT 2 s after the verification started, and prints how
   long the child took to raise KeyboardInterrupt.
"""

import argparse
import math
import os
import pty
import random
import re
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path


def terrain(work: Path, n: int) -> Path:
    random.seed(1)
    with open(work / "terrain.obj", "w") as f:
        for i in range(n):
            for j in range(n):
                x, y = i / (n - 1) * 10, j / (n - 1) * 10
                f.write(f"v {x:.6f} {y:.6f} {0.3 * math.sin(x) * math.cos(y) + random.uniform(-1e-7, 1e-7):.9f}\n")
        for i in range(n - 1):
            for j in range(n - 1):
                a = i * n + j + 1
                f.write(f"f {a} {a + n} {a + n + 1} {a + 1}\n")
    scene = work / "terrain.json"
    scene.write_text(
        '{"format": "tmcert-scene/1", "bodies": [{"name": "terrain", "mesh": "terrain.obj"}, '
        '{"name": "box", "polygons": [[[0,0,0],[0.5,0,0],[0.5,0.5,0],[0,0.5,0]]], '
        '"motion": {"type": "rational_bezier", "control_points": [[[1,0,0,1],[0,1,0,1],[0,0,1,0.4]], '
        '[[1,0,0,5],[0,1,0,8],[0,0,1,0.2]], [[1,0,0,9],[0,1,0,2],[0,0,1,0.4]]]}}]}')
    return scene


def watch(args: list) -> None:
    main, secondary = pty.openpty()
    start = time.monotonic()
    child = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=secondary)
    os.close(secondary)
    first, spans, rest = None, {}, b""
    while True:
        try:
            data = os.read(main, 65536)
        except OSError:
            break
        if not data:
            break
        now = time.monotonic() - start
        rest += data
        *pieces, rest = rest.split(b"\r")
        for piece in pieces:
            text = piece.replace(b"\x1b[K", b"").decode(errors="replace").strip()
            m = re.match(r"tmcert: (?:(\d+)% of \d+ checks?, |.*? done, )?\d+ s: (.*)$", text)
            if not m:
                continue
            first = now if first is None else first
            activity = re.sub(r"\(.*", "", m.group(2)).strip()
            lo, hi, percents = spans.get(activity, (now, now, []))
            spans[activity] = (lo, now, percents + ([int(m.group(1))] if m.group(1) else []))
    code = child.wait()
    total = time.monotonic() - start
    print(f"exit {code}, {total:.1f} s; first progress line at {first:.2f} s" if first is not None
          else f"exit {code}, {total:.1f} s; no progress line")
    print("| activity on the line | first seen (s) | last seen (s) | share shown |")
    print("|---|---:|---:|---|")
    for activity, (lo, hi, percents) in sorted(spans.items(), key=lambda kv: kv[1][0]):
        shown = f"{min(percents)}% to {max(percents)}%" if percents else ""
        print(f"| {activity} | {lo:.1f} | {hi:.1f} | {shown} |")


def ctrl_c(python: str, source: Path) -> None:
    script = textwrap.dedent(f"""
        import tmcert
        said = []
        def running(p):
            if not said:
                said.append(1)
                print("running", flush=True)
        try:
            tmcert.verify({str(source / 'examples' / 'gripper' / 'gripper-safe.json')!r}, kernel="exact",
                          progress=running, progress_interval=0.1)
            print("finished")
        except KeyboardInterrupt:
            print("interrupted")
    """)
    child = subprocess.Popen([python, "-c", script], stdout=subprocess.PIPE, text=True)
    assert child.stdout is not None and child.stdout.readline().strip() == "running"
    time.sleep(2)  # two seconds into the verification
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate()
    print(f"SIGINT 2 s into verify: {out.strip()} {time.monotonic() - sent:.2f} s later")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("tmcert")
    parser.add_argument("--python")
    parser.add_argument("--size", type=int, default=212)
    parser.add_argument("--work")
    parser.add_argument("--no-terrain", action="store_true", help="only the Ctrl-C part")
    a = parser.parse_args()
    work = Path(a.work or tempfile.mkdtemp(prefix="tmcert-progress-"))
    work.mkdir(parents=True, exist_ok=True)
    if not a.no_terrain:
        scene = terrain(work, a.size)
        watch([a.tmcert, "verify", str(scene), "--certificate", str(work / "terrain.cert")])
    if a.python:
        ctrl_c(a.python, Path(__file__).resolve().parents[1])


if __name__ == "__main__":
    main()
