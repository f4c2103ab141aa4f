#!/usr/bin/env python3
"""The command line's progress line on a terminal (a pseudo-terminal here).

    progress_tty.py TMCERT_BINARY SOURCE_DIR

Runs `tmcert verify` on the gripper scene with stderr on a pseudo-terminal
and TMCERT_PROGRESS_AFTER=0 (lines from the start instead of after two
seconds, so that the test does not depend on the machine's speed), stdout
on a pipe, and checks: progress lines come ("tmcert: P% of N checks, S s:
ACTIVITY"), P never falls and is never 100 while a check is left, the
activities are named, the line is erased ("\\r\\033[K") before the run ends,
the summary is on stdout unchanged; with --certificate the writing of the
certificate is the activity after the checks ("all N checks done"), never
a silent phase after 100%.  Without a terminal nothing is printed.

Ends with "N passed, M failed"; exits 1 on any failure.
"""

import os
import pty
import re
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import List, Tuple

LINE = re.compile(r"tmcert: (?:(\d+)% of (\d+) checks?, |(all \d+ checks|the check is) done, )?(\d+) s(?:: (.*))?$")


def run_on_tty(args: List[str]) -> Tuple[int, str, bytes]:
    """(exit code, stdout, everything written to the terminal)."""
    main, secondary = pty.openpty()
    env = dict(os.environ, TMCERT_PROGRESS_AFTER="0")
    child = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=secondary, env=env)
    os.close(secondary)
    chunks = []
    while True:
        try:
            data = os.read(main, 65536)
        except OSError:  # EIO: the child closed the terminal
            break
        if not data:
            break
        chunks.append(data)
    out = child.stdout.read().decode() if child.stdout else ""
    code = child.wait()
    os.close(main)
    return code, out, b"".join(chunks)


def progress_lines(terminal: bytes) -> List[str]:
    """The progress lines as the terminal showed them (each after a carriage return)."""
    text = terminal.decode(errors="replace").replace("\r\n", "\n")
    lines = []
    for piece in text.split("\r"):
        piece = piece.replace("\033[K", "")
        if piece.startswith("tmcert: ") and LINE.match(piece.strip()):
            lines.append(piece.strip())
    return lines


def main() -> int:
    tmcert, src = sys.argv[1], Path(sys.argv[2])
    scene = src / "examples" / "gripper" / "gripper-safe.json"
    passed, failed = 0, 0

    def check(ok: bool, what: str) -> None:
        nonlocal passed, failed
        if ok:
            passed += 1
        else:
            failed += 1
            print(f"FAIL: {what}")

    plain = subprocess.run([tmcert, "verify", str(scene)], capture_output=True, text=True)
    check(plain.returncode == 0 and plain.stderr == "", f"without a terminal: exit {plain.returncode}, "
                                                        f"stderr {plain.stderr!r} (nothing expected)")

    with tempfile.TemporaryDirectory() as work:
        cert = Path(work) / "gripper.cert"
        code, out, terminal = run_on_tty([tmcert, "verify", str(scene), "--certificate", str(cert)])
        check(code == 0, f"exit {code} on a terminal")
        lines = progress_lines(terminal)
        check(len(lines) >= 1, f"no progress line on the terminal: {terminal[:300]!r}")
        percents = []
        for line in lines:
            m = LINE.match(line)
            if m and m.group(1) is not None:
                percents.append(int(m.group(1)))
        check(all(p < 100 for p in percents), f"100% while a check is left: {lines}")
        check(percents == sorted(percents), f"the share goes back: {percents}")
        activities = {LINE.match(line).group(5) or "" for line in lines}
        check(any(a.startswith(("reading ", "checking ", "bounding ")) for a in activities),
              f"no activity named before the end: {sorted(activities)}")
        # After the checks: the certificate is written under its own name,
        # never a silent phase after 100%.
        after = [line for line in lines if LINE.match(line).group(3) is not None]
        check(all("writing the certificate" in line for line in after), f"after the checks: {after}")
        # Erased before the run ends: the last thing on the terminal about
        # progress is the erase sequence.
        tail = terminal.decode(errors="replace")
        last_line = tail.rfind("\rtmcert: ")
        check(tail.find("\r\033[K", last_line) > last_line, f"the line is not erased: {tail[-200:]!r}")
        def timeless(text: str) -> str:  # the summary without its wall times
            return re.sub(r", [0-9.e+-]+ s\)", ")", text)

        check(timeless(out) == timeless(plain.stdout), f"the summary on stdout differs: {out!r}")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
