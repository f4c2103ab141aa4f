#!/usr/bin/env bash
# Installs the built tree into a scratch prefix, builds examples/cpp against
# it with find_package(tmcert) and runs it on a bundled example.
set -euo pipefail
build=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$src/examples/cpp" -B "$work/app" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/app" -j 2 >/dev/null
set +e
"$work/app/minimal" "$src/examples/octagons-collision.json"
code=$?
set -e
if [ "$code" -ne 1 ]; then
  echo "expected exit 1 (collision), got $code"
  echo "0 passed, 1 failed"
  exit 1
fi
echo "1 passed, 0 failed"
