#!/usr/bin/env bash
# The continuous-collision query files of the public benchmark format, end
# to end: scripts/ccd_csv_to_scene.py, tmcert verify --json,
# scripts/ccd_compare.py (README, "Standard CCD query files").
#
#   ccd_csv.sh TMCERT_BINARY SOURCE_DIR
#
# 1. tests/data/ccd-csv/generate.py rewrites exactly the committed files.
# 2. The vertex-face file (truth in its seventh column) and the edge-edge
#    file (truth in mma_bool.json) convert, verify with the filtered and the
#    exact kernel, and score with --strict: no false safe, no false
#    collision, nothing undecided (every contact is at a dyadic time, every
#    miss has a margin the tests resolve), and every colliding query ends
#    "collision".
# 3. The scoring can fail: one flipped ground truth gives exit 1.
# 4. Malformed input is refused with exit 3 and a message naming the file.
# Ends with "N passed, M failed"; exits non-zero if M > 0.
set -u
if [ $# -ne 2 ]; then
  echo "usage: $0 TMCERT_BINARY SOURCE_DIR" >&2
  exit 2
fi
tmcert=$1
src=$2
data=$src/tests/data/ccd-csv
convert=$src/scripts/ccd_csv_to_scene.py
compare=$src/scripts/ccd_compare.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

# 1. The generator and the committed data agree.
mkdir -p "$work/gen"
cp "$data/generate.py" "$work/gen/"
python3 "$work/gen/generate.py"
for f in vertex-face/queries.csv edge-edge/queries.csv edge-edge/mma_bool.json; do
  if cmp -s "$work/gen/$f" "$data/$f"; then ok; else bad "generate.py does not rewrite $f as committed"; fi
done

# 2. End to end.
python3 "$convert" "$data/vertex-face/queries.csv" -o "$work/vf.json" --truth-out "$work/vf-truth.json" 2>/dev/null
python3 "$convert" "$data/edge-edge/queries.csv" --truth "$data/edge-edge/mma_bool.json" \
  -o "$work/ee.json" --truth-out "$work/ee-truth.json" 2>/dev/null
for kind in vf ee; do
  for kernel in filtered exact; do
    "$tmcert" verify "$work/$kind.json" --kernel "$kernel" --json > "$work/$kind-$kernel.json"
    rc=$?
    if [ $rc -ne 1 ]; then bad "$kind $kernel: exit $rc, expected 1 (collision)"; continue; fi
    if out=$(python3 "$compare" --strict "$work/$kind-$kernel.json" "$work/$kind-truth.json"); then
      # every colliding query proven: the "colliding" and "collision proven" columns agree
      if echo "$out" | awk -F'|' '$2 ~ /all/ { gsub(/ /, ""); exit !($4 == $9 && $4 > 0) }'; then ok
      else bad "$kind $kernel: not every colliding query was proven"; echo "$out"; fi
    else
      bad "$kind $kernel: ccd_compare --strict failed"; echo "$out"
    fi
  done
done

# 3. A flipped truth is caught.
python3 - "$work/vf-truth.json" "$work/vf-flipped.json" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
t[0]["truth"] = not t[0]["truth"]
json.dump(t, open(sys.argv[2], "w"))
PY
python3 "$compare" "$work/vf-filtered.json" "$work/vf-flipped.json" > /dev/null
rc=$?
if [ $rc -eq 1 ]; then ok; else bad "a flipped ground truth gave exit $rc, expected 1"; fi

# 4. Malformed input.
head -n 7 "$data/vertex-face/queries.csv" > "$work/seven.csv"
python3 "$convert" --kind vf "$work/seven.csv" -o "$work/x.json" 2> "$work/err"
rc=$?
if [ $rc -eq 3 ] && grep -q "seven.csv: 7 data lines" "$work/err"; then ok; else bad "7 lines: exit $rc, $(cat "$work/err")"; fi
sed '3s/^[^,]*,/x,/' "$data/vertex-face/queries.csv" > "$work/nan.csv"
python3 "$convert" --kind vf "$work/nan.csv" -o "$work/x.json" 2> "$work/err"
rc=$?
if [ $rc -eq 3 ] && grep -q "nan.csv:3:" "$work/err"; then ok; else bad "not a number: exit $rc, $(cat "$work/err")"; fi
python3 "$convert" "$work/nan.csv" -o "$work/x.json" 2> "$work/err"
rc=$?
if [ $rc -eq 3 ] && grep -q "give --kind" "$work/err"; then ok; else bad "unknown kind: exit $rc, $(cat "$work/err")"; fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
