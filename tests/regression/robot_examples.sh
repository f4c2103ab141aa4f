#!/usr/bin/env bash
# The published robots of Gepetto/example-robot-data (the Franka Panda, the
# UR5), unmodified, in the scenes of examples/robot/ listed in
# examples/robot/REAL ("<scene><TAB><verdict>"): each loads and its verdict
# is the known one (examples/robot/README.md derives each); the certificate
# `verify --certificate` writes with it is accepted by `tmcert check`.
#   robot_examples.sh TMCERT EXAMPLES_ROBOT_DIR DATA_DIR
# DATA_DIR is the fetched repository (scripts/fetch_example_robot_data.sh;
# the environment variable TMCERT_EXAMPLE_ROBOT_DATA overrides it). Without
# it the test is skipped (exit 77) with a message saying how to fetch it.
set -uo pipefail
tmcert=$(realpath "$1")
dir=$(cd "$2" && pwd)  # absolute: the scenes are linked from a temporary folder
data=${TMCERT_EXAMPLE_ROBOT_DATA:-$3}
if [ ! -f "$data/robots/panda_description/urdf/panda.urdf" ] || [ ! -f "$data/robots/ur_description/urdf/ur5_robot.urdf" ]; then
  echo "robot_examples: skipped: example-robot-data not found at $data" \
       "(fetch it with: bash scripts/fetch_example_robot_data.sh, or set TMCERT_EXAMPLE_ROBOT_DATA)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The scenes name the robots as example-robot-data/... beside them.
ln -s "$(cd "$data" && pwd)" "$work/example-robot-data"
for f in "$dir"/*.json "$dir"/*.off; do [ -e "$f" ] && ln -s "$f" "$work/$(basename "$f")"; done
failures=0
passes=0
while IFS=$'\t' read -r scene verdict || [ -n "$scene" ]; do
  case "$scene" in '' | '#'*) continue ;; esac
  case "$verdict" in safe) want=0 ;; collision) want=1 ;; *) want=2 ;; esac
  start=$(date +%s)
  rm -f "$work/cert.json"
  timeout 600 "$tmcert" verify "$work/$scene" --certificate "$work/cert.json" >"$work/out" 2>"$work/err"
  code=$?
  seconds=$(( $(date +%s) - start ))
  if [ "$code" -ne "$want" ]; then
    echo "FAIL $scene: exit $code, expected $want ($verdict), ${seconds} s"
    head -c 2000 "$work/out" "$work/err"
    failures=$((failures + 1))
    continue
  fi
  timeout 600 "$tmcert" check "$work/cert.json" "$work/$scene" >"$work/check" 2>&1
  checked=$?
  if [ "$checked" -ne 0 ]; then
    echo "FAIL $scene: its certificate: tmcert check exits $checked"
    head -c 2000 "$work/check"
    failures=$((failures + 1))
  else
    echo "ok   $scene: $verdict, certificate of $(wc -c <"$work/cert.json") bytes accepted ($(( $(date +%s) - start )) s)"
    passes=$((passes + 1))
  fi
done <"$dir/REAL"
echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
