#!/usr/bin/env bash
# Command-line regression for tmcert (SCENE_FORMAT.md, "Command line").
#
#   run_cli.sh TMCERT_BINARY TESTS_DATA_DIR EXAMPLES_DIR [PART]
#
# PART is `all` (the default: everything below), `main` (all but the
# certificate round trips of the bundled examples) or `example-certificates`
# (only those, the longest part: make test runs the two as separate tests,
# side by side).
#
# 1. Every malformed scene in DATA/bad/EXPECTED ("<file><TAB><substring>")
#    must give exit code 3, nothing on stdout and the substring on stderr;
#    so must a file that does not exist.
# 2. Every scene in DATA/scenes/EXPECTED, EXAMPLES/EXPECTED, EXAMPLES/gripper/EXPECTED and EXAMPLES/robot/EXPECTED
#    ("<file><TAB>safe|collision|undecided"), if those lists exist, must give
#    the exit code of its verdict (0, 1, 2) and that top-level "verdict" in
#    the --json output.
# Ends with the line "N passed, M failed"; exits non-zero if M > 0.
set -u

if [ $# -lt 3 ] || [ $# -gt 4 ]; then
  echo "usage: $0 TMCERT_BINARY TESTS_DATA_DIR EXAMPLES_DIR [all|main|example-certificates]" >&2
  exit 2
fi
tmcert=$1
data=$2
examples=$3
part=${4:-all}
case "$part" in
  all | main | example-certificates) ;;
  *) echo "$0: unknown part '$part' (all, main or example-certificates)" >&2; exit 2 ;;
esac

passed=0
failed=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A hung run must fail the test, not the whole suite.
run() {
  local limit=$1
  shift
  if command -v timeout >/dev/null 2>&1; then
    timeout "$limit" "$@" >"$work/out" 2>"$work/err"
  else
    "$@" >"$work/out" 2>"$work/err"
  fi
}

pass() { passed=$((passed + 1)); }
fail() {
  failed=$((failed + 1))
  echo "FAIL: $1" >&2
  if [ -s "$work/err" ]; then sed 's/^/  stderr: /' "$work/err" | head -n 5 >&2; fi
  if [ -s "$work/out" ]; then sed 's/^/  stdout: /' "$work/out" | head -n 5 >&2; fi
}

# Refused input or usage: `tmcert ARGS...` must exit 3 with nothing on
# stdout and a message on stderr containing SUBSTRING.
expect_refusal() {
  local substring=$1 code
  shift
  run 60 "$tmcert" "$@"
  code=$?
  if [ "$code" -ne 3 ]; then
    fail "tmcert $*: exit code $code, expected 3"
  elif [ -s "$work/out" ]; then
    fail "tmcert $*: output on stdout with exit code 3"
  elif ! grep -qF -- "$substring" "$work/err"; then
    fail "tmcert $*: stderr does not contain '$substring'"
  else
    pass
  fi
}

# Bad scene: `tmcert verify SCENE` refused, the message containing $2.
expect_bad() { expect_refusal "$2" verify "$1"; }

# The top-level "verdict" of the JSON document in $work/out.
top_verdict() {
  if command -v python3 >/dev/null 2>&1; then
    python3 -c 'import json, sys; print(json.load(sys.stdin).get("verdict", ""))' <"$work/out" 2>/dev/null
  else
    # Without python3: the first "verdict" key, which the format puts at the top.
    grep -o '"verdict": *"[a-z]*"' "$work/out" | head -n 1 | sed 's/.*"\([a-z]*\)"$/\1/'
  fi
}

# A scene with a known verdict: matching exit code and top-level verdict.
expect_verdict() {
  local scene=$1 verdict=$2 want code got
  case "$verdict" in
    safe) want=0 ;;
    collision) want=1 ;;
    undecided) want=2 ;;
    *) fail "$scene: unknown expected verdict '$verdict' in EXPECTED"; return ;;
  esac
  run 600 "$tmcert" verify --json "$scene"
  code=$?
  got=$(top_verdict)
  if [ "$code" -ne "$want" ]; then
    fail "$scene: exit code $code, expected $want ($verdict)"
  elif [ "$got" != "$verdict" ]; then
    fail "$scene: top-level verdict '$got', expected '$verdict'"
  else
    pass
  fi
}

# Calls "$2 DIR/<file> <field>" for each "<file><TAB><field>" line of $1
# (blank lines and lines starting with # are skipped).
for_each_line() {
  local list=$1 check=$2 dir file field
  dir=$(dirname "$list")
  while IFS=$'\t' read -r file field || [ -n "$file" ]; do
    file=${file%$'\r'}
    field=${field%$'\r'}
    case "$file" in '' | '#'*) continue ;; esac
    "$check" "$dir/$file" "$field"
  done <"$list"
}

# Round trips (section 4 below; defined here for PART example-certificates).
uncertifiable_lists=("$data/scenes/UNCERTIFIABLE" "$examples/robot/UNCERTIFIABLE")
expect_no_certificate() { expect_refusal "$2" verify "$1" --certificate "$work/refused.cert.json"; }
is_uncertifiable() {
  local scene=$1 list entry rest
  for list in "${uncertifiable_lists[@]}"; do
    [ -f "$list" ] || continue
    while IFS=$'\t' read -r entry rest || [ -n "$entry" ]; do
      case "$entry" in '' | '#'*) continue ;; esac
      if [ "$scene" = "$(dirname "$list")/$entry" ]; then return 0; fi
    done <"$list"
  done
  return 1
}

expect_round_trip() {
  local scene=$1 verdict=$2 code want
  if is_uncertifiable "$scene"; then return; fi
  case "$verdict" in safe) want=0 ;; collision) want=1 ;; *) want=2 ;; esac
  run 300 "$tmcert" verify "$scene" --certificate "$work/cert.json"
  code=$?
  # Certificates cover every scene not listed in UNCERTIFIABLE (keyframe,
  # piecewise, tolerance and clearance scenes included): never refused here.
  if [ "$code" -ne "$want" ]; then
    fail "tmcert verify $scene --certificate: exit code $code, expected $want ($(head -c 300 "$work/err"))"
    return
  fi
  run 300 "$tmcert" check "$work/cert.json" "$scene"
  code=$?
  if [ "$code" -ne 0 ]; then
    fail "tmcert check (certificate of $scene): exit code $code: $(head -c 300 "$work/err")"
  elif ! grep -qE ": ($verdict proven|$verdict: no contact before)" "$work/out"; then
    fail "tmcert check (certificate of $scene): '$verdict' not proven in the output"
  else
    pass
  fi
}

# The certificate round trips of the bundled examples (section 4), alone.
example_lists=("$examples/EXPECTED" "$examples/gripper/EXPECTED")
if [ "$part" = example-certificates ]; then
  for list in "${example_lists[@]}"; do
    if [ -f "$list" ]; then for_each_line "$list" expect_round_trip; fi
  done
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
  exit
fi

if [ -f "$data/bad/EXPECTED" ]; then
  for_each_line "$data/bad/EXPECTED" expect_bad
else
  : >"$work/err"
  : >"$work/out"
  fail "missing $data/bad/EXPECTED"
fi
expect_bad "$data/bad/does-not-exist.json" "does-not-exist.json"
if [ -f "$data/bad-cli/EXPECTED" ]; then
  for_each_line "$data/bad-cli/EXPECTED" expect_bad
fi

good="$examples/octagons-clear.json"
expect_refusal "--epsilon" verify "$good" --epsilon 0
expect_refusal "--epsilon" verify "$good" --epsilon nan
expect_refusal "--epsilon" verify "$good" --epsilon -1/3
expect_refusal "--kernel" verify "$good" --kernel quadruple
expect_refusal "--max-depth" verify "$good" --max-depth -2
expect_refusal "--max-depth" verify "$good" --max-depth 0
expect_refusal "--threads" verify "$good" --threads 0
expect_refusal "frobnicate" verify "$good" --frobnicate
expect_refusal "scene" verify
# A mistyped command is named, with the command meant.
expect_refusal "unknown command 'verfy' (did you mean 'verify'?)" verfy "$good"
expect_refusal "unknown command 'chek' (did you mean 'check'?)" chek
expect_refusal "unknown command 'frobnicate'; the commands are verify, check, batch, batch-merge" frobnicate

# Only regular files are read: a device or a FIFO (as the scene, a mesh or
# a certificate) is refused at once instead of being read forever or
# blocking on open.
expect_refusal "/dev/zero: not a regular file (it is a character device)" verify /dev/zero
expect_refusal "/dev/zero: not a regular file (it is a character device)" check /dev/zero "$good"
if command -v mkfifo >/dev/null 2>&1 && mkfifo "$work/pipe.json" "$work/pipe.off" 2>/dev/null; then
  expect_refusal "pipe.json: not a regular file (it is a FIFO)" verify "$work/pipe.json"
  printf '%s\n' '{"format": "tmcert-scene/1", "bodies": [{"name": "m", "mesh": "pipe.off"},' \
    '{"name": "p", "points": [[0,0,0]], "motion": {"type": "rational_bezier",' \
    '"control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,1],[0,1,0,0],[0,0,1,0]]]}}]}' >"$work/fifo-mesh.json"
  expect_refusal "pipe.off: not a regular file (it is a FIFO)" verify "$work/fifo-mesh.json"
fi

for list in "$data/scenes/EXPECTED" "$examples/EXPECTED" "$examples/gripper/EXPECTED" "$examples/robot/EXPECTED"; do
  if [ -f "$list" ]; then
    for_each_line "$list" expect_verdict
  fi
done

# Data from real pipelines (docs/scene-format.md): what the reader did is in
# the result ("notes", the summary's "note:" lines), and input that may not
# be meant is a warning on stderr (and "warnings" in the result).
expect_in() {  # expect_in STREAM SUBSTRING DESCRIPTION
  if grep -qF -- "$2" "$work/$1"; then pass; else fail "$3: $1 does not contain '$2'"; fi
}
pipeline="$data/scenes"
run 60 "$tmcert" verify --json "$pipeline/pipeline-quad-off-plane.json"
expect_in out '"notes": [' "verify --json pipeline-quad-off-plane.json"
expect_in out 'pipeline-quad-off-plane.obj: 1 face is not exactly planar (face 0): each is split into the triangles of a fan from its first vertex, 2 triangles in all; the body is these triangles' \
  "verify --json pipeline-quad-off-plane.json"
run 60 "$tmcert" verify "$pipeline/pipeline-sliver.json"
expect_in out '  note: ' "verify pipeline-sliver.json"
expect_in out 'pipeline-sliver.stl: 1 face has zero area (face 1): it is read as the segment (or point) it covers' \
  "verify pipeline-sliver.json"
run 60 "$tmcert" verify "$pipeline/pipeline-rpy-degrees.json"
expect_in err 'tmcert: warning: ' "verify pipeline-rpy-degrees.json"
expect_in err 'bodies[1].motion.poses[1].rotation.rpy[2]: the angle 90 is more than 2 pi: it is read as radians; if it is in degrees, write 1.5707963267948966 (its radians) instead' \
  "verify pipeline-rpy-degrees.json"
expect_in out '  warning: ' "verify pipeline-rpy-degrees.json"
run 60 "$tmcert" verify "$data/bad/kf_matrix_float_noise.json"
expect_in err 'the nearest rotation is the unit quaternion [w, x, y, z] = [0.96592582628906' "verify kf_matrix_float_noise.json"
expect_in err 'write "rotation": {"quaternion": [' "verify kf_matrix_float_noise.json"
# Approximations (docs/scene-format.md "Approximations"): an irrational
# contact time beyond the double range is the 17-digit decimal, a string
# also where a JSON number would be (never inf); a tiny one its nearest
# double (not a width-limited guess).
expect_json_text() {
  local scene=$1
  shift
  run 60 "$tmcert" verify "$scene" --json
  local text
  for text in "$@"; do
    if ! grep -qF -- "$text" "$work/out"; then
      fail "tmcert verify $scene --json: output does not contain '$text'"
      return
    fi
  done
  if grep -qiE '(^|[^a-z])-?inf(inity)?([^a-z]|$)' "$work/out"; then
    fail "tmcert verify $scene --json: 'inf' in the output"
    return
  fi
  pass
}
expect_json_text "$data/scenes/numbers-root-1e400.json" '"approx": "6.8232780382801933e+400"' \
  '"t_approx": "6.8232780382801933e+400"'
expect_json_text "$data/scenes/numbers-root-1e-20.json" '"approx": "6.823278038280193e-21"' \
  '"t_approx": 6.823278038280193e-21'
# Decisive by default (issue 23, docs/scene-format.md): without an epsilon
# a check refines its undecided parts and says so; `--epsilon auto` does the
# same; a given epsilon (here about the default, 0.1) keeps its fixed
# meaning; `tmcert batch` follows the same rule.
decisive="$data/scenes/decisive-slerp-pass-above.json"
expect_json_text "$decisive" '"verdict": "safe"' '"refined": true'
expect_verdict_with() {
  local want=$1 code=$2 text=$3
  shift 3
  run 120 "$tmcert" "$@"
  if [ "$?" -ne "$code" ]; then fail "tmcert $*: exit code, expected $code"
  elif ! grep -qF -- "$text" "$work/out"; then fail "tmcert $*: output does not contain '$text'"
  elif ! grep -qF -- "$want" "$work/out"; then fail "tmcert $*: output does not contain '$want'"
  else pass
  fi
}
expect_verdict_with '"verdict": "undecided"' 2 '"refined": false' verify "$decisive" --epsilon 0.1 --json
expect_verdict_with '"verdict": "safe"' 0 '"refined": true' verify "$decisive" --epsilon auto --json
{
  printf '%s\n' '{"format": "tmcert-scene/1", "bodies": [{"name": "plate", "polygons": [[[40, "101/100", -1], [60, "101/100", -1], [50, "-99/100", 1]], [[40, "-101/100", 1], [60, "-101/100", 1], [50, "99/100", -1]]]}, {"name": "probe", "points": [[0, 0, 0]]}]}'
  printf '%s\n' '{"id": "pass", "body": "probe", "checks": ["plate"], "motion": {"type": "keyframes", "interpolation": "slerp", "poses": [{"translation": [0, 0, 0]}, {"translation": [100, 0, 0], "rotation": {"quaternion": [1, 0, 0, 1]}}]}}'
} >"$work/decisive-batch.jsonl"
expect_verdict_with '"verdict":"safe"' 0 '"refined":true' batch "$work/decisive-batch.jsonl"
expect_verdict_with '"verdict":"undecided"' 2 '"refined":false' batch "$work/decisive-batch.jsonl" --epsilon 0.1

# 3. `tmcert check CERTIFICATE SCENE` (docs/certificate-format.md): exit 0
#    with the proven claims on stdout, 1 for a false claim or another scene,
#    3 for unreadable input; nothing on stdout unless 0, the substring on
#    stdout (exit 0) or stderr (otherwise).
expect_check() {
  local want=$1 substring=$2 code stream
  shift 2
  run 60 "$tmcert" check "$@"
  code=$?
  stream="$work/err"
  [ "$want" -eq 0 ] && stream="$work/out"
  if [ "$code" -ne "$want" ]; then
    fail "tmcert check $*: exit code $code, expected $want"
  elif [ "$want" -ne 0 ] && [ -s "$work/out" ]; then
    fail "tmcert check $*: output on stdout with exit code $code"
  elif ! grep -qF -- "$substring" "$stream"; then
    fail "tmcert check $*: output does not contain '$substring'"
  else
    pass
  fi
}
certs="$data/certificates"
if [ -d "$certs" ]; then
  expect_check 0 "probe x tri: safe proven (3 pieces, 4 separations)" "$certs/probe-safe.cert.json" "$certs/probe-safe.json"
  expect_check 0 "drop x tri: collision proven at t = 1/2" "$certs/drop-collision.cert.json" "$certs/drop.json"
  expect_check 0 "tri x box: safe proven" "$certs/solid-outside.cert.json" "$certs/solid-outside.json"
  expect_check 1 "pieces[0] [0, 1/4]: proof (groups 0, 0): separation fails at control point 0" \
    "$certs/probe-safe-tampered.cert.json" "$certs/probe-safe.json"
  expect_check 1 "the ray crosses shell 0 of \"box\" 1 time, an odd number" "$certs/solid-inside-safe.cert.json" "$certs/solid-inside.json"
  # A start point inside both shells of a two-shell solid: ray parity over
  # all polygons counted it outside (the inside is the union of the shells).
  expect_check 1 "an odd number: the vertex is inside \"solid\" at t0" \
    "$certs/solid-two-shells-false-safe.cert.json" "$certs/solid-two-shells.json"
  expect_check 1 "belongs to another scene" "$certs/drop-collision.cert.json" "$certs/probe-safe.json"
  expect_check 3 "garbage.cert.json: not JSON" "$certs/garbage.cert.json" "$certs/probe-safe.json"
  expect_check 3 "format: unknown format" "$certs/probe-safe.json" "$certs/probe-safe.json"
  expect_check 3 "does-not-exist.cert.json" "$certs/does-not-exist.cert.json" "$certs/probe-safe.json"
  expect_check 3 "does-not-exist.json" "$certs/probe-safe.cert.json" "$data/bad/does-not-exist.json"
  expect_check 3 "scene" "$certs/probe-safe.cert.json"
  # A certificate path that cannot be written is bad input (exit 3), never
  # a verdict printed without its proof.
  expect_refusal "--certificate: cannot write" verify "$examples/octagons-near.json" --certificate "$work/no-such-dir/near.cert"
  expect_refusal "--certificate: cannot write '$work': it is a directory" verify "$examples/octagons-near.json" --certificate "$work"
fi

# 4. Round trip: every scene with a known verdict, verified with
#    --certificate (same verdict and exit code as without), and the
#    certificate re-checked by `tmcert check` (exit 0, same verdict proven).
# Scenes listed in DATA/scenes/UNCERTIFIABLE or EXAMPLES/robot/UNCERTIFIABLE ("<file><TAB><substring>"):
# `verify --certificate` must be refused (exit 3, nothing on stdout, the
# substring on stderr); they take no part in the round trip.
for list in "${uncertifiable_lists[@]}"; do
  if [ -f "$list" ]; then for_each_line "$list" expect_no_certificate; fi
done
# Under the sanitizers (the sanitizer stage of make test sets
# TMCERT_SANITIZED) the round trips of the bundled examples (the octagons'
# and the gripper meshes' certificates: millions of separations, several
# minutes under AddressSanitizer) are left to the normal build's run of
# this script; the test scenes' round trips still run.  PART `main` leaves
# them to PART `example-certificates`.
round_trip_lists=("$data/scenes/EXPECTED" "$examples/robot/EXPECTED")
if [ -z "${TMCERT_SANITIZED:-}" ] && [ "$part" = all ]; then
  round_trip_lists+=("${example_lists[@]}")
fi
for list in "${round_trip_lists[@]}"; do
  if [ -f "$list" ]; then
    for_each_line "$list" expect_round_trip
  fi
done
# The same certificate with its first separation direction negated (which
# can never separate) is rejected.
run 60 "$tmcert" verify "$examples/octagons-near.json" --certificate "$work/cert.json"
# (tmcert-certificate/2 writes directions as JSON integers.)
sed -E '0,/"sep":\[/s/"sep":\[(-?[0-9]+),(-?[0-9]+),(-?[0-9]+)\]/"sep":[-\1,-\2,-\3]/' "$work/cert.json" |
  sed -E 's/([[,])--/\1/g' >"$work/tampered.json"
if cmp -s "$work/cert.json" "$work/tampered.json"; then fail "the tampering did not change the certificate"; fi
expect_check 1 "separation fails" "$work/tampered.json" "$examples/octagons-near.json"
# Exact "no contact" claims (docs/certificate-format.md): the hover at 1e-17
# (no plane separates at double precision or among the exact candidates)
# and the first contact at a root of a cubic (before_witness) are written
# and re-checked; the hand-built coplanar slide into the face is rejected.
run 60 "$tmcert" verify "$data/scenes/hover-1e-17.json" --certificate "$work/cert.json"
expect_check 0 "exact claim" "$work/cert.json" "$data/scenes/hover-1e-17.json"
run 60 "$tmcert" verify "$data/scenes/cubic-crossing-irrational.json" --certificate "$work/cert.json"
expect_check 0 "no contact before it proven (the first contact)" "$work/cert.json" "$data/scenes/cubic-crossing-irrational.json"
expect_check 1 "exact no-contact claim fails" "$certs/slide-exact.cert.json" "$certs/slide-into.json"

# 5. The result documents of planner scenes (SCENE_FORMAT.md "Tolerance and
#    clearance", docs/scene-format.md "Results of enclosed motions"): the
#    check's JSON must satisfy a Python condition on `c` (the first check).
expect_json() {
  local scene=$1 condition=$2
  command -v python3 >/dev/null 2>&1 || return
  run 300 "$tmcert" verify --json "$scene"
  if python3 -c "
import json, sys
from fractions import Fraction as F
c = json.load(open(sys.argv[1]))['checks'][0]
w = c.get('witness', {})
sys.exit(0 if ($condition) else 1)" "$work/out" 2>>"$work/err"; then
    pass
  else
    fail "$scene: result does not satisfy: $condition"
  fi
}
sc="$data/scenes"
if [ -f "$sc/planner-tolerance-collision.json" ]; then
  # A displacement of the pin within its tolerance (masses sum 4: norm 2|v| <= 1/10).
  expect_json "$sc/planner-tolerance-collision.json" \
    "w['displaced'] == 'pin' and 4 * sum(F(x) ** 2 for x in w['displacement']) <= F(1, 100) and 'point' in w"
  expect_json "$sc/planner-fixed-tolerance-collision.json" \
    "w['displaced'] == 'plate' and 4 * sum(F(x) ** 2 for x in w['displacement']) <= F(1, 100)"
  # Between the plate's slerp keyframes (an enclosed pose): a box per body,
  # every two points of the boxes within the clearance; the pin's box on its
  # segment (x = 4t - 2, y = 0).
  expect_json "$sc/planner-clearance-violated.json" \
    "c['clearance_violated'] is True and F(c['clearance']) == F(1, 2) and 'points' not in w and sum(max(abs(F(a[1]) - F(b[0])), abs(F(b[1]) - F(a[0]))) ** 2 for a, b in zip(*w['points_box'])) <= F(1, 4) and F(w['points_box'][1][0][0]) <= 4 * F(w['t']) - 2 <= F(w['points_box'][1][0][1]) and F(w['points_box'][1][1][0]) <= 0 <= F(w['points_box'][1][1][1])"
  # At an exact pose (a translation): two exact points within the clearance.
  expect_json "$sc/clearance-translation-030-violated.json" \
    "c['clearance_violated'] is True and 'points_box' not in w and sum((F(a) - F(b)) ** 2 for a, b in zip(*w['points'])) <= F(31, 100) ** 2"
  expect_json "$sc/planner-clearance-check-safe.json" "c['verdict'] == 'safe' and F(c['clearance']) == F(1, 10)"
  expect_json "$sc/planner-clearance-check-violated.json" "c['clearance_violated'] is True and F(c['clearance']) == F(1, 2)"
  # An enclosed witness: a rational box, on the wall's plane x = 1, at the bar's height z = 2t - 1, within the wall's y range.
  expect_json "$sc/planner-wall1-slerp.json" \
    "'point' not in w and F(w['point_box'][0][0]) <= 1 <= F(w['point_box'][0][1]) and F(w['point_box'][2][0]) <= 2 * F(w['t']) - 1 <= F(w['point_box'][2][1]) and F(47, 50) <= F(w['point_box'][1][0]) and F(w['point_box'][1][1]) <= F(53, 50)"
  # nlerp between exact quaternions is exact: decided by exact resolution, so
  # the witness is the exact first contact, at an algebraic time (the bar's
  # tip entering the wall) with a rational box on the wall's plane x = 1.
  expect_json "$sc/planner-wall2-nlerp.json" \
    "'root_of' in w['t'] and 'point' not in w and F(w['point_box'][0][0]) <= 1 <= F(w['point_box'][0][1]) and c['first_contact']['t'][0] == c['first_contact']['t'][1]"
fi

# 6. Resource limits (docs/scene-format.md "Limits", "--time-limit"): a
#    check past its time limit is undecided with reason "limit" (exit 2),
#    never safe; running out of memory is exit 4 with no verdict.
expect_refusal "--time-limit" verify "$good" --time-limit 0
expect_refusal "--time-limit" verify "$good" --time-limit -1
expect_refusal "--time-limit" verify "$good" --time-limit nan
expect_refusal "--time-limit" verify "$good" --time-limit inf
expect_refusal "--time-limit" verify "$good" --time-limit 1e10
expect_refusal "--time-limit" verify "$good" --time-limit 2s
expect_refusal "--memory-limit" verify "$good" --memory-limit 0
slow="$examples/octagons-near.json"
run 60 "$tmcert" verify "$slow" --json
base=$?
run 60 "$tmcert" verify "$slow" --json --time-limit 1e-9
code=$?
if [ "$base" -ne 0 ]; then
  fail "tmcert verify $slow: exit code $base without a time limit, expected 0 (safe)"
elif [ "$code" -ne 2 ]; then
  fail "tmcert verify $slow --time-limit 1e-9: exit code $code, expected 2 (undecided)"
elif ! grep -q '"reason": *"limit"' "$work/out" || ! grep -q '"verdict": *"undecided"' "$work/out"; then
  fail "tmcert verify $slow --time-limit 1e-9: no undecided interval with reason limit"
else
  pass
fi
# Address space limits do not work under AddressSanitizer (its shadow
# memory); the sanitizer stage of make test sets TMCERT_SANITIZED.
# The scene needs about 40 MB (peak resident size): a tiny scene may run
# within the heap the shared libraries' start-up left free (assimp's).
hungry="$examples/gripper/gripper-collision.json"
if [ -z "${TMCERT_SANITIZED:-}" ]; then
  run 60 "$tmcert" verify "$hungry" --memory-limit 16
  code=$?
  if [ "$code" -ne 4 ]; then
    fail "tmcert verify $hungry --memory-limit 16: exit code $code, expected 4"
  elif [ -s "$work/out" ]; then
    fail "tmcert verify $hungry --memory-limit 16: output on stdout with exit code 4"
  elif ! grep -q "out of memory" "$work/err"; then
    fail "tmcert verify $hungry --memory-limit 16: stderr does not say out of memory"
  else
    pass
  fi
fi

# 7. Output paths (docs/scene-format.md "Output paths"): an output that is
#    empty, an input (the scene, its mesh, under any spelling or link),
#    another output or the standard output's file is exit 3 before the run
#    and changes nothing; a FIFO with a reader gets the whole file; a write
#    that fails (/dev/full) is exit 4 naming the path, for every command
#    and for the standard output; nothing partial is left.
cp "$good" "$work/scene.json"
cp "$good" "$work/scene.orig"
ln -sf scene.json "$work/scene-link.json"
expect_refusal "--certificate: the file name is empty" verify "$good" --certificate ""
expect_refusal "--report: the file name is empty" verify "$good" --report ""
for out in "$work/scene.json" "$work/./scene.json" "$work/scene-link.json"; do
  expect_refusal "is the input file" verify "$work/scene.json" --certificate "$out"
  expect_refusal "is the input file" verify "$work/scene.json" --report "$out"
done
if cmp -s "$work/scene.json" "$work/scene.orig"; then pass; else fail "a refused output changed the scene"; fi
mkdir -p "$work/meshes"
cp "$data/meshes/cube.off" "$work/meshes/cube.off"
sed 's|"../meshes/cube.off"|"meshes/cube.off"|g' "$data/scenes/solid-inside.json" >"$work/mesh-scene.json"
expect_refusal "is the input file '$work/meshes/cube.off'" verify "$work/mesh-scene.json" --report "$work/meshes/cube.off"
if cmp -s "$work/meshes/cube.off" "$data/meshes/cube.off"; then pass; else fail "a refused output changed the mesh"; fi
rm -f "$work/both.out"
mkdir -p "$work/x"
expect_refusal "--report: '$work/both.out' is the same file as --certificate" \
  verify "$good" --certificate "$work/both.out" --report "$work/both.out"
expect_refusal "is the same file as --certificate" verify "$good" --certificate "$work/both.out" --report "$work/x/../both.out"
if [ ! -e "$work/both.out" ]; then pass; else fail "a refused output was created"; fi
timeout 60 "$tmcert" verify "$good" --certificate "$work/stdout.cert" >"$work/stdout.cert" 2>"$work/err"
code=$?
if [ "$code" -eq 3 ] && [ ! -s "$work/stdout.cert" ] && grep -q "the file the standard output goes to" "$work/err"; then pass
else fail "verify --certificate F > F: exit code $code, expected 3"; fi
# A FIFO without a reader is refused at once; with one, the reader gets
# the whole certificate (before: the check's open and close gave it an end
# of file, and the write then waited for a reader forever).
# Legs of the gripper's slerp path (examples/gripper) as scenes of their
# own: leg 7 verifies in about a second (time for a FIFO's reader to see
# an early end of file), leg 13 has a large certificate (98117 separations).
python3 - "$examples/gripper/gripper-path-slerp.json" "$work" <<'PY'
import json, os, sys
source, work = sys.argv[1], sys.argv[2]
scene = json.load(open(source))
base = os.path.dirname(os.path.abspath(source))
for body in scene["bodies"]:
    if "mesh" in body:
        body["mesh"] = os.path.join(base, body["mesh"])
poses = scene["bodies"][1]["motion"]["poses"]
for name, first in (("leg7.json", 7), ("leg.json", 13)):
    scene["bodies"][1]["motion"]["poses"] = poses[first:first + 2]
    json.dump(scene, open(os.path.join(work, name), "w"))
PY
# run_with_reader FIFO COPY ARGS...: tmcert ARGS with `cat FIFO > COPY` as
# the FIFO's reader; tried again while the reader has not opened it yet.
# The reader's exit status goes to reader_status (124: it waited in vain).
run_with_reader() {
  local fifo=$1 copy=$2 reader code tries=0
  shift 2
  timeout 120 cat "$fifo" >"$copy" &
  reader=$!
  while :; do
    run 60 "$tmcert" "$@"
    code=$?
    tries=$((tries + 1))
    if [ "$code" -ne 3 ] || ! grep -q "no process has this FIFO open" "$work/err" || [ "$tries" -ge 100 ]; then break; fi
    sleep 0.1
  done
  wait "$reader"
  reader_status=$?
  return "$code"
}
# (Under the sanitizers, the quick scene: the FIFO is still written, only
# the early end of file of before might go unseen.)
fifo_scene="$work/leg7.json"
if [ -n "${TMCERT_SANITIZED:-}" ]; then fifo_scene="$good"; fi
if mkfifo "$work/cert.fifo" "$work/report.fifo" 2>/dev/null; then
  expect_refusal "no process has this FIFO open for reading" verify "$good" --certificate "$work/cert.fifo"
  run_with_reader "$work/cert.fifo" "$work/from-fifo.cert" verify "$fifo_scene" --certificate "$work/cert.fifo"
  code=$?
  if [ "$code" -ne 0 ]; then
    fail "verify --certificate FIFO: exit code $code, expected 0"
  elif ! run 60 "$tmcert" check "$work/from-fifo.cert" "$fifo_scene"; then
    fail "verify --certificate FIFO: the reader did not get a whole certificate"
  else
    pass
  fi
  run_with_reader "$work/report.fifo" "$work/from-fifo.html" verify "$fifo_scene" --report "$work/report.fifo"
  code=$?
  if [ "$code" -eq 0 ] && grep -q "</html>" "$work/from-fifo.html"; then pass; else fail "verify --report FIFO: exit code $code"; fi
  # A run that fails before writing (a bad scene) leaves the reader an
  # end of file, not a wait for ever.
  run_with_reader "$work/cert.fifo" "$work/from-fifo.cert" verify "$data/bad/empty_file.json" --certificate "$work/cert.fifo"
  code=$?
  if [ "$code" -eq 3 ] && [ "$reader_status" -eq 0 ] && [ ! -s "$work/from-fifo.cert" ]; then pass
  else fail "verify BAD --certificate FIFO: exit code $code, reader $reader_status"; fi
fi
# Write failures: exit 4 naming the path, no verdict on stdout.
expect_write_failure() {
  local substring=$1 code
  shift
  run 60 "$tmcert" "$@"
  code=$?
  if [ "$code" -ne 4 ]; then
    fail "tmcert $*: exit code $code, expected 4"
  elif [ -s "$work/out" ]; then
    fail "tmcert $*: output on stdout with exit code 4"
  elif ! grep -qF -- "$substring" "$work/err"; then
    fail "tmcert $*: stderr does not contain '$substring'"
  else
    pass
  fi
}
# The standard output on /dev/full: exit 4 naming it.
expect_stdout_failure() {
  local code
  timeout 60 "$tmcert" "$@" >/dev/full 2>"$work/err"
  code=$?
  if [ "$code" -ne 4 ]; then
    fail "tmcert $* >/dev/full: exit code $code, expected 4"
  elif ! grep -q "cannot write the standard output" "$work/err"; then
    fail "tmcert $* >/dev/full: stderr does not name the standard output"
  else
    pass
  fi
}
if [ -w /dev/full ]; then
  expect_write_failure "--certificate: cannot write '/dev/full': No space left on device" verify "$good" --certificate /dev/full
  expect_write_failure "--report: cannot write '/dev/full'" verify "$good" --report /dev/full
  expect_stdout_failure verify "$good"
  expect_stdout_failure verify "$good" --json
  expect_stdout_failure verify "$examples/octagons-collision.json" --json
  expect_stdout_failure check "$data/certificates/probe-safe.cert.json" "$data/certificates/probe-safe.json"
  expect_stdout_failure --help
fi
# Out of memory while the certificate is built (the json documents of a
# large certificate, whose destruction allocates: std::terminate before)
# is exit 4 with "out of memory", no verdict, no file left, and an existing
# file unchanged.
if [ -z "${TMCERT_SANITIZED:-}" ]; then
  # (Limits in MB, well below what each needs: verify with the certificate
  # about 80, check about 55 since certificates share their proof nodes.)
  for limit in 40 55; do
    rm -f "$work/leg.cert"
    run 120 "$tmcert" verify "$work/leg.json" --certificate "$work/leg.cert" --memory-limit "$limit"
    code=$?
    if [ "$code" -ne 4 ]; then
      fail "verify leg.json --certificate --memory-limit $limit: exit code $code, expected 4"
    elif [ -s "$work/out" ] || ! grep -q "^tmcert: out of memory" "$work/err"; then
      fail "verify leg.json --certificate --memory-limit $limit: a verdict or no 'out of memory'"
    elif [ -e "$work/leg.cert" ]; then
      fail "verify leg.json --certificate --memory-limit $limit: a file was left behind"
    else
      pass
    fi
  done
  printf 'old\n' >"$work/leg.cert"
  run 120 "$tmcert" verify "$work/leg.json" --certificate "$work/leg.cert" --memory-limit 55
  code=$?
  if [ "$code" -eq 4 ] && [ "$(cat "$work/leg.cert")" = old ]; then pass
  else fail "verify leg.json --certificate EXISTING --memory-limit 55: exit code $code, or the file changed"; fi
  # The same certificate read by `tmcert check` under the limit (its json
  # document dropped while memory is exhausted: std::terminate before).
  run 120 "$tmcert" verify "$work/leg.json" --certificate "$work/leg-full.cert"
  code=$?
  if [ "$code" -ne 0 ]; then
    fail "verify leg.json --certificate: exit code $code, expected 0"
  else
    run 120 "$tmcert" check "$work/leg-full.cert" "$work/leg.json" --memory-limit 40
    code=$?
    if [ "$code" -eq 4 ] && [ ! -s "$work/out" ] && grep -q "^tmcert: out of memory" "$work/err"; then pass
    else fail "check leg-full.cert leg.json --memory-limit 40: exit code $code, expected 4 and out of memory"; fi
  fi
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
