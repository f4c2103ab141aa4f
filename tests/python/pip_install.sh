#!/usr/bin/env bash
# `pip install .` as a new user runs it (README.md, "Python"): a fresh
# virtual environment of PYTHON, pip offline (--no-index: nothing is
# downloaded; the build backend is in the tree), then the README's Python
# example from the repository root, which must import the installed
# package (not the source tree) and print what the README says.
#
#   pip_install.sh PYTHON SOURCE_DIR [BUILD_DIR]
#
# With BUILD_DIR (a build of this tree configured for PYTHON: ctest passes
# its own), the backend builds the extension there (already built: nothing
# is compiled again).  Without it, or with TMCERT_TEST_PIP_FULL=1, the
# backend builds from scratch in its own folder, as for a user (minutes).
set -euo pipefail
if [ $# -lt 2 ] || [ $# -gt 3 ]; then
  echo "usage: $0 PYTHON SOURCE_DIR [BUILD_DIR]" >&2
  exit 2
fi
python=$1
src=$(realpath "$2")
settings=()
if [ $# -eq 3 ] && [ -z "${TMCERT_TEST_PIP_FULL:-}" ]; then settings=(--config-settings "build-dir=$(realpath "$3")"); fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }

# --system-site-packages as in the README: Debian's NumPy when there is one
# (optional; the package works without it).
"$python" -m venv --system-site-packages "$work/venv"
venv_python="$work/venv/bin/python"
if ! "$venv_python" -m pip install --no-index --no-cache-dir "${settings[@]}" "$src" >"$work/pip.log" 2>&1; then
  fail "pip install $src:"
  tail -30 "$work/pip.log"
  echo "$passed passed, $failed failed"
  exit 1
fi
passed=$((passed + 1))

# Installed into the environment, stubs and the typed marker included.
if "$venv_python" - "$work/venv" <<'PY'
import os, sys, tmcert
package = os.path.dirname(tmcert.__file__)
assert package.startswith(os.path.realpath(sys.argv[1])) or package.startswith(sys.argv[1]), package
for name in ("__init__.py", "py.typed", "_tmcert.pyi"):
    assert os.path.isfile(os.path.join(package, name)), name
PY
then passed=$((passed + 1)); else fail "the package is not installed into the environment as expected"; fi

# The README's Python example: the first ```python block of its "## Python"
# section, run from the repository root; each "# ..." comment at the end of
# a print line is what that line prints.
"$venv_python" - "$src/README.md" >"$work/example.py" <<'PY'
import sys
text = open(sys.argv[1], encoding="utf-8").read()
section = text.split("\n## Python\n", 1)[1]
block = section.split("```python\n", 1)[1].split("```", 1)[0]
print(block)
PY
expected=$(grep -E '^print\(' "$work/example.py" | sed -n 's/.*  # \(.*\)$/\1/p' | head -1)
# The whole output goes to a file first: `| head -1` would close the pipe
# while the example still prints (BrokenPipeError, and pipefail).
if (cd "$src" && "$venv_python" "$work/example.py") >"$work/example.out"; then
  got=$(head -1 "$work/example.out")
else
  got="(the example exited with an error)"
fi
if [ -n "$expected" ] && [ "$got" = "$expected" ]; then
  passed=$((passed + 1))
else
  fail "README's Python example printed '$got', the README says '$expected'"
fi
# Uninstalls cleanly (the wheel's RECORD is right).
if "$venv_python" -m pip uninstall -y tmcert >/dev/null 2>&1 && ! "$venv_python" -c "import tmcert" 2>/dev/null; then
  passed=$((passed + 1))
else
  fail "pip uninstall tmcert"
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
