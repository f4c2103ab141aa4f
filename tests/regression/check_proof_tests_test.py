#!/usr/bin/env python3
"""scripts/check_proof_tests.py on a small made-up tree: proofs naming
existing Boost.Test cases (bare and as suite/case, with the `_exact`
shorthand), a Python test, a ctest name, scene files and paths pass; each
kind of stale name fails with its line.
Usage: check_proof_tests_test.py REPOSITORY_ROOT"""
import os, subprocess, sys, tempfile

SCRIPT = os.path.join(os.path.abspath(sys.argv[1]), "scripts", "check_proof_tests.py")
TREE = {
    "tests/unit/test_a.cpp": "BOOST_AUTO_TEST_SUITE(outer)\nBOOST_AUTO_TEST_SUITE(inner)\n"
                             "BOOST_AUTO_TEST_CASE(case_one_filtered) {}\nBOOST_AUTO_TEST_CASE(case_one_exact) {}\n"
                             "BOOST_AUTO_TEST_SUITE_END()\nBOOST_AUTO_TEST_SUITE_END()\n"
                             "RC_BOOST_PROP(prop_two, (int x)) {}\n",
    "tests/python/test_p.py": "def test_python_thing():\n    pass\n",
    "tests/CMakeLists.txt": "add_test(NAME my_ctest COMMAND true)\n",
    "tests/data/scenes/near-miss.json": "{}\n",
    "src/verify/search.h": "int min_sign();\n",
}
CLEAN = """# A proof

Uses `min_sign` and `enforceBounds` (src/verify/search.h).

## Checked by

- tests/unit/test_a.cpp: `outer/inner/case_one_filtered` / `_exact`,
  `inner/case_one_exact`, `prop_two`, `case_…`; `min_sign` itself.
- tests/python/test_p.py `test_python_thing`; the ctest `my_ctest`;
  `near-miss.json`, tests/data/scenes/near-*.json, `src/verify/search.{h}`.
"""


def run(proof):
    with tempfile.TemporaryDirectory() as root:
        for path, text in list(TREE.items()) + [("proofs/p.md", proof)]:
            os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
            with open(os.path.join(root, path), "w") as fh:
                fh.write(text)
        p = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True)
        return p.returncode, p.stdout + p.stderr


failures = 0


def expect(name, result, rc, text):
    global failures
    got_rc, out = result
    if got_rc != rc or text not in out:
        failures += 1
        print(f"FAIL {name}: exit {got_rc} (expected {rc}), output lacks {text!r}:\n{out}")
    else:
        print(f"ok   {name}")


expect("existing names", run(CLEAN), 0, "0 errors")
bad = CLEAN + "- `NAME`\n"
expect("a bogus bare case", run(bad.replace("NAME", "case_two_filtered")), 1,
       "proofs/p.md:11: `case_two_filtered`: names no test and nothing in the tree")
expect("a bogus suite/case", run(bad.replace("NAME", "outer/case_three")), 1,
       "`outer/case_three`: no Boost.Test suite/case of this path")
expect("a case in the wrong suite", run(bad.replace("NAME", "other/case_one_exact")), 1,
       "`other/case_one_exact`: no Boost.Test suite/case of this path")
expect("a bogus shorthand", run(CLEAN + "- `case_one_filtered` / `_fast`\n"), 1,
       "no test case_one_fast")
expect("a bogus Python test", run(bad.replace("NAME", "test_python_other")), 1,
       "`test_python_other`: no test function or file of this name")
expect("a bogus scene file", run(bad.replace("NAME", "far-miss.json")), 1,
       "`far-miss.json`: no file of this name in the tree")
expect("a bogus path", run(CLEAN + "- tests/unit/test_b.cpp\n"), 1,
       "proofs/p.md:11: no file tests/unit/test_b.cpp")
expect("a glob matching nothing", run(CLEAN + "- tests/data/scenes/far-*.json\n"), 1,
       "no file tests/data/scenes/far-*.json")
expect("a bogus prefix", run(bad.replace("NAME", "zz_…")), 1, "no test starts with zz_")
expect("a bogus name in the prose", run(CLEAN.replace("Uses `min_sign`", "Uses `case_one_fast`")), 1,
       "proofs/p.md:3: `case_one_fast`: names no test and nothing in the tree")
expect("a listed external name", run(CLEAN.replace("Uses `min_sign`", "Uses `enforceBounds`")), 0,
       "0 errors")
sys.exit(1 if failures else 0)
