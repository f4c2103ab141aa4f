#!/usr/bin/env python3
"""Records what a tmcert binary says about every bundled example scene and
every test scene, so that two builds can be compared byte for byte (a
restructuring must not change any of it).

    scripts/compare_outputs.py --tmcert OLD/tmcert --out /tmp/before
    scripts/compare_outputs.py --tmcert NEW/tmcert --out /tmp/after
    diff -r /tmp/before /tmp/after          # empty: no behaviour change

For each scene (examples/**/*.json and tests/data/scenes/*.json that are
tmcert-scene/1 documents) it stores, under OUT/<scene path>/:
  verify.json     stdout of `tmcert verify --json SCENE`, then its exit code
  certificate     the bytes `tmcert verify --certificate FILE SCENE` writes
                  (and its exit code and stderr in certificate.rc)
  check           stdout, stderr and exit code of `tmcert check` on it
  report.html     the page `tmcert verify --report FILE SCENE` writes
Wall-clock fields are masked: every JSON "seconds" value (the only stats
field that is not deterministic) becomes "seconds": "*".  Scenes run in
parallel (--jobs, default 2); each run has a time limit (--timeout, default
120 s) after which its record says "timeout".
"""
import argparse, concurrent.futures, json, os, re, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SECONDS = re.compile(rb'("seconds"\s*:\s*)(-?[0-9][0-9.eE+-]*)')


def mask(data: bytes) -> bytes:
    return SECONDS.sub(rb'\1"*"', data)


def scenes():
    out = []
    for top in ("examples", "tests/data/scenes"):
        for dp, _, fn in os.walk(os.path.join(ROOT, top)):
            for f in sorted(fn):
                if not f.endswith(".json"):
                    continue
                path = os.path.join(dp, f)
                try:
                    with open(path, encoding="utf-8") as fh:
                        doc = json.load(fh)
                except (ValueError, UnicodeDecodeError):
                    continue
                if isinstance(doc, dict) and doc.get("format") == "tmcert-scene/1":
                    out.append(os.path.relpath(path, ROOT))
    return sorted(out)


def run(cmd, timeout):
    try:
        p = subprocess.run(cmd, cwd=ROOT, capture_output=True, timeout=timeout)
        return p.stdout, p.stderr, str(p.returncode).encode()
    except subprocess.TimeoutExpired:
        return b"", b"", b"timeout"


def record(tmcert, scene, out, timeout):
    d = os.path.join(out, scene)
    os.makedirs(d, exist_ok=True)
    o, e, rc = run([tmcert, "verify", "--json", scene], timeout)
    with open(os.path.join(d, "verify.json"), "wb") as fh:
        fh.write(mask(o) + b"\n--- stderr\n" + mask(e) + b"\n--- exit " + rc + b"\n")
    with tempfile.TemporaryDirectory() as tmp:
        cert = os.path.join(tmp, "certificate.json")
        o, e, rc = run([tmcert, "verify", "--certificate", cert, scene], timeout)
        with open(os.path.join(d, "certificate.rc"), "wb") as fh:
            fh.write(mask(o) + b"\n--- stderr\n" + e.replace(tmp.encode(), b"TMP") + b"\n--- exit " + rc + b"\n")
        if os.path.exists(cert):
            with open(cert, "rb") as fh:
                data = fh.read()
            with open(os.path.join(d, "certificate"), "wb") as fh:
                fh.write(data)
            o, e, rc = run([tmcert, "check", cert], timeout)
            with open(os.path.join(d, "check"), "wb") as fh:
                fh.write((o + b"\n--- stderr\n" + e + b"\n--- exit " + rc + b"\n").replace(tmp.encode(), b"TMP"))
        page = os.path.join(tmp, "report.html")
        o, e, rc = run([tmcert, "verify", "--report", page, scene], timeout)
        data = b""
        if os.path.exists(page):
            with open(page, "rb") as fh:
                data = fh.read()
        with open(os.path.join(d, "report.html"), "wb") as fh:
            fh.write(mask(data) + b"\n--- exit " + rc + b"\n")
    return scene


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tmcert", required=True, help="the tmcert binary to record")
    ap.add_argument("--out", required=True, help="directory for the records (created)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=120)
    a = ap.parse_args()
    tmcert = os.path.abspath(a.tmcert)
    todo = scenes()
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        for s in pool.map(lambda s: record(tmcert, s, os.path.abspath(a.out), a.timeout), todo):
            pass
    print(f"{len(todo)} scenes recorded in {a.out}")


if __name__ == "__main__":
    sys.exit(main())
