#!/usr/bin/env python3
"""scripts/check_layers.py on small made-up trees: a clean tree passes; an
upward include, a checker that reaches a forbidden folder, a stale exception
and a cycle fail; a cycle through a listed exception passes as known.
Usage: check_layers_test.py REPOSITORY_ROOT"""
import os, subprocess, sys, tempfile

SCRIPT = os.path.join(os.path.abspath(sys.argv[1]), "scripts", "check_layers.py")
TABLE = """kernels:
include:
src/low: kernels
src/mid: src/low
src/top: src/mid include
checker: src/top/check.cpp
checker-forbidden: src/mid
"""
CLEAN = {
    "kernels/k.h": "",
    "include/pub/api.h": '#include "pub/other.h"\n',
    "include/pub/other.h": "#include <vector>\n",
    "src/low/a.h": '#include "kernels/k.h"\n',
    "src/mid/b.h": '#include "src/low/a.h"\n#include "kernels/k.h"\n',
    "src/top/c.cpp": '#include "src/mid/b.h"\n#include "pub/api.h"\n',
    "src/top/check.cpp": '#include "src/top/check.h"\n#include "src/low/a.h"\n',
    "src/top/check.h": "",
}


def run(files, extra_table=""):
    with tempfile.TemporaryDirectory() as root:
        for path, text in list(CLEAN.items()) + list(files.items()):
            os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
            with open(os.path.join(root, path), "w") as fh:
                fh.write(text)
        os.makedirs(os.path.join(root, "cmake"))
        with open(os.path.join(root, "cmake", "layers.txt"), "w") as fh:
            fh.write(TABLE + extra_table)
        p = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True)
        return p.returncode, p.stdout


failures = 0


def expect(name, result, rc, text):
    global failures
    got_rc, out = result
    if got_rc != rc or text not in out:
        failures += 1
        print(f"FAIL {name}: exit {got_rc} (expected {rc}), output lacks {text!r}:\n{out}")
    else:
        print(f"ok   {name}")


expect("clean tree", run({}), 0, "0 errors")
expect("upward include", run({"src/low/up.cpp": '#include "src/mid/b.h"\n'}), 1,
       "src/low/up.cpp:1: includes src/mid/b.h: src/low may not use src/mid")
expect("include of an unlisted layer", run({"src/low/x.cpp": '#include "pub/api.h"\n'}), 1,
       "src/low may not use include")
expect("checker reaches a forbidden folder", run({"src/top/check.h": '#include "src/mid/b.h"\n'}), 1,
       "the checker reaches src/mid: src/mid/b.h <- src/top/check.h <- src/top/check.cpp")
expect("cycle", run({"src/low/up.cpp": '#include "src/mid/b.h"\n'}), 1, "cycle: src/low -> src/mid")
expect("cycle through an exception", run({"src/low/up.cpp": '#include "src/mid/b.h"\n'},
                                         "exception: src/low/up.cpp -> src/mid/b.h\n"), 0,
       "known cycle (through an exception): src/low -> src/mid")
expect("excepted include not followed by the checker",
       run({"src/top/check.h": '#include "src/mid/b.h"\n'}, "exception: src/top/check.h -> src/mid/b.h\n"), 0,
       "1 known exceptions, 0 errors")
expect("stale exception", run({}, "exception: src/low/a.h -> src/mid/b.h\n"), 1,
       "exception src/low/a.h -> src/mid/b.h no longer occurs")
expect("folder missing from the table", run({"src/new/n.h": ""}), 1, "folder src/new is not in cmake/layers.txt")
sys.exit(1 if failures else 0)
