#!/usr/bin/env bash
# run_example.sh PYTHON SCRIPT EXPECTED: runs SCRIPT and compares its
# standard output with the file EXPECTED line by line (a failure shows the diff).
set -euo pipefail
if [ $# -ne 3 ]; then
  echo "usage: $0 PYTHON SCRIPT EXPECTED" >&2
  exit 2
fi
out=$(mktemp)
trap 'rm -f "$out"' EXIT
"$1" "$2" >"$out"
diff -u "$3" "$out"
echo "$(wc -l <"$3") lines as expected"
