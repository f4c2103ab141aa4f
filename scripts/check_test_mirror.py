#!/usr/bin/env python3
"""tests/ mirrors src/: every header of kernels/ and src/ has a test that
includes it.

    python3 scripts/check_test_mirror.py [--quiet] [ROOT]   # exit 0 clean, 1 otherwise

A header H (kernels/X.h, src/F/X.h) counts as tested when some .cpp or .h
under tests/ has the line #include "H".  The headers that have none yet are
listed, one a line with the reason, in tests/untested_headers.txt: a
header missing from the list and from the tests fails, and so does a
listed header that now has a test (take it off the list) or that no longer
exists.  src/python/ and src/cli/ are programs tested end to end
(tests/python, tests/regression) and are not scanned.
"""
import os
import re
import sys

args = [a for a in sys.argv[1:] if a != "--quiet"]
quiet = "--quiet" in sys.argv[1:]
root = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(os.path.realpath(__file__)), ".."))

headers = []
for top in ("kernels", "src"):
    for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
        rel = os.path.relpath(dirpath, root)
        if rel.startswith(("src/python", "src/cli")):
            continue
        headers += [os.path.join(rel, f) for f in filenames if f.endswith(".h")]

included = set()
for dirpath, _, filenames in os.walk(os.path.join(root, "tests")):
    for f in filenames:
        if f.endswith((".cpp", ".h")):
            with open(os.path.join(dirpath, f), errors="replace") as fh:
                included.update(re.findall(r'^\s*#\s*include\s*"([^"]+)"', fh.read(), re.M))

listed = {}
list_path = os.path.join(root, "tests", "untested_headers.txt")
if os.path.exists(list_path):
    with open(list_path) as fh:
        for n, line in enumerate(fh, 1):
            line = line.split("#", 1)[0].strip()
            if line:
                listed[line.split()[0]] = n

problems = []
for h in sorted(headers):
    if h in included and h in listed:
        problems.append(f"tests/untested_headers.txt:{listed[h]}: {h} has a test now: take it off the list")
    elif h not in included and h not in listed:
        problems.append(f"{h}: no test under tests/ includes it (add one, e.g. tests/{os.path.dirname(h).removeprefix('src/')}/test_{os.path.basename(h)[:-2]}.cpp)")
for h, n in sorted(listed.items()):
    if h not in headers:
        problems.append(f"tests/untested_headers.txt:{n}: {h} does not exist")

for p in problems:
    print(p)
if not quiet or problems:
    tested = sum(1 for h in headers if h in included)
    print(f"{len(headers)} headers, {tested} with a test including them, {len(listed)} listed as untested")
sys.exit(1 if problems else 0)
