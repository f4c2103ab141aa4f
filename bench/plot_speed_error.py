#!/usr/bin/env python3
"""SVG plots and Markdown summaries for tmcert_speed_error (bench/speed_error.cpp).

Usage:
    python3 bench/plot_speed_error.py SPEED.csv [HARD.csv] [--out DIR] [--markdown]

SPEED.csv is written by `tmcert_speed_error --csv`, HARD.csv by `--hard-csv`.
Writes into DIR (default bench/plots):

    time_vs_epsilon.svg       seconds against f = epsilon / scene size, log-log,
                              one panel per scene, a line per kernel
    nodes_vs_epsilon.svg      subdivision nodes against f, log-log
    outcome_vs_epsilon.svg    verdicts against f: per scene, kernel and f a bar
                              split into the safe / collision / undecided share
                              of the checks
    undecided_vs_epsilon.svg  undecided share of the parameter length against f
    filter_failures.svg       interval filter failures per predicate (filtered
                              kernel) against f
    fast_vs_certified.svg     (with HARD.csv) the fast kernel's false safes and
                              missed witnesses against f, per query set and
                              offset

With --markdown, also prints compact Markdown tables (the ones in
bench/README.md) to stdout.  Python 3 standard library only.
"""

import csv
import math
import os
import sys
from collections import OrderedDict, defaultdict

KERNELS = ["fast", "filtered", "exact"]
KERNEL_COLORS = {"fast": "#d95f02", "filtered": "#1b9e77", "exact": "#7570b3"}
KERNEL_DASH = {"fast": "6,3", "filtered": "", "exact": "2,2"}
VERDICT_COLORS = {"safe": "#4daf4a", "collision": "#e41a1c", "undecided": "#bdbdbd"}
PREDICATES = [("vf", "vertex-face"), ("ee", "edge-edge"), ("fv", "face-vertex"), ("static", "static (start, witness)")]
PREDICATE_COLORS = {"vf": "#1f78b4", "ee": "#33a02c", "fv": "#ff7f00", "static": "#6a3d9a"}
OFFSET_COLORS = ["#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#e6ab02"]


# ---------------------------------------------------------------- SVG helpers

def esc(text):
    return str(text).replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


class Svg:
    def __init__(self, width, height):
        self.width, self.height = width, height
        self.items = []

    def add(self, item):
        self.items.append(item)

    def text(self, x, y, s, size=11, anchor="start", weight="normal", color="#222", rotate=None):
        transform = f' transform="rotate({rotate} {x:.1f} {y:.1f})"' if rotate is not None else ""
        self.add(f'<text x="{x:.1f}" y="{y:.1f}" font-size="{size}" text-anchor="{anchor}" '
                 f'font-weight="{weight}" fill="{color}"{transform}>{esc(s)}</text>')

    def line(self, x1, y1, x2, y2, color="#222", width=1, dash=""):
        d = f' stroke-dasharray="{dash}"' if dash else ""
        self.add(f'<line x1="{x1:.1f}" y1="{y1:.1f}" x2="{x2:.1f}" y2="{y2:.1f}" stroke="{color}" '
                 f'stroke-width="{width}"{d}/>')

    def rect(self, x, y, w, h, fill, stroke="none"):
        self.add(f'<rect x="{x:.1f}" y="{y:.1f}" width="{max(w, 0):.1f}" height="{max(h, 0):.1f}" '
                 f'fill="{fill}" stroke="{stroke}"/>')

    def polyline(self, points, color, width=1.6, dash=""):
        if len(points) < 2:
            return
        d = f' stroke-dasharray="{dash}"' if dash else ""
        pts = " ".join(f"{x:.1f},{y:.1f}" for x, y in points)
        self.add(f'<polyline points="{pts}" fill="none" stroke="{color}" stroke-width="{width}"{d}/>')

    def marker(self, x, y, color, shape="circle", size=3.2):
        if shape == "square":
            self.rect(x - size, y - size, 2 * size, 2 * size, color)
        elif shape == "triangle":
            self.add(f'<polygon points="{x:.1f},{y - size - 1:.1f} {x - size - 1:.1f},{y + size:.1f} '
                     f'{x + size + 1:.1f},{y + size:.1f}" fill="{color}"/>')
        elif shape == "cross":
            self.line(x - size, y - size, x + size, y + size, color, 1.5)
            self.line(x - size, y + size, x + size, y - size, color, 1.5)
        else:
            self.add(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{size:.1f}" fill="{color}"/>')

    def write(self, path):
        with open(path, "w", encoding="utf-8") as out:
            out.write(f'<svg xmlns="http://www.w3.org/2000/svg" width="{self.width}" height="{self.height}" '
                      f'viewBox="0 0 {self.width} {self.height}" font-family="Helvetica, Arial, sans-serif">\n')
            out.write(f'<rect width="{self.width}" height="{self.height}" fill="white"/>\n')
            for item in self.items:
                out.write(item + "\n")
            out.write("</svg>\n")


def nice_log_ticks(lo, hi):
    a, b = math.floor(math.log10(lo)), math.ceil(math.log10(hi))
    step = max(1, (b - a) // 6)
    return [10.0 ** e for e in range(a, b + 1, step)]


def fmt_pow(v):
    e = round(math.log10(v))
    return f"1e{e}"


def nice_linear_ticks(hi):
    if hi <= 0:
        return [0]
    raw = hi / 4
    mag = 10 ** math.floor(math.log10(raw))
    step = min((s * mag for s in (1, 2, 2.5, 5, 10) if s * mag >= raw), default=mag * 10)
    ticks, v = [], 0.0
    while v <= hi * 1.0001:
        ticks.append(v)
        v += step
    return ticks


class Panel:
    """A plot area: x is always f (log, 1e-1 on the left down to 1e-9 on the right)."""

    def __init__(self, svg, x, y, w, h, title, ylog, ylo, yhi, ylabel):
        self.svg, self.x, self.y, self.w, self.h = svg, x, y, w, h
        self.ylog, self.ylo, self.yhi = ylog, ylo, yhi
        self.xlo, self.xhi = 1e-9, 1e-1
        svg.rect(x, y, w, h, "#fafafa", "#999")
        svg.text(x + w / 2, y - 6, title, size=11, anchor="middle", weight="bold")
        for e in range(-9, 0):
            px = self.px(10.0 ** e)
            svg.line(px, y + h, px, y + h + 3, "#666")
            if e % 2 == 1:
                svg.text(px, y + h + 14, f"1e{e}", size=9, anchor="middle", color="#444")
        if ylog:
            for t in nice_log_ticks(ylo, yhi):
                if ylo <= t <= yhi:
                    py = self.py(t)
                    svg.line(x, py, x + w, py, "#e3e3e3")
                    svg.text(x - 4, py + 3, fmt_pow(t), size=9, anchor="end", color="#444")
        else:
            for t in nice_linear_ticks(yhi):
                py = self.py(t)
                svg.line(x, py, x + w, py, "#e3e3e3")
                label = f"{t:g}"
                svg.text(x - 4, py + 3, label, size=9, anchor="end", color="#444")
        svg.text(x - 34, y + h / 2, ylabel, size=9, anchor="middle", color="#444", rotate=-90)

    def px(self, f):
        # 1e-1 left, 1e-9 right: epsilon shrinks to the right.
        t = (math.log10(self.xhi) - math.log10(f)) / (math.log10(self.xhi) - math.log10(self.xlo))
        return self.x + 8 + t * (self.w - 16)

    def py(self, v):
        if self.ylog:
            v = min(max(v, self.ylo), self.yhi)
            t = (math.log10(v) - math.log10(self.ylo)) / (math.log10(self.yhi) - math.log10(self.ylo))
        else:
            t = 0 if self.yhi <= 0 else min(max(v, 0), self.yhi) / self.yhi
        return self.y + self.h - t * self.h


def grid_layout(count, cols, pw, ph, left=60, top=60, gapx=70, gapy=62):
    rows = (count + cols - 1) // cols
    width = left + cols * (pw + gapx)
    height = top + rows * (ph + gapy) + 30
    cells = []
    for i in range(count):
        r, c = divmod(i, cols)
        cells.append((left + c * (pw + gapx), top + r * (ph + gapy)))
    return width, height, cells


def legend(svg, x, y, entries):
    """entries: (label, color, dash, marker)"""
    for label, color, dash, mark in entries:
        svg.line(x, y - 4, x + 22, y - 4, color, 2, dash)
        if mark:
            svg.marker(x + 11, y - 4, color, mark)
        svg.text(x + 28, y, label, size=11)
        x += 40 + 7 * len(label)


# ---------------------------------------------------------------- data

def read_speed(path):
    rows = list(csv.DictReader(open(path, newline="")))
    for r in rows:
        r["f"] = float(r["f"])
        r["ran"] = r["ran"] == "1"
        for k in ("seconds", "und_frac", "size", "epsilon"):
            r[k] = float(r[k]) if r[k] else 0.0
        for k in ("checks", "safe", "collision", "undecided", "nodes", "vf_calls", "vf_exact", "ee_calls", "ee_exact",
                  "fv_calls", "fv_exact", "static_conf", "static_pairs", "static_exact", "static_tests", "und_limit",
                  "vf_screened", "ee_screened", "fv_screened", "hull_clears", "axis_clears"):
            r[k] = int(r[k]) if r.get(k) else 0
    return rows


def scenes_of(rows):
    out = OrderedDict()
    for r in rows:
        out.setdefault(r["scene"], r["group"])
    return list(out)


def by_scene_kernel(rows):
    d = defaultdict(list)
    for r in rows:
        if r["ran"]:
            d[(r["scene"], r["kernel"])].append(r)
    for v in d.values():
        v.sort(key=lambda r: -r["f"])
    return d


# ---------------------------------------------------------------- plots

def plot_metric(rows, path, key, ylabel, title):
    scenes = scenes_of(rows)
    data = by_scene_kernel(rows)
    pw, ph = 250, 150
    width, height, cells = grid_layout(len(scenes), 4, pw, ph, top=70)
    svg = Svg(width, height)
    svg.text(20, 22, title, size=15, weight="bold")
    legend(svg, 20, 46, [(k, KERNEL_COLORS[k], KERNEL_DASH[k], "circle") for k in KERNELS])
    for scene, (x, y) in zip(scenes, cells):
        values = [r[key] for k in KERNELS for r in data.get((scene, k), []) if r[key] > 0]
        if values:
            lo, hi = min(values), max(values)
            lo = 10 ** math.floor(math.log10(lo))
            hi = 10 ** math.ceil(math.log10(hi))
            if hi / lo < 100:
                lo, hi = lo / 10, hi * 10 if hi / lo < 10 else hi
        else:
            lo, hi = 1e-6, 1
        p = Panel(svg, x, y, pw, ph, scene, True, lo, hi, ylabel)
        for k in KERNELS:
            pts = [(p.px(r["f"]), p.py(r[key])) for r in data.get((scene, k), []) if r[key] > 0]
            svg.polyline(pts, KERNEL_COLORS[k], 1.8, KERNEL_DASH[k])
            for (px, py), r in zip(pts, [r for r in data.get((scene, k), []) if r[key] > 0]):
                svg.marker(px, py, KERNEL_COLORS[k], "cross" if r["und_limit"] else "circle")
        svg.text(x + pw / 2, y + ph + 27, "f = epsilon / scene size", size=9, anchor="middle", color="#444")
    svg.text(20, height - 10, "x: f from 1e-1 (left) to 1e-9 (right); a cross marks a run that used up the node "
             "budget (undecided \"limit\"); kernels not drawn at some f were not run there (see the table).",
             size=10, color="#444")
    svg.write(path)


def plot_outcome(rows, path):
    scenes = scenes_of(rows)
    data = by_scene_kernel(rows)
    pw, ph = 250, 110
    width, height, cells = grid_layout(len(scenes), 4, pw, ph, top=70)
    svg = Svg(width, height)
    svg.text(20, 22, "Outcome against epsilon: share of checks safe / collision / undecided", size=15, weight="bold")
    x0 = 20
    for label in ("safe", "collision", "undecided"):
        svg.rect(x0, 37, 14, 10, VERDICT_COLORS[label])
        svg.text(x0 + 18, 46, label, size=11)
        x0 += 30 + 8 * len(label)
    svg.text(x0 + 20, 46, "rows in each panel: fast (top), filtered, exact (bottom); empty: not run", size=11,
             color="#444")
    fs = [10.0 ** e for e in range(-1, -10, -1)]
    for scene, (x, y) in zip(scenes, cells):
        svg.text(x + pw / 2, y - 6, scene, size=11, anchor="middle", weight="bold")
        svg.rect(x, y, pw, ph, "#fafafa", "#999")
        band = ph / 3
        colw = (pw - 16) / len(fs)
        for i, k in enumerate(KERNELS):
            svg.text(x - 4, y + band * i + band / 2 + 3, k, size=9, anchor="end", color="#444")
            runs = {r["f"]: r for r in data.get((scene, k), [])}
            for j, f in enumerate(fs):
                r = next((v for key, v in runs.items() if abs(math.log10(key) - math.log10(f)) < 0.01), None)
                if not r or not r["checks"]:
                    continue
                bx = x + 8 + j * colw + 2
                by = y + band * i + 4
                bw, bh = colw - 4, band - 8
                acc = 0.0
                for label in ("safe", "collision", "undecided"):
                    share = r[label] / r["checks"]
                    svg.rect(bx + acc * bw, by, share * bw, bh, VERDICT_COLORS[label])
                    acc += share
        for j, f in enumerate(fs):
            if j % 2 == 0:
                svg.text(x + 8 + (j + 0.5) * colw, y + ph + 14, f"1e{-1 - j}", size=9, anchor="middle", color="#444")
    svg.text(20, height - 10, "columns: f = epsilon / scene size from 1e-1 (left) to 1e-9 (right)", size=10,
             color="#444")
    svg.write(path)


def plot_undecided(rows, path):
    scenes = [s for s in scenes_of(rows)
              if any(r["und_frac"] > 0 for r in rows if r["scene"] == s and r["ran"])]
    data = by_scene_kernel(rows)
    pw, ph = 250, 150
    width, height, cells = grid_layout(max(len(scenes), 1), 4, pw, ph, top=70)
    svg = Svg(width, height)
    svg.text(20, 22, "Undecided share of the parameter length against epsilon (scenes with any)", size=15,
             weight="bold")
    legend(svg, 20, 46, [(k, KERNEL_COLORS[k], KERNEL_DASH[k], "circle") for k in KERNELS])
    for scene, (x, y) in zip(scenes, cells):
        vals = [r["und_frac"] for k in KERNELS for r in data.get((scene, k), [])]
        hi = max(vals) if vals else 1
        hi = hi * 1.1 if hi > 0 else 1
        p = Panel(svg, x, y, pw, ph, scene, False, 0, hi, "undecided length share")
        for k in KERNELS:
            pts = [(p.px(r["f"]), p.py(r["und_frac"])) for r in data.get((scene, k), [])]
            svg.polyline(pts, KERNEL_COLORS[k], 1.8, KERNEL_DASH[k])
            for px, py in pts:
                svg.marker(px, py, KERNEL_COLORS[k])
    svg.text(20, height - 10, "undecided parameter length / total parameter length, over the checks ending "
             "undecided; x: f from 1e-1 (left) to 1e-9 (right)", size=10, color="#444")
    svg.write(path)


def failure_rates(r, of_all=False):
    """% of interval calls that needed exact arithmetic (of_all: % of all tests,
    including those the double pre-test kept without certified arithmetic)."""
    out = {}
    for key, _ in PREDICATES:
        if key == "static":
            calls, fails = r["static_pairs"], r["static_exact"]
        else:
            calls, fails = r[key + "_calls"], r[key + "_exact"]
            if of_all:
                calls += r[key + "_screened"]
        out[key] = (100.0 * fails / calls) if calls else None
    return out


def plot_filter(rows, path):
    filt = [r for r in rows if r["kernel"] == "filtered" and r["ran"]]
    scenes = [s for s in scenes_of(filt) if any(r["vf_calls"] + r["ee_calls"] + r["fv_calls"] > 0
                                                  for r in filt if r["scene"] == s)]
    pw, ph = 250, 150
    width, height, cells = grid_layout(max(len(scenes), 1), 4, pw, ph, top=70)
    svg = Svg(width, height)
    svg.text(20, 22, "Interval filter failures per predicate (filtered kernel): % decided by exact arithmetic",
             size=15, weight="bold")
    legend(svg, 20, 46, [(label, PREDICATE_COLORS[key], "", "circle") for key, label in PREDICATES] +
           [("% of all contact tests", "#555", "4,3", "")])
    for scene, (x, y) in zip(scenes, cells):
        rs = sorted([r for r in filt if r["scene"] == scene], key=lambda r: -r["f"])
        vals = [v for r in rs for v in failure_rates(r).values() if v is not None]
        hi = max(vals) if vals else 1
        hi = max(hi * 1.15, 1.0)
        p = Panel(svg, x, y, pw, ph, scene, False, 0, hi, "% exact")
        for key, _ in PREDICATES:
            pts = [(p.px(r["f"]), p.py(failure_rates(r)[key])) for r in rs if failure_rates(r)[key] is not None]
            svg.polyline(pts, PREDICATE_COLORS[key], 1.6)
            for px, py in pts:
                svg.marker(px, py, PREDICATE_COLORS[key], size=2.6)
            if key != "static" and any(r[key + "_screened"] for r in rs):
                pts = [(p.px(r["f"]), p.py(failure_rates(r, True)[key])) for r in rs
                       if failure_rates(r, True)[key] is not None]
                svg.polyline(pts, PREDICATE_COLORS[key], 1.2, "4,3")
    svg.text(20, height - 24, "contact tests, solid: exact fallbacks / interval calls (the filter's failure rate); "
             "dashed (when a double pre-test keeps pairs without certified arithmetic): exact / all tests;",
             size=10, color="#444")
    svg.text(20, height - 10, "static: simplex pairs the interval boxes and separating axes could not separate / "
             "pairs examined; x: f from 1e-1 (left) to 1e-9 (right)", size=10, color="#444")
    svg.write(path)


def read_hard(path):
    rows = list(csv.DictReader(open(path, newline="")))
    for r in rows:
        r["f"] = float(r["f"])
        for k in r:
            if k not in ("set", "offset", "kind", "f", "fast_s", "cert_s"):
                r[k] = int(r[k])
    return rows


def plot_hard(rows, path):
    allrows = [r for r in rows if r["kind"] == "~all"]
    sets = list(OrderedDict((r["set"], 1) for r in allrows))
    offsets = list(OrderedDict((r["offset"], 1) for r in allrows))
    pw, ph = 300, 170
    metrics = [("false_safe", "truth_coll", "fast false safe, % of colliding queries"),
               ("fast_und", "n", "fast undecided, % of queries")]
    width, height, cells = grid_layout(len(sets) * len(metrics), len(metrics), pw, ph, top=70, gapx=90)
    svg = Svg(width, height)
    svg.text(20, 22, "Fast (double precision) kernel against the truth, by offset from the origin", size=15,
             weight="bold")
    legend(svg, 20, 46, [(f"offset {o}", OFFSET_COLORS[i % len(OFFSET_COLORS)], "", "circle")
                         for i, o in enumerate(offsets)])
    i = 0
    for s in sets:
        for num, den, label in metrics:
            x, y = cells[i]
            i += 1
            rs = [r for r in allrows if r["set"] == s]
            vals = [100.0 * r[num] / r[den] for r in rs if r[den]]
            hi = max(max(vals) * 1.15 if vals else 1, 1.0)
            p = Panel(svg, x, y, pw, ph, f"{s}: {label}", False, 0, hi, "%")
            for j, o in enumerate(offsets):
                pts = sorted([(r["f"], 100.0 * r[num] / r[den]) for r in rs if r["offset"] == o and r[den]],
                             key=lambda t: -t[0])
                color = OFFSET_COLORS[j % len(OFFSET_COLORS)]
                svg.polyline([(p.px(f), p.py(v)) for f, v in pts], color, 1.8)
                for f, v in pts:
                    svg.marker(p.px(f), p.py(v), color)
    svg.text(20, height - 10, "x: f = epsilon / (2 sqrt 3) from 1e-1 (left) to 1e-9 (right); the certified kernels "
             "have no false safe anywhere", size=10, color="#444")
    svg.write(path)


# ---------------------------------------------------------------- markdown

def md_speed(rows):
    data = by_scene_kernel(rows)
    scenes = scenes_of(rows)
    fs = sorted({r["f"] for r in rows}, reverse=True)
    head = "| scene | " + " | ".join(f"{f:.0e}" for f in fs) + " |"
    sep = "|---|" + "--:|" * len(fs)

    def cell(scene, k, f, fn):
        r = next((r for r in data.get((scene, k), []) if abs(math.log10(r["f"]) - math.log10(f)) < 0.01), None)
        return fn(r) if r else "–"

    def verdict(r):
        if r["checks"] == 1:
            return {"safe": "s", "collision": "c", "undecided": "u"}[r["verdict"]]
        return f"{r['undecided']}u"

    print("Filtered kernel: seconds (best of the repetitions) and verdict (s/c/u; for several checks, the "
          "number undecided); `L` = node or stop budget used up (undecided pieces with reason limit):\n")
    print(head)
    print(sep)
    for s in scenes:
        print(f"| {s} | " + " | ".join(
            cell(s, "filtered", f, lambda r: f"{r['seconds']:.3g} {verdict(r)}{' L' if r['und_limit'] else ''}")
            for f in fs) + " |")
    print("\nfiltered / fast time:\n")
    print(head)
    print(sep)
    for s in scenes:
        cells = []
        for f in fs:
            a = next((r for r in data.get((s, "fast"), []) if abs(math.log10(r["f"]) - math.log10(f)) < 0.01), None)
            b = next((r for r in data.get((s, "filtered"), []) if abs(math.log10(r["f"]) - math.log10(f)) < 0.01),
                     None)
            cells.append(f"{b['seconds'] / max(a['seconds'], 1e-9):.2g}" if a and b and a["seconds"] > 0 else "–")
        print(f"| {s} | " + " | ".join(cells) + " |")
    exact_scenes = [s for s in scenes if data.get((s, "exact"))]
    if exact_scenes:
        print("\nexact / filtered time:\n")
        print(head)
        print(sep)
        for s in exact_scenes:
            cells = []
            for f in fs:
                a = next((r for r in data.get((s, "filtered"), []) if abs(math.log10(r["f"]) - math.log10(f)) < 0.01),
                         None)
                b = next((r for r in data.get((s, "exact"), []) if abs(math.log10(r["f"]) - math.log10(f)) < 0.01),
                         None)
                cells.append(f"{b['seconds'] / max(a['seconds'], 1e-9):.3g}" if a and b and a["seconds"] > 0 else "–")
            print(f"| {s} | " + " | ".join(cells) + " |")
    print("\nContact tests of the filtered kernel per predicate: tests / interval calls / exact (exact = the "
          "interval answer was uncertain and exact arithmetic ran); axis = contact tests settled by the axis "
          "test before any interval call (proofs/contact-tests.md section 3, not in the tests column); hull = "
          "feature pairs cleared by the hull test:\n")
    print(head.replace("| scene |", "| scene | predicate |"))
    print(sep.replace("|---|", "|---|---|", 1))
    for s in scenes:
        rows_s = [r for r in data.get((s, "filtered"), [])]
        for key, label in (("vf", "vertex-face"), ("ee", "edge-edge"), ("fv", "face-vertex")):
            if not any(r[key + "_calls"] + r[key + "_screened"] for r in rows_s):
                continue
            def fmt(r, key=key):
                tests = r[key + "_calls"] + r[key + "_screened"]
                return f"{tests} / {r[key + '_calls']} / {r[key + '_exact']}" if tests else "0"
            print(f"| {s} | {label} | " + " | ".join(cell(s, "filtered", f, fmt) for f in fs) + " |")
        if any(r["axis_clears"] for r in rows_s):
            print(f"| {s} | axis clears | " + " | ".join(cell(s, "filtered", f, lambda r: str(r["axis_clears"]))
                                                        for f in fs) + " |")
        if any(r["hull_clears"] for r in rows_s):
            print(f"| {s} | hull clears | " + " | ".join(cell(s, "filtered", f, lambda r: str(r["hull_clears"]))
                                                        for f in fs) + " |")
    print("\nStatic tests (start check and witness candidates), filtered kernel: simplex pairs examined and the "
          "share the interval filter could not separate:\n")
    print(head)
    print(sep)
    for s in scenes:
        print(f"| {s} | " + " | ".join(cell(
            s, "filtered", f,
            lambda r: f"{r['static_pairs']} / {100.0 * r['static_exact'] / r['static_pairs']:.2g}%"
            if r["static_pairs"] else "0") for f in fs) + " |")


def md_hard(rows):
    allrows = [r for r in rows if r["kind"] == "~all"]
    fs = sorted({r["f"] for r in allrows}, reverse=True)
    print("\nFast kernel against the truth and the certified (filtered) kernel: false safes / colliding "
          "queries, then missed witnesses and fast-only undecided (`–`: certified kernel not run):\n")
    print("| set | offset | n | colliding | " + " | ".join(f"f = {f:.0e}" for f in fs) + " |")
    print("|---|--:|--:|--:|" + "---|" * len(fs))
    keys = list(OrderedDict(((r["set"], r["offset"]), 1) for r in allrows))
    for s, o in keys:
        rs = {r["f"]: r for r in allrows if r["set"] == s and r["offset"] == o}
        any_r = next(iter(rs.values()))
        cells = []
        for f in fs:
            r = rs.get(f)
            if not r:
                cells.append("")
                continue
            text = f"FS {r['false_safe']}"
            if r["cert_run"]:
                text += f", miss {r['missed_witness']}, f.und {r['fast_undecided']}"
            else:
                text += f", fast und {r['fast_und']} (–)"
            cells.append(text)
        print(f"| {s} | {o} | {any_r['n']} | {any_r['truth_coll']} | " + " | ".join(cells) + " |")


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    out = "bench/plots"
    if "--out" in argv:
        out = argv[argv.index("--out") + 1]
        args = [a for a in args if a != out]
    if not args:
        print(__doc__, file=sys.stderr)
        return 3
    os.makedirs(out, exist_ok=True)
    speed = read_speed(args[0])
    plot_metric(speed, os.path.join(out, "time_vs_epsilon.svg"), "seconds", "seconds",
                "Time against epsilon (verify_scene, one thread, best of the repetitions)")
    plot_metric(speed, os.path.join(out, "nodes_vs_epsilon.svg"), "nodes", "nodes",
                "Subdivision nodes against epsilon")
    plot_outcome(speed, os.path.join(out, "outcome_vs_epsilon.svg"))
    plot_undecided(speed, os.path.join(out, "undecided_vs_epsilon.svg"))
    plot_filter(speed, os.path.join(out, "filter_failures.svg"))
    hard = None
    if len(args) > 1:
        hard = read_hard(args[1])
        plot_hard(hard, os.path.join(out, "fast_vs_certified.svg"))
    if "--markdown" in argv:
        md_speed(speed)
        if hard:
            md_hard(hard)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
