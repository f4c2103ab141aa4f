#!/usr/bin/env bash
# Certificate cost on the bundled scenes: search time, writing time, size,
# and the exact checker's time, one run each (bench/README.md).
# Usage: bench/certificates.sh [TMCERT]   (default build/tmcert)
set -u
tmcert=${1:-build/tmcert}
dir=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '| scene | verdict | search s | write s | pieces | separations | size | check s |\n'
printf '|---|---|--:|--:|--:|--:|--:|--:|\n'
for scene in examples/octagons-near.json examples/octagons-collision.json examples/vertex-face-linear.json \
             tests/data/scenes/hover-grid-10.json tests/data/scenes/solid-entering.json \
             examples/gripper/gripper-safe.json examples/gripper/gripper-collision.json; do
  "$tmcert" verify "$dir/$scene" --json --threads 1 --certificate "$work/c.json" >"$work/out.json" 2>"$work/err"
  verdict=$(grep -o '"verdict": *"[a-z]*"' "$work/out.json" | head -1 | grep -o '[a-z]*"$' | tr -d '"')
  search=$(grep -o '"seconds": *[0-9.e-]*' "$work/out.json" | awk -F: '{s += $2} END {printf "%.4f", s}')
  read -r pieces seps write < <(sed -E 's/.*\(([0-9]+) pieces, ([0-9]+) separations, ([0-9.e-]+) s\).*/\1 \2 \3/' "$work/err")
  size=$(du -h "$work/c.json" | cut -f1)
  start=$(date +%s.%N)
  "$tmcert" check "$work/c.json" "$dir/$scene" >/dev/null 2>&1 || verdict="$verdict (CHECK FAILED)"
  check=$(echo "$(date +%s.%N) - $start" | bc)
  printf '| %s | %s | %s | %.4f | %s | %s | %s | %.3f |\n' "$scene" "$verdict" "$search" "$write" "$pieces" "$seps" "$size" "$check"
done
