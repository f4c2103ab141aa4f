#!/usr/bin/env python3
"""Thread scaling of `tmcert verify` and `tmcert batch`, and `batch-merge` time.

  - verify: the gripper's 20-keyframe slerp path (examples/gripper/) with
    each segment cut into --split pieces by keyframes at exact nlerp
    points of the quaternions as written (translation and quaternion
    linear in the cut parameter: exact short decimals), so 19 * split + 1
    keyframes (96 by default); one check, so `--threads N` goes to the
    parts of the path and the pieces of each part.
  - batch: the warehouse roadmap of bench/batch_throughput.py (--edges
    requests, seeded), `tmcert batch --threads N`.
  - batch-merge: the batch run's output cut into --shards files by index
    modulo the shard count (what `--shard i/n` writes), merged again.

For every thread count it prints wall-clock and CPU seconds (user + system
of the child) and the speed-up in wall-clock time over one thread, and it
checks that the outputs are the same for every thread count (verify: the
JSON result without its `seconds`; batch and batch-merge: the bytes).

  python3 bench/thread_scaling.py [--tmcert build/tmcert] [--threads 1,2]
      [--split 5] [--edges 40000] [--shards 16] [--repeat 3] [--keep DIR]
"""

import argparse
import json
import os
import random
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import batch_throughput  # noqa: E402  (the roadmap generator)


def dec(x):
    """An exact decimal string of a Fraction whose denominator divides a power of 10."""
    x = Fraction(x)
    for digits in range(0, 30):
        scaled = x * 10 ** digits
        if scaled.denominator == 1:
            s = str(abs(scaled.numerator)).rjust(digits + 1, "0")
            out = s[: len(s) - digits] + ("." + s[len(s) - digits:] if digits else "")
            return ("-" if x < 0 else "") + out
    raise ValueError(x)


def split_path(scene, split):
    """The scene with every keyframe segment of its moving body cut into `split` pieces."""
    for body in scene["bodies"]:
        motion = body.get("motion")
        if not motion or motion.get("type") != "keyframes":
            continue
        poses = motion["poses"]
        out = []
        for a, b in zip(poses, poses[1:]):
            ta = [Fraction(str(v)) for v in a["translation"]]
            tb = [Fraction(str(v)) for v in b["translation"]]
            qa = [Fraction(str(v)) for v in a["rotation"]["quaternion"]]
            qb = [Fraction(str(v)) for v in b["rotation"]["quaternion"]]
            if sum(x * y for x, y in zip(qa, qb)) < 0:
                qb = [-v for v in qb]
            for j in range(split):
                s = Fraction(j, split)
                out.append({"translation": [dec((1 - s) * x + s * y) for x, y in zip(ta, tb)],
                            "rotation": {"quaternion": [dec((1 - s) * x + s * y) for x, y in zip(qa, qb)]}})
        out.append(poses[-1])
        motion["poses"] = out
        motion.pop("times", None)
    return scene


def timed(cmd, stdout=None):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run(cmd, stdout=stdout, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if proc.returncode not in (0, 1, 2):
        sys.exit("failed (%d): %s\n%s" % (proc.returncode, " ".join(cmd), proc.stderr))
    return wall, cpu


def best(runs):
    """The run with the least wall-clock time (the one least disturbed)."""
    return min(runs, key=lambda r: r[0])


def strip_seconds(x):
    if isinstance(x, dict):
        return {k: strip_seconds(v) for k, v in x.items() if k != "seconds"}
    if isinstance(x, list):
        return [strip_seconds(v) for v in x]
    return x


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tmcert", default="build/tmcert")
    ap.add_argument("--threads", default="1,2", help="thread counts, comma-separated")
    ap.add_argument("--split", type=int, default=5, help="pieces per segment of the gripper path")
    ap.add_argument("--edges", type=int, default=40000, help="batch requests (also the lines merged)")
    ap.add_argument("--shards", type=int, default=16, help="files batch-merge merges")
    ap.add_argument("--repeat", type=int, default=3, help="runs per measurement (the fastest is shown)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--keep", help="write the inputs and outputs here (default: a temporary directory)")
    args = ap.parse_args()
    threads = [int(t) for t in args.threads.split(",")]
    work = args.keep or tempfile.mkdtemp(prefix="tmcert-threads-bench-")
    os.makedirs(work, exist_ok=True)
    root = os.path.dirname(HERE)
    print("cores: %d, load average at start: %.1f %.1f %.1f" % ((os.cpu_count(),) + os.getloadavg()))

    # verify on the cut gripper path
    with open(os.path.join(root, "examples", "gripper", "gripper-path-slerp.json")) as f:
        scene = split_path(json.load(f), args.split)
    base = os.path.join(root, "examples", "gripper")
    for body in scene["bodies"]:  # mesh files relative to the example's folder
        if "mesh" in body and isinstance(body["mesh"], str) and not os.path.isabs(body["mesh"]):
            body["mesh"] = os.path.join(base, body["mesh"])
        if isinstance(body.get("mesh"), dict) and "file" in body["mesh"] and not os.path.isabs(body["mesh"]["file"]):
            body["mesh"]["file"] = os.path.join(base, body["mesh"]["file"])
    path = os.path.join(work, "gripper-path-%d.json" % args.split)
    with open(path, "w") as f:
        json.dump(scene, f)
    keyframes = [len(b["motion"]["poses"]) for b in scene["bodies"] if b.get("motion", {}).get("type") == "keyframes"]
    print("\nverify: gripper slerp path, %d keyframes (%s)" % (keyframes[0], path))
    print("| threads | wall [s] | CPU [s] | speed-up | verdict |")
    print("|--:|--:|--:|--:|---|")
    reference, one = None, None
    for n in threads:
        out = os.path.join(work, "verify-%d.json" % n)
        runs = []
        for _ in range(args.repeat):
            with open(out, "w") as f:
                runs.append(timed([args.tmcert, "verify", path, "--json", "--threads", str(n)], stdout=f))
        wall, cpu = best(runs)
        with open(out) as f:
            result = json.load(f)
        same = strip_seconds(result)
        if reference is None:
            reference, one = same, wall
        elif same != reference:
            sys.exit("verify --threads %d: a result different from --threads %d" % (n, threads[0]))
        print("| %d | %.2f | %.2f | %.2f | %s |" % (n, wall, cpu, one / wall, result["verdict"]))
    print("results equal for every thread count (seconds left out): yes")

    # batch on the roadmap
    env = os.path.join(work, "environment.json")
    requests = os.path.join(work, "requests.jsonl")
    with open(env, "w") as f:
        json.dump(batch_throughput.environment(), f)
    with open(requests, "w") as f:
        for e in batch_throughput.edges(args.edges, random.Random(args.seed)):
            f.write(json.dumps(e) + "\n")
    print("\nbatch: warehouse roadmap, %d requests" % args.edges)
    print("| threads | wall [s] | CPU [s] | requests/s | speed-up |")
    print("|--:|--:|--:|--:|--:|")
    reference, one = None, None
    for n in threads:
        out = os.path.join(work, "batch-%d.jsonl" % n)
        wall, cpu = best([timed([args.tmcert, "batch", "--scene", env, "--threads", str(n), "-o", out, requests])
                          for _ in range(1 if args.edges > 2000 else args.repeat)])
        with open(out, "rb") as f:
            data = f.read()
        if reference is None:
            reference, one = data, wall
        elif data != reference:
            sys.exit("batch --threads %d: bytes different from --threads %d" % (n, threads[0]))
        print("| %d | %.2f | %.2f | %.0f | %.2f |" % (n, wall, cpu, args.edges / wall, one / wall))
    print("outputs byte-identical for every thread count: yes")

    # batch-merge of the output cut into shards
    shards = [[] for _ in range(args.shards)]
    for line in reference.splitlines(keepends=True):
        shards[json.loads(line)["index"] % args.shards].append(line)
    files = []
    for i, lines in enumerate(shards):
        files.append(os.path.join(work, "shard-%d.jsonl" % i))
        with open(files[-1], "wb") as f:
            f.writelines(lines)
    merged = os.path.join(work, "merged.jsonl")
    wall, cpu = best([timed([args.tmcert, "batch-merge", "-o", merged] + files) for _ in range(args.repeat)])
    with open(merged, "rb") as f:
        if f.read() != reference:
            sys.exit("batch-merge: bytes different from the unsharded run")
    print("\nbatch-merge: %d lines (%.1f MB) in %d files: %.3f s wall, %.3f s CPU; bytes equal to the unsharded run: yes"
          % (len(reference.splitlines()), len(reference) / 1e6, args.shards, wall, cpu))
    if not args.keep:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
