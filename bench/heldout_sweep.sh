#!/usr/bin/env bash
# Runs the scenes of bench/heldout_scenes.py at default settings and
# tabulates them against their known truth (issue 23, "Decisive by default").
#
#   bench/heldout_sweep.sh TMCERT_BINARY [OUT_DIR] [SEED]
#
# HELDOUT_HARD=1: the second set of bench/heldout_scenes.py (--hard);
# HELDOUT_ROBOTS=DIR: the robot scenes of bench/heldout_robots.py on the
# example-robot-data checkout DIR (needs python3-mpmath).
#
# Prints one line per scene (file, truth, margin, verdict, seconds) and, per
# family, the counts: ok, false safe, false collision, undecided. A false
# verdict or an undecided scene whose margin exceeds 1e-6 of the scene's box
# diagonal is a failure of the issue; exit 1 if there is any.
set -u
tmcert=$1
out=${2:-$(mktemp -d)}
seed=${3:-23}
here=$(cd "$(dirname "$0")" && pwd)
if [ -n "${HELDOUT_ROBOTS:-}" ]; then
  python3 "$here/heldout_robots.py" "$HELDOUT_ROBOTS" "$out" >/dev/null || exit 2
else
  python3 "$here/heldout_scenes.py" "$out" --seed "$seed" ${HELDOUT_HARD:+--hard} >/dev/null || exit 2
fi
results="$out/RESULTS"
: >"$results"
while IFS=$'\t' read -r file truth margin family; do
  start=$(date +%s.%N)
  timeout 120 "$tmcert" verify --json "$out/$file" >"$out/${file%.json}.out" 2>"$out/${file%.json}.err"
  rc=$?
  end=$(date +%s.%N)
  case $rc in 0) v=safe ;; 1) v=collision ;; 2) v=undecided ;; *) v="error$rc" ;; esac
  printf '%s\t%s\t%s\t%s\t%s\t%.2f\n' "$file" "$truth" "$margin" "$family" "$v" \
    "$(echo "$end - $start" | bc)" | tee -a "$results"
done <"$out/MANIFEST"
python3 - "$results" <<'PY'
import sys, collections
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]) if l.strip()]
fam = collections.OrderedDict()
bad = 0
for f, truth, margin, family, v, sec in rows:
    c = fam.setdefault(family, collections.Counter())
    c["n"] += 1
    c["time"] += float(sec)
    c["max"] = max(c["max"], float(sec))
    if v == truth:
        c["ok"] += 1
    elif v == "safe":
        c["false_safe"] += 1; bad += 1
    elif v == "collision":
        c["false_collision"] += 1; bad += 1
    elif v == "undecided":
        c["undecided"] += 1
        if family != "tolerance-band" and float(margin) > 1e-6:
            bad += 1
    else:
        c["error"] += 1; bad += 1
print(f"\n{'family':24} {'n':>3} {'ok':>3} {'false safe':>10} {'false coll':>10} {'undecided':>9} {'error':>5} {'total s':>8} {'max s':>6}")
for k, c in fam.items():
    print(f"{k:24} {c['n']:3} {c['ok']:3} {c['false_safe']:10} {c['false_collision']:10} {c['undecided']:9} {c['error']:5} {c['time']:8.1f} {c['max']:6.1f}")
print(f"failures (false verdicts, undecided with margin > 1e-6 outside tolerance-band): {bad}")
sys.exit(1 if bad else 0)
PY
