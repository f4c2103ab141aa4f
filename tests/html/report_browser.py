#!/usr/bin/env python3
"""The visual report (tmcert verify --report) in headless Chromium.

For each scene: runs `tmcert verify SCENE --json --report page.html` (one
run, so the page and the JSON describe the same result), opens the page
from file:// in Debian's chromium, driven through the DevTools protocol
over --remote-debugging-pipe (Python's standard library only), and checks

  1. no console error, exception or WebGL error while loading and drawing,
     the page's own error log is empty, and it requests nothing but
     itself and data: URLs;
  2. the canvas is not blank: a screenshot of it (PNG, decoded here with
     zlib) has many colours and many pixels that are not background;
  3. the timeline in the DOM (spans with exact data-t0/data-t1, the
     witness mark) matches the JSON result exactly: the spans tile the
     check's interval and are its partition (SCENE_FORMAT.md, "Every
     interval claim holds"): the undecided intervals are the result's,
     safe spans exactly the rest before the witness, and from the witness
     on not-searched (an algebraic witness time: a narrow witness span
     holding its root, checked with exact signs of its polynomial);
     `not_searched` is [witness, end]; and the witness's two features
     resolve to geometry that is highlighted;
     at the witness time the page shows the witness; and the result
     document on the page is --json's.

Usage: report_browser.py TMCERT REPO_ROOT [--screenshot OUT.png [--view OPTIONS]]
  --screenshot writes the gripper collision at its witness time (the
  README's docs/images/gripper-collision.png); --view adds page options
  (e.g. "view=-60,26&zoom=1.5", src/html/report_app.js) to its address.
Also checks that an unwritable --report path is exit 3 naming --report.
"""
import base64
import json
import os
import queue
import shutil
import struct
import subprocess
import sys
import tempfile
import threading
import time
import zlib
from fractions import Fraction

TIMEOUT = 25.0  # seconds for one page to load and draw


def fail(message):
    raise AssertionError(message)


# ---------------------------------------------------------------- DevTools over a pipe


class Browser:
    """Chromium with --remote-debugging-pipe: requests on fd 3, replies on fd 4,
    each message JSON ending in a NUL byte."""

    def __init__(self, chromium, profile, log):
        to_browser_r, self._to_browser = os.pipe()
        self._from_browser, from_browser_w = os.pipe()

        def child_fds():
            a, b = os.dup(to_browser_r), os.dup(from_browser_w)
            os.dup2(a, 3)
            os.dup2(b, 4)

        args = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--disable-default-apps", "--disable-extensions", "--mute-audio", "--hide-scrollbars",
                "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--window-size=1200,760",
                "--user-data-dir=" + profile, "--remote-debugging-pipe", "about:blank"]
        self.proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=log, stderr=log,
                                     preexec_fn=child_fds, close_fds=False)
        os.close(to_browser_r)
        os.close(from_browser_w)
        self._next = 0
        self._replies = {}
        self._events = queue.Queue()
        self._cond = threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        buf = b""
        while True:
            chunk = os.read(self._from_browser, 1 << 16)
            if not chunk:
                with self._cond:
                    self._replies[None] = True
                    self._cond.notify_all()
                return
            buf += chunk
            while b"\0" in buf:
                raw, buf = buf.split(b"\0", 1)
                msg = json.loads(raw)
                if "id" in msg:
                    with self._cond:
                        self._replies[msg["id"]] = msg
                        self._cond.notify_all()
                else:
                    self._events.put(msg)

    def send(self, method, params=None, session=None, timeout=TIMEOUT):
        self._next += 1
        ident = self._next
        msg = {"id": ident, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        os.write(self._to_browser, json.dumps(msg).encode() + b"\0")
        deadline = time.monotonic() + timeout
        with self._cond:
            while ident not in self._replies:
                if None in self._replies:
                    fail("chromium exited while waiting for " + method)
                left = deadline - time.monotonic()
                if left <= 0:
                    fail("no reply from chromium to " + method)
                self._cond.wait(left)
            reply = self._replies.pop(ident)
        if "error" in reply:
            fail(f"{method}: {reply['error']}")
        return reply["result"]

    def events(self):
        out = []
        while True:
            try:
                out.append(self._events.get_nowait())
            except queue.Empty:
                return out

    def close(self):
        try:
            self.send("Browser.close", timeout=5)
        except AssertionError:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        os.close(self._to_browser)


def problems_in(events, page):
    """Console errors, exceptions, WebGL errors and requests for anything but
    the page itself and data: URLs, among DevTools events."""
    found = []
    for e in events:
        method, p = e.get("method"), e.get("params", {})
        if method == "Network.requestWillBeSent":
            url = p["request"]["url"]
            if not url.startswith("data:") and url.split("#")[0] != "file://" + page:
                found.append("the page fetched " + url)
        elif method == "Runtime.exceptionThrown":
            d = p["exceptionDetails"]
            found.append("exception: " + d.get("exception", {}).get("description", d.get("text", "")))
        elif method == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            found.append("console.error: " + " ".join(str(a.get("value", a.get("description", ""))) for a in p["args"]))
        elif method == "Runtime.consoleAPICalled" or method == "Log.entryAdded":
            entry = p.get("entry", p)
            text = entry.get("text") or " ".join(str(a.get("value", "")) for a in p.get("args", []))
            level = entry.get("level", entry.get("type"))
            # WebGL API errors ("WebGL: INVALID_OPERATION: ...", GL_INVALID_*) come as warnings;
            # the driver's performance notes (a screenshot's ReadPixels stalls) are not errors.
            performance_note = "GL Driver Message" in text and "Performance" in text
            if level == "error" or (not performance_note and ("WebGL" in text or "GL_INVALID" in text
                                                             or "GL ERROR" in text)):
                found.append(f"{level}: {text}")
    return found


# ---------------------------------------------------------------- PNG


def png_pixels(data):
    """(width, height, rows of RGB tuples) of an 8-bit RGB or RGBA PNG."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail("not a PNG")
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                fail(f"unexpected PNG format: depth {depth}, colour type {colour}, interlace {interlace}")
            channels = 4 if colour == 6 else 3
        elif kind == b"IDAT":
            idat += body
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        prev = line
    return width, height, rows


def check_not_blank(png, what):
    width, height, rows = png_pixels(png)
    counts = {}
    for row in rows:
        for px in row:
            counts[px] = counts.get(px, 0) + 1
    background, bg_count = max(counts.items(), key=lambda kv: kv[1])
    drawn = width * height - bg_count
    if len(counts) < 8 or drawn < 0.003 * width * height:
        fail(f"{what}: the canvas looks blank: {len(counts)} colours, {drawn} of {width * height} pixels "
             f"differ from the background {background}")
    return len(counts), drawn / (width * height)


# ---------------------------------------------------------------- exact times


def frac(text):
    return Fraction(text)


def poly_sign(coefficients, x):
    v = sum(Fraction(int(c)) * x ** k for k, c in enumerate(coefficients))
    return (v > 0) - (v < 0)


def check_timeline(result, page, name):
    """The page's timeline (read from the DOM) against the JSON result."""
    checks = result["checks"]
    if len(page) != len(checks):
        fail(f"{name}: {len(page)} timelines on the page, {len(checks)} checks in the result")
    for i, (c, p) in enumerate(zip(checks, page)):
        where = f"{name}, check {i} ({c['bodies'][0]} x {c['bodies'][1]})"
        if [p["a"], p["b"]] != c["bodies"] or p["verdict"] != c["verdict"]:
            fail(f"{where}: page shows {p['a']} x {p['b']}: {p['verdict']}")
        spans = p["spans"]
        if not spans:
            fail(f"{where}: empty timeline")
        # The spans tile the check's interval, in order.
        if frac(spans[0]["t0"]) != frac(p["t0"]) or frac(spans[-1]["t1"]) != frac(p["t1"]):
            fail(f"{where}: spans cover [{spans[0]['t0']}, {spans[-1]['t1']}], not [{p['t0']}, {p['t1']}]")
        for s, n in zip(spans, spans[1:]):
            if frac(s["t1"]) != frac(n["t0"]):
                fail(f"{where}: gap or overlap between {s} and {n}")
        for s in spans:
            if not frac(s["t0"]) < frac(s["t1"]):
                fail(f"{where}: empty or reversed span {s}")
        # Undecided: exactly the result's intervals and reasons.
        # (Clipped where the claims end: at the witness, or at the narrow
        # span drawn around an algebraic witness time.)
        end = frac(p["t1"])
        if c["verdict"] == "collision":
            w_spans = [s for s in spans if s["kind"] == "witness"]
            end = frac(w_spans[0]["t0"]) if w_spans else frac(c["witness"]["t"]) if isinstance(c["witness"]["t"], str) else end
        shown = [(frac(s["t0"]), frac(s["t1"]), s["reason"]) for s in spans if s["kind"] == "undecided"]
        listed = sorted((frac(u["t"][0]), min(frac(u["t"][1]), end), u["reason"]) for u in c["undecided"]
                        if frac(u["t"][0]) < end)
        if shown != listed:
            fail(f"{where}: undecided on the page {shown}, in the result {listed}")
        kinds = {s["kind"] for s in spans}
        if c["verdict"] != "collision":
            if kinds - {"safe", "undecided"}:
                fail(f"{where}: {c['verdict']} check shows {kinds}")
            if (c["verdict"] == "safe") != (kinds == {"safe"}):
                fail(f"{where}: verdict {c['verdict']} but spans {kinds}")
            if p["witness"] is not None:
                fail(f"{where}: a witness mark without a witness")
            continue
        # Collision: the partition ends at the witness.  Before it, safe
        # spans are exactly the gaps between the undecided intervals; from it
        # on, "not-searched" (an algebraic witness: a narrow "witness" span
        # holding its root in between); nothing else (no "colliding" span:
        # the bodies may separate again after the witness).
        if kinds - {"safe", "undecided", "witness", "not-searched"}:
            fail(f"{where}: collision check shows {kinds}")
        witness = c["witness"]["t"]
        mark = p["witness"]
        if mark is None:
            fail(f"{where}: no witness mark")
        if c["not_searched"][0] != witness or frac(c["not_searched"][1]) != frac(p["t1"]):
            fail(f"{where}: not_searched {c['not_searched']}, witness {witness}, interval ends at {p['t1']}")
        if isinstance(witness, str):
            if mark.get("t") is None or frac(mark["t"]) != frac(witness):
                fail(f"{where}: witness mark at {mark}, result {witness}")
            claims_end = frac(witness)
            if "witness" in kinds:
                fail(f"{where}: a witness span for a rational witness time")
        else:
            lo, hi = frac(witness["interval"][0]), frac(witness["interval"][1])
            if mark.get("lo") is None or frac(mark["lo"]) != lo or frac(mark["hi"]) != hi:
                fail(f"{where}: witness mark {mark}, result interval {witness['interval']}")
            poly = witness["root_of"]
            if not lo < float(mark["display"]) < hi:
                fail(f"{where}: witness drawn at {mark['display']}, outside its interval")
            ws = [s for s in spans if s["kind"] == "witness"]
            if len(ws) != 1:
                fail(f"{where}: {len(ws)} witness spans for an algebraic witness time")
            a, b = frac(ws[0]["t0"]), frac(ws[0]["t1"])
            # The root lies in [a, b]: the polynomial changes sign (or vanishes) there.
            if not (lo <= a and b <= hi) or poly_sign(poly, a) * poly_sign(poly, b) > 0:
                fail(f"{where}: witness span [{a}, {b}] does not hold the root in ({lo}, {hi})")
            claims_end = a
        shown_safe = [(frac(s["t0"]), frac(s["t1"])) for s in spans if s["kind"] == "safe"]
        want_safe, cursor = [], frac(p["t0"])
        for lo_u, hi_u, _ in listed:
            if cursor < min(lo_u, claims_end):
                want_safe.append((cursor, min(lo_u, claims_end)))
            cursor = max(cursor, hi_u)
        if cursor < claims_end:
            want_safe.append((cursor, claims_end))
        if shown_safe != want_safe:
            fail(f"{where}: safe spans {shown_safe}, but the result certifies {want_safe}")
        for s in spans:
            if s["kind"] in ("safe", "undecided") and frac(s["t1"]) > claims_end:
                fail(f"{where}: span {s} reaches past the witness {witness}")
        tail = [s for s in spans if s["kind"] == "not-searched"]
        if frac(p["t1"]) > claims_end and (not tail or spans[-1] is not tail[-1] or len(tail) != 1):
            fail(f"{where}: after the witness the interval is not drawn not-searched: {spans[-3:]}")
        # The witness's features resolve to drawn geometry.
        w = p["data_witness"]
        if w["features"] != c["witness"]["features"]:
            fail(f"{where}: page features {w['features']}, result {c['witness']['features']}")
        for h in w["highlight"]:
            if not (h.get("triangles") or h.get("lines") or h.get("points")):
                fail(f"{where}: feature '{h['name']}' is not highlighted")


READ_TIMELINE = r"""
(() => {
  const data = JSON.parse(document.getElementById('tmcert-data').textContent);
  return JSON.stringify([...document.querySelectorAll('#timelines .check')].map((el, i) => {
    const bar = el.querySelector('.bar');
    const mark = bar.querySelector('.witness-mark');
    return {
      a: el.dataset.bodyA, b: el.dataset.bodyB, verdict: el.dataset.verdict,
      t0: bar.dataset.t0, t1: bar.dataset.t1,
      spans: [...bar.querySelectorAll('.span')].map((s) => ({
        kind: s.dataset.kind, t0: s.dataset.t0, t1: s.dataset.t1, reason: s.dataset.reason || null })),
      witness: mark ? { t: mark.dataset.t || null, lo: mark.dataset.tLo || null, hi: mark.dataset.tHi || null,
                        display: mark.dataset.tDisplay } : null,
      data_witness: data.checks[i].witness || null,
    };
  }));
})()
"""


def evaluate(browser, session, expression):
    r = browser.send("Runtime.evaluate", {"expression": expression, "returnByValue": True, "awaitPromise": True},
                     session)
    if "exceptionDetails" in r:
        fail("evaluating in the page: " + json.dumps(r["exceptionDetails"])[:500])
    return r["result"].get("value")


def wait_for(browser, session, expression, what):
    deadline = time.monotonic() + TIMEOUT
    while time.monotonic() < deadline:
        if evaluate(browser, session, expression):
            return
        time.sleep(0.05)
    fail("timed out waiting for " + what)


def canvas_screenshot(browser, session):
    """The canvas alone: the overlays on it are hidden while it is captured."""
    evaluate(browser, session, "document.getElementById('bodies-legend').style.visibility = 'hidden'")
    rect = json.loads(evaluate(browser, session,
        "JSON.stringify(document.getElementById('scene-canvas').getBoundingClientRect())"))
    if rect["width"] < 100 or rect["height"] < 100:
        fail(f"canvas is {rect['width']} x {rect['height']}")
    clip = {"x": rect["x"], "y": rect["y"], "width": rect["width"], "height": rect["height"], "scale": 0.5}
    png = base64.b64decode(browser.send("Page.captureScreenshot", {"format": "png", "clip": clip}, session)["data"])
    evaluate(browser, session, "document.getElementById('bodies-legend').style.visibility = ''")
    return png


def check_page(browser, tmcert, scene, options, work, name, screenshot=None, view=""):
    started = time.monotonic()
    page = os.path.join(work, name + ".html")
    run = subprocess.run([tmcert, "verify", scene, "--json", "--report", page] + options,
                         capture_output=True, text=True, timeout=120)
    result = json.loads(run.stdout)
    verified = time.monotonic()
    expected_code = {"safe": 0, "collision": 1, "undecided": 2}[result["verdict"]]
    if run.returncode != expected_code:
        fail(f"{name}: exit {run.returncode} for verdict {result['verdict']}: {run.stderr}")
    if "report written to" not in run.stderr:
        fail(f"{name}: no report message on stderr: {run.stderr}")

    target = browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
    session = browser.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
    for domain in ("Runtime", "Log", "Page", "Network"):
        browser.send(domain + ".enable", {}, session)
    # Software WebGL draws every pixel on the CPU: a small page unless a
    # screenshot for people is wanted.
    width, height = (1200, 760) if screenshot else (720, 480)
    browser.send("Emulation.setDeviceMetricsOverride",
                 {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False}, session)
    browser.events()
    browser.send("Page.navigate", {"url": "file://" + page + ("#" + view if view else "")}, session)
    wait_for(browser, session,
             "location.protocol === 'file:' && !!document.documentElement && "
             "(document.documentElement.dataset.status === 'rendered' || !!document.documentElement.dataset.errors)",
             name + " to render")
    time.sleep(0.2)  # a resize may draw again
    errors = evaluate(browser, session, "JSON.stringify(window.tmcertErrors || ['no error log'])")
    problems = problems_in(browser.events(), page) + json.loads(errors)
    if problems:
        fail(f"{name}: errors while loading:\n  " + "\n  ".join(problems))
    colours, drawn = check_not_blank(canvas_screenshot(browser, session), name)

    check_timeline(result, json.loads(evaluate(browser, session, READ_TIMELINE)), name)
    shown = json.loads(evaluate(browser, session, "document.getElementById('tmcert-result').textContent"))
    if shown != result:
        fail(f"{name}: the result document on the page differs from --json's")

    if any(c["verdict"] == "collision" for c in result["checks"]):
        evaluate(browser, session, "document.getElementById('to-witness').click()")
        wait_for(browser, session, "document.documentElement.dataset.witnessShown === '1'", name + " witness")
        wait_for(browser, session, "new Promise(r => requestAnimationFrame(() => requestAnimationFrame(() => r(true))))",
                 name + " frame")
        if screenshot:  # first: a clipped, scaled capture can leave the page scaled
            full = browser.send("Page.captureScreenshot", {"format": "png"}, session)["data"]
            with open(screenshot, "wb") as f:
                f.write(base64.b64decode(full))
        check_not_blank(canvas_screenshot(browser, session), name + " at the witness")
    problems = problems_in(browser.events(), page) + json.loads(
        evaluate(browser, session, "JSON.stringify(window.tmcertErrors)"))
    if problems:
        fail(f"{name}: errors while interacting:\n  " + "\n  ".join(problems))
    browser.send("Target.closeTarget", {"targetId": target})
    print(f"ok {name}: verdict {result['verdict']}, {colours} colours, {100 * drawn:.0f}% of the canvas drawn "
          f"(tmcert {verified - started:.1f} s, browser {time.monotonic() - verified:.1f} s)")


def check_unwritable(tmcert, scene, work):
    target = os.path.join(work, "no-such-folder", "report.html")
    run = subprocess.run([tmcert, "verify", scene, "--report", target], capture_output=True, text=True, timeout=60)
    if run.returncode != 3 or "--report" not in run.stderr or run.stdout:
        fail(f"unwritable --report: exit {run.returncode}, stdout {run.stdout!r}, stderr {run.stderr!r}")
    print("ok unwritable --report path: exit 3")


def main():
    args = sys.argv[1:]
    screenshot = None
    if "--screenshot" in args:
        k = args.index("--screenshot")
        screenshot = os.path.abspath(args[k + 1])
        del args[k:k + 2]
    view = ""
    if "--view" in args:
        k = args.index("--view")
        view = args[k + 1]
        del args[k:k + 2]
    tmcert, repo = os.path.abspath(args[0]), os.path.abspath(args[1])
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        fail("chromium is not installed (scripts/deps.sh installs it)")
    os.chdir(repo)  # scenes named as in the README (the page shows the name)
    work = tempfile.mkdtemp(prefix="tmcert-report-")
    log_path = os.path.join(work, "chromium.log")
    browser = None
    try:
        check_unwritable(tmcert, "examples/octagons-near.json", work)
        profile = os.path.join(work, "profile")
        os.mkdir(profile)
        with open(log_path, "w") as log:
            browser = Browser(chromium, profile, log)
            # Small scenes: undecided spans (the depth limit) between safe
            # ones; a clearance violated after an undecided span (safe,
            # undecided and not-searched spans, a witness of two point boxes); a
            # point entering a solid after an undecided stop (after_undecided);
            # a safe one; then the gripper collision (5,700 triangles, a
            # witness at an algebraic time).
            check_page(browser, tmcert, "tests/data/scenes/planner-clearance-safe.json",
                       ["--max-depth", "2"], work, "clearance-undecided")
            check_page(browser, tmcert, "tests/data/scenes/planner-clearance-violated.json",
                       ["--max-depth", "2"], work, "clearance-violated")
            check_page(browser, tmcert, "tests/data/scenes/solid-entered-after-undecided-rpy.json", [], work,
                       "solid-after-undecided")
            check_page(browser, tmcert, "examples/octagons-clear.json", [], work, "octagons-clear")
            check_page(browser, tmcert, "examples/gripper/gripper-collision.json", [], work,
                       "gripper-collision", screenshot, view)
    except AssertionError as e:
        print("FAIL:", e)
        if os.path.exists(log_path):
            with open(log_path) as f:
                tail = f.read()[-3000:]
            print("chromium's output (end):\n" + tail)
        return 1
    finally:
        if browser:
            browser.close()
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
