#!/usr/bin/env bash
# Installs the built tree into a scratch prefix, builds examples/cpp against
# it with find_package(tmcert), once with the shared library and once with
# the static one, and runs the examples: the scene built in code (drop_box)
# and a bundled scene file (minimal).  Also checks that the installed
# headers are the public ones only; with a third argument "ompl" (the tree
# has its OMPL adapter), builds examples/ompl against the install with
# find_package(tmcert COMPONENTS ompl); and configures tmcert as a
# subproject without its tests' dependencies.
#
#   find_package.sh BUILD_DIR SOURCE_DIR [ompl]
set -euo pipefail
build=$1
src=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
passed=0
failed=0
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }

# Only include/tmcert/ is installed: no internal header, no CGAL in them.
headers=$(cd "$work/prefix/include" && find . -type f | sort | tr '\n' ' ')
if [ "$(cd "$work/prefix/include" && find . -type f ! -path './tmcert/*' | wc -l)" -ne 0 ] ||
   grep -lE '#include [<"](CGAL|gmp|Eigen|nlohmann|src/|kernels/)' "$work/prefix/include/tmcert/"*.h >/dev/null; then
  fail "installed headers are not only the public ones: $headers"
else
  passed=$((passed + 1))
fi

expected_drop="verdict: collision
box meets table at t = 0.666666666666667 (exactly 2/3)"
for target in tmcert::tmcert tmcert::tmcert_static; do
  app="$work/app-${target#tmcert::}"
  cmake -S "$src/examples/cpp" -B "$app" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_PREFIX_PATH="$work/prefix" -DTMCERT_TARGET="$target" >/dev/null
  cmake --build "$app" -j 2 >/dev/null
  set +e
  out=$("$app/drop_box")
  code=$?
  "$app/minimal" "$src/examples/octagons-collision.json" >/dev/null
  code_minimal=$?
  set -e
  if [ "$code" -ne 1 ] || [ "$(printf '%s\n' "$out" | head -2)" != "$expected_drop" ] ||
     ! printf '%s\n' "$out" | grep -qE '^witness point: \(.*, .*, 0\)$'; then
    fail "$target: drop_box exited $code with output:"
    printf '%s\n' "$out"
  else
    passed=$((passed + 1))
  fi
  if [ "$code_minimal" -ne 1 ]; then
    fail "$target: minimal on octagons-collision.json: expected exit 1 (collision), got $code_minimal"
  else
    passed=$((passed + 1))
  fi
done
# The shared example needs the shared library; the static one does not.
# (ldd's output is read whole first: `ldd | grep -q` under pipefail fails
# whenever grep stops reading early and ldd dies of SIGPIPE.)
shared_libs=$(ldd "$work/app-tmcert/drop_box")
static_libs=$(ldd "$work/app-tmcert_static/drop_box")
if grep -q 'libtmcert\.so' <<<"$shared_libs" && ! grep -q 'libtmcert\.so' <<<"$static_libs"; then
  passed=$((passed + 1))
else
  fail "drop_box is not linked as expected (shared: libtmcert.so; static: none)"
fi
# The OMPL adapter as a user gets it: find_package(tmcert COMPONENTS ompl)
# and tmcert::ompl, for examples/ompl built on its own against the prefix;
# the SE(3) example plans and certifies its path (exit 0).
if [ "${3:-}" = ompl ] && [ -z "$(find "$work/prefix" -name tmcertOmplTargets.cmake)" ]; then
  fail "tmcert was built with its OMPL adapter, but the install has no tmcertOmplTargets.cmake"
elif [ -n "$(find "$work/prefix" -name tmcertOmplTargets.cmake)" ]; then
  ompl_app="$work/app-ompl"
  if cmake -S "$src/examples/ompl" -B "$ompl_app" -DCMAKE_BUILD_TYPE=Release \
       -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/ompl.log" 2>&1 &&
     cmake --build "$ompl_app" -j 2 --target ompl_rigid_passage >>"$work/ompl.log" 2>&1 &&
     "$ompl_app/ompl_rigid_passage" >>"$work/ompl.log" 2>&1; then
    passed=$((passed + 1))
  else
    fail "examples/ompl against the installed package (find_package(tmcert COMPONENTS ompl)):"
    tail -30 "$work/ompl.log"
  fi
  # An unknown component is refused by name.
  mkdir -p "$work/bad-component"
  printf '%s\n' 'cmake_minimum_required(VERSION 3.20)' 'project(x LANGUAGES CXX)' \
    'find_package(tmcert REQUIRED COMPONENTS teleport)' >"$work/bad-component/CMakeLists.txt"
  if cmake -S "$work/bad-component" -B "$work/bad-component/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
       >"$work/bad.log" 2>&1 || ! grep -q "unknown component teleport" "$work/bad.log"; then
    fail "find_package(tmcert COMPONENTS teleport) was not refused by name:"
    tail -10 "$work/bad.log"
  else
    passed=$((passed + 1))
  fi
else
  echo "skipped: the OMPL adapter is not installed (built with TMCERT_WITH_OMPL=OFF)"
fi

# Added with add_subdirectory by a project that has tests of its own (its
# BUILD_TESTING is ON): tmcert's tests are not built, so neither rapidcheck
# nor Boost.Test is looked for, no benchmark is built, and tmcert::ompl is
# there to link.
mkdir -p "$work/sub"
printf '%s\n' 'cmake_minimum_required(VERSION 3.20)' 'project(user LANGUAGES CXX)' 'include(CTest)' \
  "add_subdirectory(\"$src\" tmcert)" \
  'if(NOT TARGET tmcert::ompl OR NOT TARGET tmcert::tmcert)' '  message(FATAL_ERROR "no tmcert::ompl")' 'endif()' \
  >"$work/sub/CMakeLists.txt"
if cmake -S "$work/sub" -B "$work/sub/build" -DCMAKE_BUILD_TYPE=Release \
     -DCMAKE_DISABLE_FIND_PACKAGE_rapidcheck=ON -DTMCERT_WITH_PYTHON=OFF >"$work/sub.log" 2>&1 &&
   ! grep -q "unit_test_framework" "$work/sub/build/CMakeCache.txt" &&
   ! cmake --build "$work/sub/build" --target help | grep -qE 'tmcert_(unit|ccd_bench|paper_grid|speed_error|ompl_bench)'; then
  passed=$((passed + 1))
else
  fail "added with add_subdirectory, tmcert still needs the tests' dependencies or builds tests or benchmarks:"
  tail -20 "$work/sub.log"
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
