#!/usr/bin/env python3
"""The held-out degenerate CCD families through tmcert_ccd_bench: a table.

  bench/ccd_degenerate.py OUT [--build build] [--n 1000] [--seed 1]
                          [--kernel filtered] [--kernel exact] [--families a,b] [--reuse]

Writes the families of scripts/ccd_degenerate_queries.py to OUT (truth from
its exact oracle), converts each family (its vertex-face and edge-edge files
together) with scripts/ccd_csv_to_scene.py (epsilon 1e-6 of the largest
query box), and times every query with `tmcert_ccd_bench --scene --truth
--cpu-time --kernel K` (thread CPU time per check, one verifier per
family). Prints one markdown row per family and kernel: queries, colliding,
false verdicts (false safe + false collision), undecided, and the median,
mean and largest CPU time per query. Exit 1 if any query is false or
undecided (times are reported, not judged).
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--n", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--kernel", action="append", choices=["filtered", "exact"])
    ap.add_argument("--families")
    ap.add_argument("--reuse", action="store_true", help="time the families already written to OUT (no generation)")
    args = ap.parse_args()
    kernels = args.kernel or ["filtered"]
    gen = [sys.executable, os.path.join(ROOT, "scripts", "ccd_degenerate_queries.py"), args.out,
           "--n", str(args.n), "--seed", str(args.seed)]
    if args.families:
        gen += ["--families", args.families]
    if args.reuse:
        families = sorted(f for f in os.listdir(args.out) if os.path.isdir(os.path.join(args.out, f)))
    else:
        families = [line.split()[0] for line in subprocess.run(gen, check=True, capture_output=True,
                                                                 text=True).stdout.splitlines()]
    made = f"as written in {args.out}" if args.reuse else f"{args.n} queries each (seed {args.seed})"
    print(f"held-out degenerate CCD families: {made}, truth from the exact oracle; CPU time per query")
    print()
    print("| family | kernel | n | colliding | false | undecided | median us | mean us | max us |")
    print("|---|---|--:|--:|--:|--:|--:|--:|--:|")
    bad = 0
    for family in families:
        files = []
        for kind in ("vertex-face", "edge-edge"):
            f = os.path.join(args.out, family, kind, "queries.csv")
            if os.path.exists(f):
                files.append(f)
        scene = os.path.join(args.out, family, "scene.json")
        truth = os.path.join(args.out, family, "truth.json")
        subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "ccd_csv_to_scene.py"), *files, "-o", scene,
                        "--truth-out", truth], check=True, capture_output=True)
        for kernel in kernels:
            extra = [] if kernel == "filtered" else ["--kernel", kernel]  # (builds before --kernel existed)
            out = subprocess.run([os.path.join(args.build, "tmcert_ccd_bench"), "--scene", scene, "--truth", truth,
                                  "--cpu-time", *extra], capture_output=True, text=True)
            rows = {line.split("|")[1].strip(): [c.strip() for c in line.split("|")[2:-1]]
                    for line in out.stdout.splitlines() if line.startswith("| ")}
            if "all" not in rows:
                print(f"| {family} | {kernel} | tmcert_ccd_bench failed (exit {out.returncode}): {out.stderr.strip()} |")
                bad += 1
                continue
            n, coll, fs, fc, und_free, und_coll, _, med, mean, mx, _ = rows["all"]
            free = int(n) - int(coll)
            undecided = round(float(und_free.rstrip("%")) * free / 100) + round(
                float(und_coll.rstrip("%")) * int(coll) / 100)
            false = int(fs) + int(fc)
            bad += false + undecided
            print(f"| {family} | {kernel} | {n} | {coll} | {false} | {undecided} | {med} | {mean} | {mx} |")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
