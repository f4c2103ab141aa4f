#!/usr/bin/env bash
# `tmcert batch` and `tmcert batch-merge` (docs/scene-format.md "Batch runs").
#
#   batch.sh TMCERT_BINARY EXAMPLES_DIR
#
# 1. The example (examples/batch) gives its expected verdicts, the same
#    bytes with the environment as the first line as with --scene, and the
#    same bytes with --threads 2.
# 2. 4 local shards merged are byte-identical to the unsharded run.
# 3. Bad request lines become error lines naming the field; the run goes on.
#    With 2 and 3 threads, a mixed file longer than the threads' window
#    gives the bytes of one thread (also sharded and merged).
# 4. Bad options, a bad environment and bad merges exit 3 with nothing on stdout.
# 5. Every check of every example request has the verdict `tmcert verify`
#    gives the equivalent single scene.
# Ends with "N passed, M failed"; exits non-zero if M > 0.
set -u

if [ $# -ne 2 ]; then
  echo "usage: $0 TMCERT_BINARY EXAMPLES_DIR" >&2
  exit 2
fi
tmcert=$1
example=$2/batch
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() {
  failed=$((failed + 1))
  echo "FAIL: $*"
}
# expect_code CODE DESCRIPTION COMMAND...: stdout in $work/out, stderr in $work/err.
expect_code() {
  local want=$1 what=$2
  shift 2
  timeout 120 "$@" >"$work/out" 2>"$work/err"
  local rc=$?
  if [ "$rc" -eq "$want" ]; then pass; else fail "$what: exit $rc, expected $want ($(head -c 300 "$work/err"))"; fi
}
# expect_bad DESCRIPTION SUBSTRING COMMAND...: exit 3, nothing on stdout, SUBSTRING on stderr.
expect_bad() {
  local what=$1 needle=$2
  shift 2
  expect_code 3 "$what" "$@"
  if [ -s "$work/out" ]; then fail "$what: something on stdout with exit 3"; else pass; fi
  if grep -qF -- "$needle" "$work/err"; then pass; else fail "$what: stderr lacks '$needle': $(cat "$work/err")"; fi
}

# ---------------------------------------------------------------- 1. the example
expect_code 1 "example" "$tmcert" batch "$example/requests.jsonl" --scene "$example/environment.json"
cp "$work/out" "$work/example.jsonl"
got=$(python3 -c '
import json, sys
for line in open(sys.argv[1]):
    r = json.loads(line)
    print(r["index"], json.dumps(r["id"], separators=(",", ":")), r["verdict"], ",".join(c["verdict"] for c in r["checks"]))
' "$work/example.jsonl")
want='0 "e0" safe safe,safe,safe
1 "e1" collision safe,collision,safe
2 "e2" safe safe,safe,safe
3 {"edge":[7,8]} safe safe,safe,safe
4 4 safe safe'
if [ "$got" = "$want" ]; then pass; else fail "example verdicts:"$'\n'"$got"$'\n'"expected:"$'\n'"$want"; fi
if grep -q '"stats"' "$work/example.jsonl"; then fail "stats in results without --stats"; else pass; fi
expect_code 1 "--stats" "$tmcert" batch "$example/requests.jsonl" --scene "$example/environment.json" --stats
if [ "$(grep -o '"seconds":' "$work/out" | wc -l)" -eq 13 ]; then pass; else fail "--stats: not 13 checks with seconds"; fi
if grep -q 'tmcert batch: shard 0/1: 5 of 5 requests: 4 safe, 1 collision, 0 undecided, 0 bad' "$work/err"; then pass; else
  fail "summary line: $(cat "$work/err")"
fi

# The environment as the first line of the requests.
python3 -c 'import json, sys; print(json.dumps(json.load(open(sys.argv[1]))))' "$example/environment.json" >"$work/inline.jsonl"
cat "$example/requests.jsonl" >>"$work/inline.jsonl"
expect_code 1 "environment as the first line" "$tmcert" batch "$work/inline.jsonl"
if cmp -s "$work/out" "$work/example.jsonl"; then pass; else fail "environment as the first line: other bytes"; fi
expect_code 1 "--threads 2" "$tmcert" batch "$example/requests.jsonl" --scene "$example/environment.json" --threads 2
if cmp -s "$work/out" "$work/example.jsonl"; then pass; else fail "--threads 2: other bytes"; fi
expect_code 1 "-o" "$tmcert" batch "$example/requests.jsonl" --scene "$example/environment.json" -o "$work/o.jsonl"
if [ ! -s "$work/out" ] && cmp -s "$work/o.jsonl" "$work/example.jsonl"; then pass; else fail "-o: other bytes"; fi

# Inside a solid without touching its surface: a collision (the start
# containment), not cleared by the boxes; and the same cube far from
# everything: safe.
cat >"$work/inside.jsonl" <<'END'
{"id":"inside","body":"cube","checks":["pillar"],"motion":{"type":"keyframes","poses":[{"translation":["1.5","1.5",1]},{"translation":["1.5","1.5",2]}]}}
{"id":"far","body":"cube","motion":{"type":"keyframes","poses":[{"translation":[20,20,20]},{"translation":[21,20,20]}]}}
END
expect_code 1 "inside a solid" "$tmcert" batch "$work/inside.jsonl" --scene "$example/environment.json"
if grep -q '"id":"inside","verdict":"collision".*"features":\["cube [^"]*","pillar interior"' "$work/out" &&
  grep -q '"id":"far","verdict":"safe"' "$work/out"; then pass; else fail "inside a solid: $(cat "$work/out")"; fi

# ---------------------------------------------------------------- 2. shards
# 26 requests: the example's, repeated with other ids (blank lines between
# do not count), so that every shard holds several, of both verdicts.
python3 - "$example/requests.jsonl" "$work/many.jsonl" <<'EOF'
import json, sys
requests = [json.loads(line) for line in open(sys.argv[1])]
with open(sys.argv[2], "w") as out:
    for k in range(26):
        r = dict(requests[k % len(requests)])
        r["id"] = k * 10
        out.write(json.dumps(r) + "\n")
        if k % 7 == 3:
            out.write("\n")
EOF
expect_code 1 "26 requests" "$tmcert" batch "$work/many.jsonl" --scene "$example/environment.json" -o "$work/whole.jsonl"
for i in 0 1 2 3; do
  expect_code 1 "shard $i/4" "$tmcert" batch "$work/many.jsonl" --scene "$example/environment.json" --shard "$i/4" \
    -o "$work/shard-$i.jsonl"
  if [ "$(wc -l <"$work/shard-$i.jsonl")" -ge 6 ]; then pass; else fail "shard $i/4: fewer than 6 results"; fi
done
expect_code 0 "merge of 4 shards" "$tmcert" batch-merge "$work/shard-2.jsonl" "$work/shard-0.jsonl" \
  "$work/shard-3.jsonl" "$work/shard-1.jsonl" -o "$work/merged.jsonl"
if cmp -s "$work/merged.jsonl" "$work/whole.jsonl"; then pass; else fail "4 shards merged differ from the unsharded run"; fi
if [ "$(wc -l <"$work/whole.jsonl")" -eq 26 ]; then pass; else fail "26 requests: $(wc -l <"$work/whole.jsonl") results"; fi
expect_code 0 "merge to stdout" "$tmcert" batch-merge "$work/shard-0.jsonl" "$work/shard-1.jsonl" \
  "$work/shard-2.jsonl" "$work/shard-3.jsonl"
if cmp -s "$work/out" "$work/whole.jsonl"; then pass; else fail "merge to stdout differs"; fi

# ---------------------------------------------------------------- 3. bad request lines
good='{"id":"ok","body":"cube","motion":{"type":"keyframes","poses":[{"translation":[-1,-3,1]},{"translation":[3,-3,1]}]}}'
cat >"$work/bad.jsonl" <<EOF
$good
{"id":"json","body":"cube",
{"id":"nobody","body":"ghost","motion":{"type":"keyframes","poses":[{"translation":[0,0,1]},{"translation":[1,0,1]}]}}
{"id":"type","body":"cube","motion":{"type":"spline","poses":[]}}
{"id":"times","body":"cube","motion":{"type":"keyframes","times":[0,0],"poses":[{"translation":[0,0,1]},{"translation":[1,0,1]}]}}
{"id":"nomotion","body":"cube"}
{"id":"check","body":"cube","checks":["floor","ghost"],"motion":{"type":"keyframes","poses":[{"translation":[0,0,1]},{"translation":[1,0,1]}]}}
{"id":"self","body":"cube","checks":["cube"],"motion":{"type":"keyframes","poses":[{"translation":[0,0,1]},{"translation":[1,0,1]}]}}
{"id":"still","body":"cube","motion":{"type":"rational_bezier","control_points":[[[1,0,0,0],[0,1,0,0],[0,0,1,1]]]}}
{"id":"field","body":"cube","speed":3,"motion":{"type":"keyframes","poses":[{"translation":[0,0,1]},{"translation":[1,0,1]}]}}
{"id":"nan","body":"cube","motion":{"type":"keyframes","poses":[{"translation":[0,0,"nan"]},{"translation":[1,0,1]}]}}
{"id":"clearance","body":"cube","clearance":-1,"motion":{"type":"keyframes","poses":[{"translation":[0,0,1]},{"translation":[1,0,1]}]}}
[1,2,3]
$good
EOF
expect_code 2 "bad lines" "$tmcert" batch "$work/bad.jsonl" --scene "$example/environment.json"
got=$(python3 -c '
import json, sys
for line in open(sys.argv[1]):
    r = json.loads(line)
    print(r["index"], json.dumps(r["id"]), r.get("verdict", "-"), r.get("error", "-"))
' "$work/out")
while IFS='|' read -r index needle; do
  if printf '%s\n' "$got" | grep -q "^$index .*$needle"; then pass; else
    fail "bad line $index: no '$needle' in: $(printf '%s\n' "$got" | grep "^$index ")"
  fi
done <<'EOF'
0|"ok" safe -
1|null - line 2: invalid JSON
2|"nobody" - line 3: body: unknown body "ghost"
3|"type" - line 4: motion.type: unknown motion type "spline"
4|"times" - line 5: motion.times
5|"nomotion" - line 6: motion: missing required field
6|"check" - line 7: checks\[1\]: unknown body "ghost"
7|"self" - line 8: checks\[0\]: a body cannot be checked against itself
8|"still" - line 9: motion: the motion must move
9|"field" - line 10: speed: unknown field
10|"nan" - line 11: motion.poses\[0\].translation\[2\]
11|"clearance" - line 12: clearance: must not be negative
12|null - line 13: document: expected an object
13|"ok" safe -
EOF
if grep -q '14 of 14 requests: 2 safe, 0 collision, 0 undecided, 12 bad' "$work/err"; then pass; else fail "bad lines summary: $(cat "$work/err")"; fi

# ---------------------------------------------------------------- 3b. threads
# A mixed file longer than the threads' window of requests (64 per
# thread): the example's requests, the bad lines, the solid's inside,
# blank lines; the bytes are those of one thread with 2 and 3 threads, and
# with 2 threads per shard once merged.
python3 - "$example/requests.jsonl" "$work/bad.jsonl" "$work/inside.jsonl" "$work/mixed.jsonl" <<'EOF'
import sys
lines = [l.rstrip("\n") for f in sys.argv[1:4] for l in open(f) if l.strip()]
with open(sys.argv[4], "w") as out:
    for k in range(300):
        out.write(lines[(k * 5) % len(lines)] + "\n")
        if k % 11 == 5:
            out.write("\n")
EOF
expect_code 1 "mixed, 1 thread" "$tmcert" batch "$work/mixed.jsonl" --scene "$example/environment.json" \
  -o "$work/mixed-1.jsonl"
if [ "$(wc -l <"$work/mixed-1.jsonl")" -eq 300 ] && grep -q '"error"' "$work/mixed-1.jsonl" &&
  grep -q '"verdict":"collision"' "$work/mixed-1.jsonl"; then pass; else fail "mixed: not 300 results of all kinds"; fi
for n in 2 3; do
  expect_code 1 "mixed, $n threads" "$tmcert" batch "$work/mixed.jsonl" --scene "$example/environment.json" \
    --threads "$n" -o "$work/mixed-$n.jsonl"
  if cmp -s "$work/mixed-$n.jsonl" "$work/mixed-1.jsonl"; then pass; else fail "mixed, --threads $n: other bytes"; fi
done
for i in 0 1; do
  expect_code 1 "mixed, shard $i/2, 2 threads" "$tmcert" batch "$work/mixed.jsonl" --scene "$example/environment.json" \
    --threads 2 --shard "$i/2" -o "$work/mixed-shard-$i.jsonl"
done
expect_code 0 "mixed, merge" "$tmcert" batch-merge "$work/mixed-shard-1.jsonl" "$work/mixed-shard-0.jsonl"
if cmp -s "$work/out" "$work/mixed-1.jsonl"; then pass; else fail "mixed, 2 shards of 2 threads merged: other bytes"; fi

# ---------------------------------------------------------------- 4. bad options and environments
for shard in 4/4 1/0 x 1 -1/2 2/-3 "1/2/3" ""; do
  expect_bad "--shard '$shard'" "--shard" "$tmcert" batch "$example/requests.jsonl" --scene "$example/environment.json" \
    --shard "$shard"
done
expect_bad "unwritable -o" "-o: cannot write" "$tmcert" batch "$example/requests.jsonl" \
  --scene "$example/environment.json" -o "$work/no/such/dir/out.jsonl"
expect_bad "missing requests" "cannot open" "$tmcert" batch "$work/none.jsonl" --scene "$example/environment.json"
expect_bad "--epsilon 0" "--epsilon" "$tmcert" batch "$example/requests.jsonl" --scene "$example/environment.json" \
  --epsilon 0
expect_bad "--time-limit -1" "--time-limit" "$tmcert" batch "$example/requests.jsonl" \
  --scene "$example/environment.json" --time-limit -1
python3 - "$example/environment.json" "$work/moving.json" <<'EOF'
import json, sys
env = json.load(open(sys.argv[1]))
env["bodies"][1]["motion"] = {"type": "keyframes", "poses": [{"translation": [0, 0, 0]}, {"translation": [1, 0, 0]}]}
json.dump(env, open(sys.argv[2], "w"))
EOF
expect_bad "moving environment body" "bodies[1].motion: the bodies of a batch environment are fixed" \
  "$tmcert" batch "$example/requests.jsonl" --scene "$work/moving.json"
printf '{"format":"tmcert-scene/1","bodies":[]}\n' >"$work/empty-env.jsonl"
cat "$example/requests.jsonl" >>"$work/empty-env.jsonl"
expect_bad "bad first-line environment" "empty-env.jsonl line 1: bodies" "$tmcert" batch "$work/empty-env.jsonl"
printf '\n\n' >"$work/blank.jsonl"
expect_bad "no environment" "no environment" "$tmcert" batch "$work/blank.jsonl"
# Merges: a gap, a repeated index, a line that is not a result.
expect_bad "merge with a missing shard" "no file holds index 1" "$tmcert" batch-merge "$work/shard-0.jsonl" \
  "$work/shard-2.jsonl" "$work/shard-3.jsonl"
expect_bad "merge with a repeated shard" "is also in another file" "$tmcert" batch-merge "$work/shard-0.jsonl" \
  "$work/shard-0.jsonl" "$work/shard-1.jsonl" "$work/shard-2.jsonl" "$work/shard-3.jsonl"
printf '{"index":0}\nnot json\n' >"$work/junk.jsonl"
expect_bad "merge of a bad line" "junk.jsonl line 2: not a result line" "$tmcert" batch-merge "$work/junk.jsonl"
expect_bad "merge onto its input" "is the input file" "$tmcert" batch-merge "$work/shard-0.jsonl" \
  -o "$work/shard-0.jsonl"

# ---------------------------------------------------------------- 4b. output paths (docs/scene-format.md "Output paths")
# An output that is an input (the requests, under another spelling or a
# link, the environment scene, the merged files) or empty is exit 3 before
# anything is written: the inputs keep their bytes.
cp "$example/requests.jsonl" "$work/req.jsonl"
cp "$example/environment.json" "$work/env.json"
ln -sf req.jsonl "$work/req-link.jsonl"
{ cat "$work/env.json" | tr -d '\n'; echo; cat "$work/req.jsonl"; } >"$work/with-env.jsonl"
cp "$work/with-env.jsonl" "$work/with-env.copy"
for out in "$work/req.jsonl" "$work/./req.jsonl" "$work/req-link.jsonl"; do
  expect_bad "-o onto the requests ($out)" "is the input file" "$tmcert" batch "$work/req.jsonl" --scene "$work/env.json" -o "$out"
done
expect_bad "-o onto the environment" "is the input file" "$tmcert" batch "$work/req.jsonl" --scene "$work/env.json" -o "$work/env.json"
expect_bad "-o onto the requests read from standard input" "is the input file '<stdin>'" \
  "$tmcert" batch - --scene "$work/env.json" -o "$work/req.jsonl" <"$work/req.jsonl"
expect_bad "-o onto requests with their environment" "is the input file" "$tmcert" batch "$work/with-env.jsonl" -o "$work/with-env.jsonl"
if cmp -s "$example/requests.jsonl" "$work/req.jsonl" && cmp -s "$example/environment.json" "$work/env.json" &&
   cmp -s "$work/with-env.jsonl" "$work/with-env.copy"; then pass; else fail "an input was changed by a refused -o"; fi
expect_bad "-o empty" "-o: the file name is empty" "$tmcert" batch "$work/req.jsonl" --scene "$work/env.json" -o ""
expect_bad "--scene empty" "--scene: the file name is empty" "$tmcert" batch "$work/req.jsonl" --scene ""
expect_bad "batch-merge -o empty" "-o: the file name is empty" "$tmcert" batch-merge "$work/shard-0.jsonl" -o ""
timeout 120 "$tmcert" batch "$work/req.jsonl" --scene "$work/env.json" -o "$work/stdout.jsonl" >"$work/stdout.jsonl" 2>"$work/err"
rc=$?
if [ "$rc" -eq 3 ] && [ ! -s "$work/stdout.jsonl" ] && grep -q "the file the standard output goes to" "$work/err"; then pass
else fail "-o the file standard output goes to: exit $rc: $(cat "$work/err")"; fi
# A write that fails is exit 4 naming the file (or the standard output).
if [ -w /dev/full ]; then
  expect_code 4 "batch -o /dev/full" "$tmcert" batch "$work/req.jsonl" --scene "$work/env.json" -o /dev/full
  if grep -qF -- "-o: cannot write '/dev/full'" "$work/err"; then pass; else fail "batch -o /dev/full: $(cat "$work/err")"; fi
  timeout 120 "$tmcert" batch "$work/req.jsonl" --scene "$work/env.json" >/dev/full 2>"$work/err"
  rc=$?
  if [ "$rc" -eq 4 ] && grep -q "standard output" "$work/err"; then pass; else fail "batch >/dev/full: exit $rc: $(cat "$work/err")"; fi
  expect_code 4 "batch-merge -o /dev/full" "$tmcert" batch-merge "$work/shard-0.jsonl" "$work/shard-1.jsonl" \
    "$work/shard-2.jsonl" "$work/shard-3.jsonl" -o /dev/full
  timeout 120 "$tmcert" batch-merge "$work/shard-0.jsonl" "$work/shard-1.jsonl" "$work/shard-2.jsonl" \
    "$work/shard-3.jsonl" >/dev/full 2>"$work/err"
  rc=$?
  if [ "$rc" -eq 4 ] && grep -q "standard output" "$work/err"; then pass; else fail "batch-merge >/dev/full: exit $rc: $(cat "$work/err")"; fi
fi
# -o to a FIFO with a reader: the reader gets every result line (the
# check opens the FIFO once, and that descriptor is written).
if mkfifo "$work/results.fifo" 2>/dev/null; then
  timeout 120 cat "$work/results.fifo" >"$work/from-fifo.jsonl" &
  reader=$!
  for _ in $(seq 100); do  # again while the reader has not opened the FIFO yet
    timeout 120 "$tmcert" batch "$work/req.jsonl" --scene "$work/env.json" -o "$work/results.fifo" >"$work/out" 2>"$work/err"
    rc=$?
    if [ "$rc" -ne 3 ] || ! grep -q "no process has this FIFO open" "$work/err"; then break; fi
    sleep 0.1
  done
  wait "$reader"
  if [ "$rc" -eq 1 ] && cmp -s "$work/from-fifo.jsonl" "$work/example.jsonl"; then pass
  else fail "batch -o FIFO: exit $rc, or the reader did not get the results ($(head -c 300 "$work/err"))"; fi
fi

# Out of memory (exit 4, "out of memory") leaves no -o file behind, also
# when it strikes after the file was begun (the gripper's slerp legs of
# examples/gripper against its fixture; address space limits do not work
# under AddressSanitizer).
if [ -z "${TMCERT_SANITIZED:-}" ]; then
  python3 - "$example/../gripper" "$work" <<'PY'
import json, os, sys
gripper, work = os.path.abspath(sys.argv[1]), sys.argv[2]
scene = json.load(open(os.path.join(gripper, "gripper-path-slerp.json")))
env = {"format": "tmcert-scene/1", "epsilon": scene["epsilon"],
       "bodies": [{"name": "fixture", "mesh": os.path.join(gripper, "fixture.off")}]}
json.dump(env, open(os.path.join(work, "gripper-env.json"), "w"))
motion = scene["bodies"][1]["motion"]
with open(os.path.join(work, "gripper-legs.jsonl"), "w") as out:
    for k in range(8, 19):
        leg = dict(motion, poses=motion["poses"][k:k + 2])
        body = {"name": "gripper", "mesh": os.path.join(gripper, "gripper.off")}
        out.write(json.dumps({"id": k, "body": body, "motion": leg}) + "\n")
PY
  for limit in 44 48; do
    rm -f "$work/legs-out.jsonl"
    expect_code 4 "batch out of memory (--memory-limit $limit)" "$tmcert" batch "$work/gripper-legs.jsonl" \
      --scene "$work/gripper-env.json" -o "$work/legs-out.jsonl" --memory-limit "$limit"
    if grep -q "^tmcert: out of memory" "$work/err" && [ ! -e "$work/legs-out.jsonl" ]; then pass
    else fail "batch out of memory (--memory-limit $limit): no 'out of memory', or the -o file was left"; fi
  done
fi

# ---------------------------------------------------------------- 5. batch agrees with verify
# Each example request as a scene of its own: the environment, the moved
# body with the request's motion, one check per obstacle.
python3 - "$example/environment.json" "$example/requests.jsonl" "$work" <<'EOF'
import json, sys
env = json.load(open(sys.argv[1]))
for k, line in enumerate(open(sys.argv[2])):
    r = json.loads(line)
    scene = json.loads(json.dumps(env))
    moved = next(b for b in scene["bodies"] if b["name"] == r["body"])
    moved["motion"] = r["motion"]
    others = r.get("checks") or [b["name"] for b in scene["bodies"] if b["name"] != r["body"]]
    if "clearance" in r:
        scene["checks"] = [{"bodies": [r["body"], o], "clearance": r["clearance"]} for o in others]
    else:
        scene["checks"] = [[r["body"], o] for o in others]
    json.dump(scene, open("%s/single-%d.json" % (sys.argv[3], k), "w"))
EOF
k=0
while IFS= read -r line; do
  timeout 120 "$tmcert" verify --json "$work/single-$k.json" >"$work/verify.json" 2>"$work/err"
  single=$(python3 -c 'import json, sys; print(",".join(c["verdict"] for c in json.load(open(sys.argv[1]))["checks"]))' \
    "$work/verify.json")
  batch=$(printf '%s\n' "$line" | python3 -c 'import json, sys; print(",".join(c["verdict"] for c in json.loads(sys.stdin.read())["checks"]))')
  if [ -n "$single" ] && [ "$single" = "$batch" ]; then pass; else fail "request $k: batch $batch, verify $single"; fi
  k=$((k + 1))
done <"$work/example.jsonl"

# ---------------------------------------------------------------- 6. robot path segments
# The environment examples/robot/reach-panel.json (the arm, a panel); its
# path is not used: each request gives one.
robots=$(cd "$2/robot" && pwd)
cat >"$work/robot.jsonl" <<'END'
{"id":"sweep","robot":"arm","path":{"times":[0,1],"positions":[[0,0,0],[-1,0,0]]}}
{"id":"away","robot":"arm","path":{"times":[0,1,2],"positions":[[0,0,0],["1/2","-0.5",1],[1,-1,0]]}}
{"id":"limits","robot":"arm","path":{"times":[0,1],"positions":[[0,0,0],[0,9,0]]}}
{"id":"columns","robot":"arm","path":{"times":[0,1],"positions":[[0,0],[1,0]]}}
{"id":"ghost","robot":"hand","path":{"times":[0,1],"positions":[[0,0,0],[1,0,0]]}}
{"id":"link","body":"arm/forearm","motion":{"type":"keyframes","poses":[{"translation":[0,0,0]},{"translation":[1,0,0]}]}}
{"id":"both","robot":"arm","motion":{"type":"keyframes","poses":[{"translation":[0,0,0]},{"translation":[1,0,0]}]}}
END
expect_code 1 "robot requests" "$tmcert" batch "$work/robot.jsonl" --scene "$robots/reach-panel.json"
cp "$work/out" "$work/robot-out.jsonl"
got=$(python3 -c '
import json, sys
for line in open(sys.argv[1]):
    r = json.loads(line)
    print(r["index"], r["id"], r.get("verdict", "-"), r.get("error", "-"))
' "$work/robot-out.jsonl")
while IFS='|' read -r index needle; do
  if printf '%s\n' "$got" | grep -q "^$index .*$needle"; then pass; else
    fail "robot line $index: no '$needle' in: $(printf '%s\n' "$got" | grep "^$index ")"
  fi
done <<'END'
0|sweep collision -
1|away safe -
2|limits - line 3: path.positions\[1\]\[1\]: waypoint 1: joint "elbow"
3|columns - line 4: path.positions\[0\]
4|ghost - line 5: robot: unknown robot "hand"
5|link - line 6: body: "arm/forearm" is a link of a robot
6|both - line 7: motion: a robot moves along its "path"
END
# The first two against verify of the scene with their path.
python3 - "$robots" "$work/robot.jsonl" "$work" <<'END'
import json, sys
env = json.load(open(sys.argv[1] + "/reach-panel.json"))
for k, line in enumerate(open(sys.argv[2])):
    if k > 1:
        break
    scene = json.loads(json.dumps(env))
    scene["robots"][0]["path"] = json.loads(line)["path"]
    scene["robots"][0]["urdf"] = sys.argv[1] + "/" + scene["robots"][0]["urdf"]
    json.dump(scene, open("%s/robot-%d.json" % (sys.argv[3], k), "w"))
END
for k in 0 1; do
  timeout 120 "$tmcert" verify --json "$work/robot-$k.json" >"$work/verify.json" 2>"$work/err"
  single=$(python3 -c '
import json, sys
print(sorted((c["bodies"][0], c["bodies"][1], c["verdict"]) for c in json.load(open(sys.argv[1]))["checks"]))' \
    "$work/verify.json")
  batch=$(sed -n "$((k + 1))p" "$work/robot-out.jsonl" | python3 -c '
import json, sys
print(sorted((c["bodies"][0], c["bodies"][1], c["verdict"]) for c in json.loads(sys.stdin.read())["checks"]))')
  if [ "$single" = "$batch" ] && [ "$single" != "[]" ]; then pass; else fail "robot request $k: batch $batch, verify $single"; fi
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
