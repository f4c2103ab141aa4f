#!/usr/bin/env python3
"""The proofs' test names: every test that proofs/*.md names must exist.

    python3 scripts/check_proof_tests.py [--quiet] [ROOT]   # exit 0 clean, 1 stale names

What counts as a name of a test, and what it must match (ROOT the
repository):

- a Boost.Test case or suite, in backticks, as `suite/case` (any trailing
  part of its suite path: `case`, `suite/case`, `outer/suite/case`) or as
  a bare `case`: a BOOST_AUTO_TEST_CASE, BOOST_FIXTURE_TEST_CASE,
  BOOST_DATA_TEST_CASE or RC_BOOST_PROP of tests/ (suites from
  BOOST_AUTO_TEST_SUITE / BOOST_FIXTURE_TEST_SUITE);
- a Python test function `test_...` (def test_... in tests/ or python/);
- a ctest name (add_test(NAME ...) in a CMakeLists.txt of the tree);
- a file, backticked or not, written as a path of the tree
  (tests/..., examples/..., scripts/..., bench/..., src/..., kernels/...,
  include/...; `*` as in a shell glob), or as a bare file name ending in
  .json/.cpp/.py/.sh (a scene of tests/data or examples, a test file):
  some file of the tree must have that name;
- the shorthands of the proofs: `_exact` after `name_filtered` means the
  name with its last part(s) replaced (`name_exact`); `a2_…` means some
  test starting with `a2_`.

A backticked bare identifier that is none of these (`min_sign`,
`free_at`) is a name of the code: it must occur as a word somewhere in the
tree outside proofs/ and docs/, so that a test renamed or removed (and so
absent from the tree) is reported however and wherever the proof spelt it.
Names of other libraries and of the mathematics that the proofs use are
listed in EXTERNAL below (a new one is added there deliberately).
Backticked text that is not a name (code, JSON, expressions, options
starting with -) is not checked.
"""
import fnmatch, os, re, sys

BOOST_CASE = re.compile(
    r'^\s*(BOOST_AUTO_TEST_CASE|BOOST_FIXTURE_TEST_CASE|BOOST_DATA_TEST_CASE|RC_BOOST_PROP)\s*\(\s*(\w+)')
BOOST_SUITE = re.compile(r'^\s*(BOOST_AUTO_TEST_SUITE|BOOST_FIXTURE_TEST_SUITE)\s*\(\s*(\w+)')
BOOST_SUITE_END = re.compile(r'^\s*BOOST_AUTO_TEST_SUITE_END\s*\(')
PY_TEST = re.compile(r'^\s*(?:async\s+)?def\s+(test_\w+)\s*\(')
CTEST = re.compile(r'add_test\s*\(\s*NAME\s+([\w.-]+)')
BACKTICK = re.compile(r'`([^`\n]+)`')
TREE_PATH = re.compile(r'(?<![\w/.-])((?:tests|examples|scripts|bench|src|kernels|include|python|docs|cmake)/[\w./*{},-]*[\w*}])')
IDENT = re.compile(r'^[A-Za-z_]\w*$')
FILE_NAME = re.compile(r'^[\w.*-]+\.(?:json|cpp|py|sh)$')
# Backticked names in proofs/ that are not of this tree: CGAL, MPFR, OMPL
# and the mathematics' symbols.
EXTERNAL = {
    "CGAL_USE_SSE2", "Assertion_exception", "is_valid",   # CGAL
    "emin",                                                # MPFR
    "enforceBounds",                                       # OMPL
    "sin_cos", "M_a", "M_b",                               # notation
}
SKIP_DIRS = {".git", "build", "third_party", "node_modules", "__pycache__"}
WORD = re.compile(r'\w+')


class Inventory:
    def __init__(self, root):
        self.root = root
        self.boost_paths = set()   # "suite/inner/case" and "suite/inner" (suites)
        self.boost_names = set()   # bare case and suite names
        self.python = set()
        self.ctest = set()
        self.files = []            # every file of the tree, relative
        self.basenames = set()
        self.words = set()         # words of the tree outside proofs/ and docs/
        for dirpath, dirnames, filenames in os.walk(root):
            dirnames[:] = [d for d in dirnames if d not in SKIP_DIRS and not d.startswith("build")]
            rel_dir = os.path.relpath(dirpath, root)
            for name in filenames:
                rel = os.path.normpath(os.path.join(rel_dir, name))
                self.files.append(rel)
                self.basenames.add(name)
                self.read(rel)

    def read(self, rel):
        top = rel.split(os.sep)[0]
        text_like = rel.endswith((".cpp", ".h", ".hpp", ".py", ".pyi", ".txt", ".sh", ".cmake", ".md", ".json"))
        if not text_like or rel.endswith(".json") and not rel.startswith("tests"):
            return
        try:
            with open(os.path.join(self.root, rel), encoding="utf-8", errors="replace") as fh:
                text = fh.read()
        except OSError:
            return
        if top not in ("proofs", "docs") and not rel.endswith(".json"):
            self.words.update(WORD.findall(text))
        if rel.endswith(".cpp") and top == "tests":
            suites = []
            for line in text.splitlines():
                m = BOOST_SUITE.match(line)
                if m:
                    suites.append(m.group(2))
                    self.boost_names.add(m.group(2))
                    self.boost_paths.add("/".join(suites))
                    continue
                if BOOST_SUITE_END.match(line):
                    if suites:
                        suites.pop()
                    continue
                m = BOOST_CASE.match(line)
                if m:
                    self.boost_names.add(m.group(2))
                    self.boost_paths.add("/".join(suites + [m.group(2)]))
        if rel.endswith(".py") and top in ("tests", "python"):
            for line in text.splitlines():
                m = PY_TEST.match(line)
                if m:
                    self.python.add(m.group(1))
        if os.path.basename(rel) == "CMakeLists.txt" or rel.endswith(".cmake"):
            self.ctest.update(CTEST.findall(text))

    def is_test(self, name):
        return name in self.boost_names or name in self.python or name in self.ctest

    def test_names(self):
        return self.boost_names | self.python | self.ctest

    def boost_path(self, path):
        """`a/b` names a test if some suite path ends with it."""
        return any(p == path or p.endswith("/" + path) for p in self.boost_paths)

    def path_exists(self, path):
        path = path.rstrip("/.")
        m = re.search(r"\{([^{}]*)\}", path)
        if m:   # src/motion/bezier.{h,cpp}: each
            return all(self.path_exists(path[:m.start()] + alt + path[m.end():])
                       for alt in m.group(1).split(","))
        if not os.path.splitext(path)[1]:   # kernels/real_roots: the .h/.cpp pair
            if any(self.path_exists(path + ext) for ext in (".h", ".cpp", ".hpp")):
                return True
        if any(c in path for c in "*?["):
            return any(fnmatch.fnmatchcase(f, path) for f in self.files)
        full = os.path.join(self.root, path)
        return os.path.exists(full)

    def basename_exists(self, name):
        if any(c in name for c in "*?["):
            return any(fnmatch.fnmatchcase(b, name) for b in self.basenames)
        return name in self.basenames


def check_file(inv, rel, text):
    errors = []
    previous = None   # the last full test name, for the `_exact` shorthand
    checked_by = False  # inside a "Checked by" part (to the next heading)
    for n, line in enumerate(text.splitlines(), 1):
        if line.startswith("#"):
            checked_by = "checked by" in line.lower()
        elif "Checked by" in line:
            checked_by = True
        for m in TREE_PATH.finditer(line):
            path = m.group(1)
            if not inv.path_exists(path):
                errors.append(f"{rel}:{n}: no file {path}")
        for m in BACKTICK.finditer(line):
            token = m.group(1).strip()
            problem, previous = classify(inv, token, previous, checked_by)
            if problem:
                errors.append(f"{rel}:{n}: `{token}`: {problem}")
    return errors


def classify(inv, token, previous, checked_by):
    """(problem or None, the new `previous`)."""
    if TREE_PATH.fullmatch(token):
        return None, previous            # checked as a path above
    if token.endswith(("…", "...")) and IDENT.match(token.rstrip(".…")):
        prefix = token.rstrip(".…")
        if any(t.startswith(prefix) for t in inv.test_names()):
            return None, previous
        return "no test starts with " + prefix, previous
    if token.startswith("_") and IDENT.match(token) and previous:
        parts = [i for i, c in enumerate(previous) if c == "_"]
        if any(inv.is_test(previous[:i] + token) for i in parts):
            return None, previous
        return f"no test {previous[:parts[-1]] + token if parts else token} (shorthand after `{previous}`)", previous
    if FILE_NAME.match(token):
        if inv.basename_exists(token):
            return None, previous
        return "no file of this name in the tree", previous
    if "/" in token and all(IDENT.match(p) for p in token.split("/")):
        if inv.boost_path(token):
            return None, token.split("/")[-1]
        if inv.path_exists(token):
            return None, previous
        return "no Boost.Test suite/case of this path", previous
    if IDENT.match(token):
        if inv.is_test(token):
            return None, token
        if token.startswith("test_"):
            if inv.basename_exists(token + ".cpp") or inv.basename_exists(token + ".py"):
                return None, previous
            return "no test function or file of this name", previous
        if token in inv.words or token in EXTERNAL:
            return None, previous       # a name of the code
        return "names no test and nothing in the tree", previous
    return None, previous


def main(argv):
    quiet = "--quiet" in argv
    args = [a for a in argv[1:] if a != "--quiet"]
    root = os.path.realpath(args[0] if args else os.path.join(os.path.dirname(os.path.realpath(__file__)), ".."))
    inv = Inventory(root)
    errors = []
    proofs = os.path.join(root, "proofs")
    for name in sorted(os.listdir(proofs)):
        if name.endswith(".md"):
            with open(os.path.join(proofs, name), encoding="utf-8") as fh:
                errors += check_file(inv, "proofs/" + name, fh.read())
    for e in errors:
        print(e)
    if not quiet or errors:
        print(f"{len(errors)} errors ({len(inv.boost_paths)} Boost.Test cases and suites, "
              f"{len(inv.python)} Python tests, {len(inv.ctest)} ctest names known)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
