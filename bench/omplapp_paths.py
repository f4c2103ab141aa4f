#!/usr/bin/env python3
"""tmcert on real planner output: the OMPL.app problems' stored solution paths.

Issue 23 item 8 and issue 26 item 5. For each OMPL.app problem with a stored
path (by default the seven of the issues: Twistycool, Twistycooler,
alpha-1.1, alpha-1.2, alpha-1.5, Apartment, Easy; --all adds cubicles,
escape and spirelli; pipedream's environment mesh is not in OMPL.app), in
one run:

  - converts the problem (scripts/omplapp_to_scene.py: OMPL.app's geometry,
    exactly; the path as slerp keyframes);
  - OMPL.app's own checking (bench/omplapp_fcl.cpp, `tmcert_omplapp_fcl
    check`): OMPL's DiscreteMotionValidator at its default resolution with
    FCL as the state validity checker, on the whole path (PathGeometric::check,
    median of --reps runs) and on each shortcut query;
  - `tmcert verify` of the whole path at default settings (filtered kernel,
    one thread unless --threads says otherwise, the default epsilon: 1/1000 of the box of the robot's sweep
    and the environment), and at the default epsilon divided by each
    --factors value (default 10 and 100);
  - `tmcert verify` of each shortcut query (waypoint k to k+2 and k to k+4:
    what OMPL's path simplifier asks its validator), each a scene of its own,
    at default settings; the undecided ones again at the divided epsilons;
  - a certificate of the whole path at default settings (`--certificate`):
    size, the time to write it (the verify run), `tmcert check` time, the
    peak memory of both (/usr/bin/time).

Each tmcert run has a wall-clock timeout (--timeout, default 600 s; the
run's process group is killed and it counts as `timeout`) and a memory
limit (--memory-limit, default 4096 MiB, tmcert's own option: past it the
run ends with exit 4, counted as `out of memory`). Times are the CPU time
(user + system) and the wall time of whole processes (reading the scene and
meshes, preparing the bodies, the search), from /usr/bin/time; OMPL's are
the CPU time of the checks alone, in-process.

Usage:
  bench/omplapp_paths.py OMPLAPP [--scenes DIR] [--tmcert build/tmcert] [--threads N]
                         [--tool build/tmcert_omplapp_fcl] [--only NAME ...] [--all]
                         [--factors 10,100] [--timeout S] [--memory-limit MIB] [--reps N]
                         [--no-shortcuts] [--no-certificates] [--json OUT.json]
OMPLAPP is the OMPL.app checkout (github.com/ompl/omplapp) or its resources/3D
folder. Without it (or without the two programs) the benchmark prints
"omplapp_paths: skipped: ..." and exits 0: nothing was measured. --scenes
keeps the converted scenes there (default: a temporary folder, removed).
Exit status otherwise 0; 3 on bad usage.
"""
import argparse
import json
import os
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import omplapp_to_scene  # noqa: E402

ISSUE_SET = ["Twistycool", "Twistycooler", "alpha-1.1", "alpha-1.2", "alpha-1.5", "Apartment", "Easy"]


def skip(message):
    print(f"omplapp_paths: skipped: {message}")
    sys.exit(0)


def run_timed(cmd, timeout, cwd=None):
    """Runs cmd under /usr/bin/time: (exit code or 'timeout', stdout, wall s, CPU s (user + system), peak MiB).

    The run is a process group of its own, killed whole at the timeout (so
    that no tmcert outlives /usr/bin/time)."""
    with tempfile.NamedTemporaryFile("r", suffix=".time") as tf:
        full = ["/usr/bin/time", "-f", "%e %U %S %M", "-o", tf.name] + cmd
        start = time.monotonic()
        proc = subprocess.Popen(full, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=cwd,
                                start_new_session=True)
        try:
            out, _ = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
            return "timeout", "", time.monotonic() - start, None, None
        wall, cpu, rss = time.monotonic() - start, None, None
        try:
            fields = tf.read().split()
            wall, cpu, rss = float(fields[-4]), float(fields[-3]) + float(fields[-2]), int(fields[-1]) / 1024.0
        except (ValueError, IndexError):
            pass
        return proc.returncode, out, wall, cpu, rss


MEMORY_LIMIT = ["--memory-limit", "4096"]  # set from --memory-limit in main()
THREADS = ["--threads", "1"]  # set from --threads in main()


def verify(tmcert, scene, timeout, epsilon=None, certificate=None):
    """tmcert verify --json: a dict with verdict, epsilon, nodes, search s, wall s, peak MiB, undecided."""
    cmd = [tmcert, "verify", scene, "--json"] + MEMORY_LIMIT + THREADS
    if epsilon is not None:
        cmd += ["--epsilon", epsilon]
    if certificate is not None:
        cmd += ["--certificate", certificate]
    rc, out, wall, cpu, rss = run_timed(cmd, timeout)
    r = {"wall": wall, "cpu": cpu, "rss": rss, "rc": rc}
    if rc == "timeout":
        r["verdict"] = "timeout"
        return r
    if rc == 4:
        r["verdict"] = "out of memory"  # or an internal error: exit 4 either way
        return r
    if rc not in (0, 1, 2, 3):
        r["verdict"] = f"crash (exit {rc})"
        return r
    try:
        doc = json.loads(out)
    except json.JSONDecodeError:
        r["verdict"] = f"error (exit {rc})"
        return r
    check = doc["checks"][0]
    stats = check.get("stats", {})
    r.update(verdict=doc["verdict"], epsilon=check.get("epsilon"), epsilon_approx=check.get("epsilon_approx"),
             refined=check.get("refined", False),
             nodes=stats.get("nodes"), search=stats.get("seconds"), undecided=check.get("undecided", []),
             prefiltered=stats.get("prefiltered"))
    if "witness" in check:
        r["witness_t"] = check["witness"].get("t_approx")
    return r


def divided(epsilon, factor):
    return str(Fraction(epsilon) / factor)


def fcl_check(tool, cfg, path, reps, queries):
    cmd = [tool, "check", cfg, path, "--reps", str(reps)] + (["--queries"] if queries else [])
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        print(f"omplapp_paths: {' '.join(cmd)}: exit {proc.returncode}: {proc.stderr.strip()}", file=sys.stderr)
        sys.exit(3)
    out = {"queries": {}}
    for line in proc.stdout.splitlines():
        d = json.loads(line)
        if d["kind"] == "query":
            out["queries"][(d["from"], d["to"])] = d
        else:
            out[d["kind"]] = d
    return out


def undecided_edges(r):
    """The path edges (k for the part [k, k+1] of the parameter) that hold an undecided interval."""
    edges = set()
    for u in r.get("undecided", []):
        lo, hi = (Fraction(x) for x in u["t"])
        first = lo.numerator // lo.denominator
        last = max(first, -((-hi.numerator) // hi.denominator) - 1)  # ceil(hi) - 1
        edges.update(range(first, last + 1))
    return sorted(edges)


FINE = 100000  # states of FCL's cross-check of an edge OMPL passes and tmcert proves colliding


def fine_check(tool, res):
    """FCL on FINE + 1 states of each shortcut query that OMPL's check passed and tmcert proved colliding."""
    for q in res.get("queries", []):
        if q["fcl"]["valid"] and q["verdict"] == "collision" and "fine" not in q:
            cmd = [tool, "sample", res["cfg"], res["path"], str(q["from"]), str(q["to"]), str(FINE)]
            proc = subprocess.run(cmd, capture_output=True, text=True)
            q["fine"] = json.loads(proc.stdout) if proc.returncode == 0 else {"error": proc.stderr.strip()}


def fmt_s(x):
    if x is None:
        return "-"
    return f"{x:.3f}" if x < 10 else f"{x:.1f}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("omplapp")
    ap.add_argument("--scenes", help="keep the converted scenes in this folder (reused when present)")
    ap.add_argument("--tmcert", default=os.path.join(ROOT, "build", "tmcert"))
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", "tmcert_omplapp_fcl"))
    ap.add_argument("--only", nargs="*")
    ap.add_argument("--all", action="store_true", help="every problem with a stored path, not just the issues' seven")
    ap.add_argument("--factors", default="10,100", help="divide the default epsilon by these (comma-separated)")
    ap.add_argument("--timeout", type=float, default=600.0, help="per tmcert run, seconds")
    ap.add_argument("--memory-limit", type=int, default=4096,
                    help="MiB, passed to every tmcert run (--memory-limit; exit 4 past it)")
    ap.add_argument("--reps", type=int, default=3, help="runs of OMPL's whole-path check (median)")
    ap.add_argument("--threads", type=int, default=1,
                    help="tmcert verify --threads (default 1, as OMPL's checking)")
    ap.add_argument("--no-shortcuts", action="store_true")
    ap.add_argument("--no-certificates", action="store_true")
    ap.add_argument("--json", help="write every measurement to this file")
    ap.add_argument("--from-json", help="print the tables of a run saved with --json (runs nothing else)")
    a = ap.parse_args()
    MEMORY_LIMIT[1] = str(a.memory_limit)
    THREADS[1] = str(a.threads)
    if a.from_json:
        with open(a.from_json) as f:
            saved = json.load(f)
        report(saved["results"], saved["factors"], argparse.Namespace(**saved["options"]))
        return 0
    try:
        factors = [int(f) for f in a.factors.split(",") if f]
    except ValueError:
        print("omplapp_paths: --factors: comma-separated integers", file=sys.stderr)
        return 3

    resources = a.omplapp
    if os.path.isdir(os.path.join(resources, "resources", "3D")):
        resources = os.path.join(resources, "resources", "3D")
    if not os.path.isdir(resources):
        skip(f"{a.omplapp} does not exist (git clone https://github.com/ompl/omplapp)")
    for prog, what in ((a.tmcert, "tmcert"), (a.tool, "tmcert_omplapp_fcl (needs libassimp-dev, libfcl-dev)")):
        if not (os.path.isfile(prog) and os.access(prog, os.X_OK)):
            skip(f"{prog} is not built ({what})")

    names = a.only or (None if a.all else ISSUE_SET)
    found = [p for p in omplapp_to_scene.problems(resources) if names is None or p[0] in names]
    order = {n: i for i, n in enumerate(ISSUE_SET)}
    found.sort(key=lambda p: (order.get(p[0], len(order)), p[0]))
    if not found:
        skip(f"{resources}: no problem with a stored path")
    work = a.scenes or tempfile.mkdtemp(prefix="omplapp-scenes-")
    results = []
    try:
        for name, cfg, path in found:
            pdir = os.path.join(work, name)
            info_file = os.path.join(pdir, "problem.json")
            if os.path.isfile(info_file):
                with open(info_file) as f:
                    info = json.load(f)
            else:
                info = omplapp_to_scene.convert(a.tool, name, cfg, path, work)
                if info is None:
                    continue
            print(f"== {name}: {info['states']} states, robot {info['robot']['triangles']} / env "
                  f"{info['env']['triangles']} triangles", file=sys.stderr, flush=True)
            res = {"name": name, "cfg": cfg, "path": path, "states": info["states"],
                   "robot_triangles": info["robot"]["triangles"],
                   "env_triangles": info["env"]["triangles"]}
            fcl = fcl_check(a.tool, cfg, path, a.reps, not a.no_shortcuts)
            res["fcl"] = {k: v for k, v in fcl.items() if k != "queries"}
            scene = os.path.join(pdir, "path.json")
            d = verify(a.tmcert, scene, a.timeout)
            d["undecided_edges"] = undecided_edges(d)
            res["default"] = d
            print(f"   path default: {d['verdict']} in {fmt_s(d['wall'])} s", file=sys.stderr, flush=True)
            res["divided"] = {}
            if d.get("epsilon") and not d.get("refined"):
                # the same epsilon, given: what the default epsilon's computation costs
                # (a refined run's epsilon is the smallest it used: not the default's)
                r = verify(a.tmcert, scene, a.timeout, d["epsilon"])
                res["given"] = r
                for f in factors:
                    r = verify(a.tmcert, scene, a.timeout, divided(d["epsilon"], f))
                    r["undecided_edges"] = undecided_edges(r)
                    res["divided"][f] = r
                    print(f"   path eps/{f}: {r['verdict']} in {fmt_s(r['wall'])} s", file=sys.stderr, flush=True)
            if not a.no_certificates:
                cert = os.path.join(work, f"{name}.cert")
                c = verify(a.tmcert, scene, a.timeout, certificate=cert)
                c["size"] = os.path.getsize(cert) if os.path.isfile(cert) and c["rc"] in (0, 1, 2) else None
                if c["size"] is not None:
                    rc, _, wall, cpu, rss = run_timed([a.tmcert, "check", cert, scene] + MEMORY_LIMIT, a.timeout)
                    c["check"] = {"rc": rc, "wall": wall, "cpu": cpu, "rss": rss}
                if os.path.isfile(cert):
                    os.remove(cert)
                res["certificate"] = c
                print(f"   certificate: {c['verdict']}, {c['size']} bytes", file=sys.stderr, flush=True)
            if not a.no_shortcuts:
                qs = []
                for q in info["queries"]:
                    qf = os.path.join(pdir, q["file"])
                    r = verify(a.tmcert, qf, a.timeout)
                    r["fcl"] = fcl["queries"][(q["from"], q["to"])]
                    r["from"], r["to"] = q["from"], q["to"]
                    if r["verdict"] == "undecided" and r.get("epsilon"):
                        r["divided"] = {}
                        for f in factors:
                            rr = verify(a.tmcert, qf, a.timeout, divided(r["epsilon"], f))
                            r["divided"][f] = rr
                            if rr["verdict"] != "undecided":
                                break
                    qs.append(r)
                res["queries"] = qs
                fine_check(a.tool, res)
                print(f"   {len(qs)} shortcut queries: "
                      f"{sum(q['verdict'] == 'undecided' for q in qs)} undecided", file=sys.stderr, flush=True)
            results.append(res)
    finally:
        if not a.scenes:
            shutil.rmtree(work, ignore_errors=True)

    if a.json:
        with open(a.json, "w") as f:
            json.dump({"results": results, "factors": factors,
                       "options": {"timeout": a.timeout, "reps": a.reps, "memory_limit": a.memory_limit,
                                   "threads": a.threads}},
                      f, indent=1, default=str)
    report(results, factors, a)
    return 0


def fmt_cpu(r):
    """CPU s (wall s) of a run."""
    if r is None:
        return "-"
    if r.get("cpu") is None:
        return f"- ({fmt_s(r['wall'])})"
    return f"{fmt_s(r['cpu'])} ({fmt_s(r['wall'])})"


def report(results, factors, a):
    some = results[0]["fcl"]["path"] if results else {}
    threads = getattr(a, "threads", 1)  # runs saved before --threads: one thread
    print(f"tmcert (filtered kernel, {threads} thread{'s' if threads != 1 else ''}) against OMPL {some.get('ompl', '?')}'s DiscreteMotionValidator "
          f"at its default resolution with FCL {some.get('fcl', '?')} (OMPL.app's checker); "
          f"timeout {a.timeout:.0f} s per tmcert run. Times: CPU s (user + system) of the whole process, "
          "wall s in parentheses; OMPL: CPU s of the check alone (meshes loaded and models built before), "
          f"median of {a.reps} runs.\n")
    print("Whole paths at default settings:\n")
    print("| problem | states | triangles robot / env | tmcert verdict | undecided edges | nodes | tmcert CPU s (wall) "
          "| OMPL+FCL | states checked | OMPL CPU s | CPU ratio |")
    print("|---|--:|--:|---|--:|--:|--:|---|--:|--:|--:|")
    for r in results:
        d, f = r["default"], r["fcl"]["path"]
        e = f["first_invalid_edge"]
        fv = "valid" if f["valid"] else ("start invalid" if e == -2 else f"invalid: edge {e}")
        ue = d.get("undecided_edges", [])
        ratio = f"{d['cpu'] / f['cpu_seconds']:.0f}" if d.get("cpu") and f["cpu_seconds"] else "-"
        print(f"| {r['name']} | {r['states']} | {r['robot_triangles']} / {r['env_triangles']} | {d['verdict']} "
              f"| {len(ue)} | {d.get('nodes', '-')} | {fmt_cpu(d)} | {fv} | {f['state_checks']} "
              f"| {f['cpu_seconds']:.4f} | {ratio} |")
    n_und = sum(r["default"]["verdict"] == "undecided" for r in results)
    print(f"\n{n_und} of {len(results)} paths undecided at default settings.\n")

    print("The same paths with the default epsilon given on the command line (the same search, without computing "
          "the default), and divided; verdict, CPU s (wall s):\n")
    print("| problem | epsilon (smallest used) | default | epsilon given | "
          + " | ".join(f"epsilon / {f}" for f in factors) + " |")
    print("|---|--:|---|---|" + "---|" * len(factors))
    for r in results:
        d = r["default"]
        cells = []
        for x in [r.get("given")] + [r["divided"].get(f) or r["divided"].get(str(f)) for f in factors]:
            cells.append("-" if x is None else f"{x['verdict']}, {fmt_cpu(x)}")
        eps = d.get("epsilon_approx")
        refined = " (refined)" if d.get("refined") else ""
        print(f"| {r['name']} | {'-' if eps is None else f'{eps:.6g}'}{refined} | {d['verdict']}, {fmt_cpu(d)} | "
              + " | ".join(cells) + " |")
    print()

    if any("queries" in r for r in results):
        print("Shortcut queries (waypoint k to k+2 and k+4), each a scene of its own, tmcert verify at default "
              "settings; the undecided ones again at the divided epsilons:\n")
        print("| problem | queries | safe | collision | undecided | timeout / other | decided at eps/" + " / eps/".join(map(str, factors))
              + " | tmcert CPU s (sum) | median | OMPL+FCL valid / invalid | OMPL CPU s (sum) "
              "| FCL valid, tmcert collision | FCL invalid, tmcert safe |")
        print("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
        tot = {"n": 0, "safe": 0, "collision": 0, "undecided": 0, "cpu": 0.0, "fcl": 0.0, "fv": 0, "miss": 0,
               "false_inv": 0}
        tot_dec = [0] * len(factors)
        for r in results:
            qs = r.get("queries")
            if qs is None:
                continue
            n = len(qs)
            c = {v: sum(q["verdict"] == v for q in qs) for v in ("safe", "collision", "undecided")}
            dec = []
            for f in factors:
                dec.append(sum(1 for q in qs if q["verdict"] == "undecided" and any(
                    x["verdict"] in ("safe", "collision") for k, x in q.get("divided", {}).items()
                    if int(k) <= f)))
            cpu = sum(q["cpu"] or 0 for q in qs)
            med = statistics.median(q["cpu"] or 0 for q in qs)
            fv = sum(q["fcl"]["valid"] for q in qs)
            fs = sum(q["fcl"]["cpu_seconds"] for q in qs)
            miss = sum(q["fcl"]["valid"] and q["verdict"] == "collision" for q in qs)
            false_inv = sum((not q["fcl"]["valid"]) and q["verdict"] == "safe" for q in qs)
            other = n - c["safe"] - c["collision"] - c["undecided"]
            tot["other"] = tot.get("other", 0) + other
            print(f"| {r['name']} | {n} | {c['safe']} | {c['collision']} | {c['undecided']} | {other} | "
                  + " / ".join(map(str, dec)) + f" | {cpu:.1f} | {med:.3f} | {fv} / {n - fv} | {fs:.3f} "
                  f"| {miss} | {false_inv} |")
            tot["n"] += n
            for v in ("safe", "collision", "undecided"):
                tot[v] += c[v]
            tot["cpu"] += cpu
            tot["fcl"] += fs
            tot["fv"] += fv
            tot["miss"] += miss
            tot["false_inv"] += false_inv
            tot_dec = [x + y for x, y in zip(tot_dec, dec)]
        print(f"| all | {tot['n']} | {tot['safe']} | {tot['collision']} | {tot['undecided']} | {tot.get('other', 0)} | "
              + " / ".join(map(str, tot_dec)) + f" | {tot['cpu']:.1f} | | {tot['fv']} / {tot['n'] - tot['fv']} "
              f"| {tot['fcl']:.3f} | {tot['miss']} | {tot['false_inv']} |\n")
        for r in results:
            for q in r.get("queries", []):
                if q["fcl"]["valid"] and q["verdict"] == "collision":
                    fine = q.get("fine", {})
                    seen = (f"FCL on {fine['states']} evenly spaced states of the edge: {fine['invalid']} in collision"
                            + (f", s in [{fine['first']:.5f}, {fine['last']:.5f}]" if fine["invalid"] else "")
                            if "states" in fine else "no finer FCL check")
                    print(f"  {r['name']} {q['from']}-{q['to']}: OMPL's {q['fcl']['state_checks']} states pass; "
                          f"tmcert proves a contact at t = {q.get('witness_t')}; {seen}")
                if q["verdict"] == "undecided" and not any(
                        x["verdict"] in ("safe", "collision") for x in q.get("divided", {}).values()):
                    print(f"  {r['name']} {q['from']}-{q['to']}: undecided at every epsilon tried")
                if q["verdict"] not in ("safe", "collision", "undecided"):
                    print(f"  {r['name']} {q['from']}-{q['to']}: {q['verdict']}")
        print()

    if any("certificate" in r for r in results):
        print("Certificates of the whole paths at default settings (`verify --certificate`, then `check`):\n")
        print("| problem | verdict | size MB | write: verify CPU s (wall) | peak MiB | check CPU s (wall) "
              "| check peak MiB | check exit |")
        print("|---|---|--:|--:|--:|--:|--:|--:|")
        for r in results:
            c = r.get("certificate")
            if c is None:
                continue
            ch = c.get("check")
            size = "-" if c.get("size") is None else f"{c['size'] / 1e6:.2f}"
            rss = "-" if c.get("rss") is None else f"{c['rss']:.0f}"
            crss = "-" if not ch or ch.get("rss") is None else f"{ch['rss']:.0f}"
            print(f"| {r['name']} | {c['verdict']} | {size} | {fmt_cpu(c)} | {rss} | "
                  f"{fmt_cpu(ch)} | {crss} | {ch.get('rc', '-') if ch else '-'} |")
        print()


if __name__ == "__main__":
    sys.exit(main())
