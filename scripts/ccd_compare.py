#!/usr/bin/env python3
"""Score a tmcert result against the ground truth of converted CCD queries.

  ccd_compare.py RESULT.json TRUTH.json

RESULT.json is `tmcert verify SCENE --json` output for a scene written by
ccd_csv_to_scene.py, TRUTH.json the --truth-out list of that conversion.
Prints, per kind (vertex-face, edge-edge) and in all: queries, colliding
ones, false safe (a colliding query reported safe), false collision (a
free query reported collision), undecided among free and among colliding
queries, and the check times (median, mean, max, from the result's
stats.seconds; checks cleared by the prefilter report 0).

Exit status: 0 when there is no false safe and no false collision (and,
with --strict, no undecided query either), 1 otherwise, 3 on unreadable
input. Queries without ground truth are counted but not scored.
"""
import json
import statistics
import sys


def fail(message):
    print(f"ccd_compare: {message}", file=sys.stderr)
    sys.exit(3)


def load(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail(f"{path}: {e}")


def main():
    args = sys.argv[1:]
    strict = "--strict" in args
    args = [a for a in args if a != "--strict"]
    if len(args) != 2:
        fail("usage: ccd_compare.py [--strict] RESULT.json TRUTH.json")
    result, truth = load(args[0]), load(args[1])
    if not isinstance(result, dict) or result.get("format") != "tmcert-result/1":
        fail(f"{args[0]}: not a tmcert-result/1 document")
    checks = result.get("checks", [])
    if not isinstance(truth, list) or len(truth) != len(checks):
        fail(f"{args[1]}: {len(truth) if isinstance(truth, list) else 'no'} entries for {len(checks)} checks")

    for i, entry in enumerate(truth):
        if (not isinstance(entry, dict) or entry.get("kind") not in ("vf", "ee") or "truth" not in entry
                or not (entry["truth"] is None or isinstance(entry["truth"], bool))):
            fail(f"{args[1]}: entry {i} is not {{\"kind\": \"vf\"|\"ee\", \"truth\": true|false|null}}")
    rows = {}
    for entry, check in zip(truth, checks):
        verdict = check.get("verdict")
        for key in (entry["kind"], "all"):
            r = rows.setdefault(key, {"n": 0, "coll": 0, "free": 0, "unknown": 0, "fs": 0, "fc": 0,
                                      "und_free": 0, "und_coll": 0, "found": 0, "seconds": []})
            r["n"] += 1
            r["seconds"].append(float(check.get("stats", {}).get("seconds", 0)))
            t = entry["truth"]
            if t is None:
                r["unknown"] += 1
            elif t:
                r["coll"] += 1
                r["fs"] += verdict == "safe"
                r["und_coll"] += verdict == "undecided"
                r["found"] += verdict == "collision"
            else:
                r["free"] += 1
                r["fc"] += verdict == "collision"
                r["und_free"] += verdict == "undecided"

    def pct(a, b):
        return f"{100.0 * a / b:.2f}%" if b else "-"

    print(f"epsilon {result.get('epsilon')}, kernel {result.get('kernel')}, certified {result.get('certified')}")
    print("| kind | n | colliding | false safe | false collision | undecided (free) | undecided (colliding) "
          "| collision proven | median us | mean us | max us |")
    print("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    names = {"vf": "vertex-face", "ee": "edge-edge", "all": "all"}
    for key in ("vf", "ee", "all"):
        if key not in rows:
            continue
        r = rows[key]
        us = [s * 1e6 for s in r["seconds"]]
        print(f"| {names[key]} | {r['n']} | {r['coll']} | {r['fs']} | {r['fc']} | {pct(r['und_free'], r['free'])} "
              f"| {pct(r['und_coll'], r['coll'])} | {r['found']} | {statistics.median(us):.2f} "
              f"| {statistics.mean(us):.2f} | {max(us):.1f} |")
    if rows["all"]["unknown"]:
        print(f"{rows['all']['unknown']} queries without ground truth (not scored)")
    bad = rows["all"]["fs"] + rows["all"]["fc"]
    if strict:
        bad += rows["all"]["und_free"] + rows["all"]["und_coll"]
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
