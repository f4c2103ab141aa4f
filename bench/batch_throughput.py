#!/usr/bin/env python3
"""Throughput of `tmcert batch` (docs/scene-format.md "Batch runs").

Generates a planner-like roadmap: N short edges of a solid box robot (keyframe
edges: pure translations, nlerp turns (exact rational motions) and slerp turns
(enclosed motions)) through a warehouse of solid pillars and shelves, mostly
safe and some colliding; then measures, on this machine:

  - one process, one shard (--threads 1),
  - one process with --threads 2,
  - 2 and 4 shards run concurrently as separate processes, then batch-merge
    (the merged bytes are checked against the unsharded run),
  - the baseline: the first B edges as separate `tmcert verify` runs of one
    scene each (what a user without batch would do),

and prints a table of edges/s with ratios to the single shard.

  python3 bench/batch_throughput.py [--tmcert build/tmcert] [--edges 100000]
                                    [--baseline 300] [--seed 1] [--keep DIR]
"""

import argparse
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time


def box(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return [
        [[x0, y0, z0], [x0, y1, z0], [x1, y1, z0], [x1, y0, z0]],
        [[x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]],
        [[x0, y0, z0], [x1, y0, z0], [x1, y0, z1], [x0, y0, z1]],
        [[x0, y1, z0], [x0, y1, z1], [x1, y1, z1], [x1, y1, z0]],
        [[x0, y0, z0], [x0, y0, z1], [x0, y1, z1], [x0, y1, z0]],
        [[x1, y0, z0], [x1, y1, z0], [x1, y1, z1], [x1, y0, z1]],
    ]


def environment():
    """A 10 x 10 floor, a 4 x 3 grid of pillars (solid boxes), two shelves; the
    robot: a solid box 0.4 x 0.2 x 0.2 (exact decimals)."""
    bodies = [{"name": "floor", "polygons": [[[-5, -5, 0], [5, -5, 0], [5, 5, 0], [-5, 5, 0]]]}]
    for i in range(4):
        for j in range(3):
            x, y = -3 + 2 * i, -2 + 2 * j
            bodies.append({"name": "pillar-%d-%d" % (i, j), "solid": True,
                           "polygons": box((x, y, 0), (round(x + 0.5, 1), round(y + 0.5, 1), 3))})
    bodies.append({"name": "shelf-a", "polygons": [[[-4, -4, 2], [4, -4, 2], [4, -3, 2], [-4, -3, 2]]]})
    bodies.append({"name": "shelf-b", "polygons": [[[-4, 3, "1.5"], [4, 3, "1.5"], [4, 4, "1.5"], [-4, 4, "1.5"]]]})
    bodies.append({"name": "robot", "solid": True, "polygons": box((-0.2, -0.1, -0.1), (0.2, 0.1, 0.1))})
    return {"format": "tmcert-scene/1", "epsilon": "1/1000", "bodies": bodies}


def dec(x):
    return "%.2f" % x


def edges(n, rng):
    """n keyframe edges of the robot: 70% translations, 20% nlerp turns, 10%
    slerp turns, each about 0.3 long, at heights 0.5 to 1.8."""
    for k in range(n):
        x, y, z = rng.uniform(-4.5, 4.5), rng.uniform(-4.5, 4.5), rng.uniform(0.5, 1.8)
        dx, dy, dz = rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(-0.05, 0.05)
        a = {"translation": [dec(x), dec(y), dec(z)]}
        b = {"translation": [dec(x + dx), dec(y + dy), dec(z + dz)]}
        kind = rng.random()
        motion = {"type": "keyframes", "poses": [a, b]}
        if kind >= 0.7:
            # A turn about z by up to about 30 degrees: quaternions [1, 0, 0, s].
            a["rotation"] = {"quaternion": [1, 0, 0, dec(rng.uniform(-0.3, 0.3))]}
            b["rotation"] = {"quaternion": [1, 0, 0, dec(rng.uniform(-0.3, 0.3))]}
            motion["interpolation"] = "nlerp" if kind < 0.9 else "slerp"
        yield {"id": k, "body": "robot", "motion": motion}


def run(cmd, **kw):
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, **kw)


def timed_shards(tmcert, requests, env, work, shards, threads=1):
    """Runs `shards` processes at once; returns (seconds, output files)."""
    outs = [os.path.join(work, "s%d-%d.jsonl" % (shards, i)) for i in range(shards)]
    start = time.perf_counter()
    procs = [subprocess.Popen([tmcert, "batch", requests, "--scene", env, "--shard", "%d/%d" % (i, shards),
                               "--threads", str(threads), "-o", outs[i]],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE) for i in range(shards)]
    for p in procs:
        _, err = p.communicate()
        if p.returncode not in (0, 1, 2):
            sys.exit("tmcert batch failed (%d): %s" % (p.returncode, err.decode()))
    return time.perf_counter() - start, outs


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tmcert", default="build/tmcert")
    ap.add_argument("--edges", type=int, default=100000)
    ap.add_argument("--baseline", type=int, default=300, help="edges run as separate tmcert verify processes")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--keep", help="write the inputs and outputs here (default: a temporary directory)")
    args = ap.parse_args()
    tmcert = os.path.abspath(args.tmcert)
    work = args.keep or tempfile.mkdtemp(prefix="tmcert-batch-bench-")
    os.makedirs(work, exist_ok=True)
    print("seed %d, %d edges, baseline %d edges, %d cores, work %s" % (args.seed, args.edges, args.baseline,
                                                                       os.cpu_count(), work))
    rng = random.Random(args.seed)
    env = environment()
    env_file = os.path.join(work, "environment.json")
    with open(env_file, "w") as f:
        json.dump(env, f)
    requests = os.path.join(work, "requests.jsonl")
    reqs = list(edges(args.edges, rng))
    with open(requests, "w") as f:
        for r in reqs:
            f.write(json.dumps(r, separators=(",", ":")) + "\n")

    rows = []
    t1, outs = timed_shards(tmcert, requests, env_file, work, 1)
    whole = outs[0]
    with open(whole) as f:
        verdicts = [json.loads(line).get("verdict", "error") for line in f]
    rows.append(("batch, 1 shard", t1))
    t, outs = timed_shards(tmcert, requests, env_file, work, 1, threads=2)
    same = open(outs[0], "rb").read() == open(whole, "rb").read()
    rows.append(("batch, 1 shard, --threads 2", t))
    for shards in (2, 4):
        t, outs = timed_shards(tmcert, requests, env_file, work, shards)
        merged = os.path.join(work, "merged-%d.jsonl" % shards)
        start = time.perf_counter()
        m = run([tmcert, "batch-merge", *outs, "-o", merged])
        t_merge = time.perf_counter() - start
        if m.returncode != 0:
            sys.exit("batch-merge failed: " + m.stderr.decode())
        same = same and open(merged, "rb").read() == open(whole, "rb").read()
        rows.append(("batch, %d shards at once + merge (%.2f s)" % (shards, t_merge), t + t_merge))

    # Baseline: one verify process per edge, on the first edges.
    b = min(args.baseline, len(reqs))
    scenes = []
    for k in range(b):
        scene = json.loads(json.dumps(env))
        robot = next(x for x in scene["bodies"] if x["name"] == "robot")
        robot["motion"] = reqs[k]["motion"]
        path = os.path.join(work, "single-%d.json" % k)
        with open(path, "w") as f:
            json.dump(scene, f)
        scenes.append(path)
    start = time.perf_counter()
    agree = 0
    for k, path in enumerate(scenes):
        r = run([tmcert, "verify", "--json", "--threads", "1", path])
        if r.returncode not in (0, 1, 2):
            sys.exit("verify failed: " + r.stderr.decode())
        agree += json.loads(r.stdout)["verdict"] == verdicts[k]
    t_base = time.perf_counter() - start

    counts = {v: verdicts.count(v) for v in sorted(set(verdicts))}
    print("verdicts: " + ", ".join("%s %d" % kv for kv in counts.items()))
    print("sharded and threaded outputs byte-identical to the single run: %s" % ("yes" if same else "NO"))
    print("baseline verdicts equal to batch's: %d of %d" % (agree, b))
    print()
    print("| run | edges | seconds | edges/s | vs 1 shard |")
    print("|---|---:|---:|---:|---:|")
    for name, t in rows:
        print("| %s | %d | %.1f | %.0f | %.2f |" % (name, args.edges, t, args.edges / t, t1 / t))
    print("| verify, one process per edge | %d | %.1f | %.1f | %.3f |" % (b, t_base, b / t_base,
                                                                          (b / t_base) / (args.edges / t1)))
    if not args.keep:
        shutil.rmtree(work)
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
