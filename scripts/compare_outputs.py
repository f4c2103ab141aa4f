#!/usr/bin/env python3
"""Records what a tmcert binary says about every bundled example scene and
every test scene, so that two builds can be compared byte for byte (a
restructuring must not change any of it).

    scripts/compare_outputs.py --tmcert OLD/tmcert --out /tmp/before
    scripts/compare_outputs.py --tmcert NEW/tmcert --out /tmp/after
    diff -r /tmp/before /tmp/after          # empty: no behaviour change

For each scene (examples/**/*.json and tests/data/scenes/*.json that are
tmcert-scene/1 documents) it stores, under OUT/<scene path>/:
  verify.json     stdout, stderr and exit code of
                  `tmcert verify --json --report PAGE --certificate CERT SCENE`
  verify.json.report.html   the page it wrote
  certificate     the certificate it wrote, and `check` the stdout, stderr
                  and exit code of `tmcert check CERT SCENE`
  verify-without-certificate.json (and .report.html)   where no certificate
                  was written, the same run without --certificate
Wall-clock fields are masked: every JSON "seconds" value (the only stats
field that is not deterministic; also HTML-escaped in the page) becomes
"seconds": "*", and the writer's
time on stderr ("..., 0.0123 s)") becomes "* s)".  Scenes run in
parallel (--jobs, default 2); each run has a time limit (--timeout, default
300 s) after which its record says "timeout".
"""
import argparse, concurrent.futures, json, os, re, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SECONDS = re.compile(rb'((?:"|&quot;)seconds(?:"|&quot;)\s*:\s*)(-?[0-9][0-9.eE+-]*)')
# The writer's time on stderr: "(2 pieces, 2 separations, 0.0123 s)".
STDERR_SECONDS = re.compile(rb'(, )[0-9][0-9.eE+-]* s\)')


def mask(data: bytes) -> bytes:
    return STDERR_SECONDS.sub(rb'\1* s)', SECONDS.sub(rb'\1"*"', data))


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


def save(path, data):
    with open(path, "wb") as fh:
        fh.write(data)


def record(tmcert, scene, out, timeout):
    d = os.path.join(out, scene)
    os.makedirs(d, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        cert = os.path.join(tmp, "certificate.json")
        page = os.path.join(tmp, "report.html")

        def verify(name, extra):
            o, e, rc = run([tmcert, "verify", "--json", "--report", page] + extra + [scene], timeout)
            save(os.path.join(d, name), mask(o) + b"\n--- stderr\n" + mask(e).replace(tmp.encode(), b"TMP") +
                 b"\n--- exit " + rc + b"\n")
            if os.path.exists(page):
                with open(page, "rb") as fh:
                    save(os.path.join(d, name + ".report.html"), mask(fh.read()))
                os.remove(page)

        # One run for the result, the page and the certificate; where no
        # certificate is written (a scene certificates do not cover, a fast
        # result), the result and page again without asking for one.
        verify("verify.json", ["--certificate", cert])
        if os.path.exists(cert):
            with open(cert, "rb") as fh:
                save(os.path.join(d, "certificate"), fh.read())
            o, e, rc = run([tmcert, "check", cert, scene], timeout)
            save(os.path.join(d, "check"), (o + b"\n--- stderr\n" + e + b"\n--- exit " + rc + b"\n").replace(tmp.encode(), b"TMP"))
        else:
            verify("verify-without-certificate.json", [])
    return scene


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tmcert", required=True, help="the tmcert binary to record")
    ap.add_argument("--out", required=True, help="directory for the records (created)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("only", nargs="*", help="record only the scenes whose path contains one of these")
    a = ap.parse_args()
    tmcert = os.path.abspath(a.tmcert)
    todo = [s for s in scenes() if not a.only or any(o in s for o in a.only)]
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        for s in pool.map(lambda s: record(tmcert, s, os.path.abspath(a.out), a.timeout), todo):
            pass
    print(f"{len(todo)} scenes recorded in {a.out}")


if __name__ == "__main__":
    sys.exit(main())
