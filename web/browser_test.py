#!/usr/bin/env python3
"""The page's tests in a real browser: Debian's headless Chromium against build/web/page.

Each test serves the page over HTTP on 127.0.0.1 (a free port; /fixtures/ serves the test's
work folder), opens it with a ?test=... query (web/page/fosssim-page.js, runTest), lets
Chromium run it and reads the result the page writes into <pre id="test-result"> from the DOM
Chromium dumps (--dump-dom), or takes a screenshot (--screenshot). The offline test drives
Chromium through its DevTools protocol instead (devtools_pipe.py), in real time, since a service
worker never registers under virtual time. Every browser run is bounded by `timeout -k`.

Chromium runs with --no-sandbox: as root (CI, containers) it refuses to start otherwise, since
its sandbox relies on unprivileged user namespaces. Here that is acceptable: it loads only our
own static page from a server this script started on the loopback interface, with no other
site or network access, in a throwaway profile.

  browser_test.py digests  --page DIR --browser chromium --manifest golden.tsv SCENE...
  browser_test.py error    --page DIR --browser chromium
  browser_test.py grade    --page DIR --browser chromium --native FOSSSim --work DIR SCENE
  browser_test.py picture  --page DIR --browser chromium --native FOSSSim --work DIR SCENE STEPS
  browser_test.py drag     --page DIR --browser chromium
  browser_test.py references --page DIR --browser chromium --native FOSSSim --work DIR
                           --user SCENE,FILE... SCENE...
  browser_test.py offline  --page DIR --browser chromium --manifest golden.tsv SCENE
  browser_test.py timing   --page DIR --browser chromium [--native FOSSSim] SCENE_FILE
      (a measurement, not a test: the page's load time and the time per step of SCENE_FILE in
       the browser, and with --native the native program's time per step on the same scene)

Exit 0 on success, 1 on failure; a test that needs a native FOSSSim prints "skipped" and
exits 0 when there is none (ctest's SKIP_REGULAR_EXPRESSION).
"""

import argparse
import functools
import hashlib
import html
import http.server
import json
import math
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.parse
import xml.etree.ElementTree as ElementTree
import zlib

from devtools_pipe import Browser, DevToolsError

BROWSER_SECONDS = 300  # the longest browser run: the digests of a set of scenes


class Handler(http.server.SimpleHTTPRequestHandler):
    """The page's folder, and /fixtures/NAME from the test's work folder."""

    fixtures = None
    no_store = False

    def end_headers(self):
        if self.no_store:  # the offline test: nothing kept in Chromium's HTTP cache
            self.send_header("Cache-Control", "no-store")
        super().end_headers()

    def translate_path(self, path):
        route = urllib.parse.urlsplit(path).path
        if route.startswith("/fixtures/") and self.fixtures:
            return os.path.join(self.fixtures, os.path.basename(route))
        return super().translate_path(path)

    def do_POST(self):
        """The timing page posts its figures here (virtual time would stop its clock)."""
        body = self.rfile.read(int(self.headers["Content-Length"])).decode()
        self.send_response(204)
        self.end_headers()
        self.server.posted = body
        self.server.arrived.set()

    def log_message(self, *args):
        pass


class Server:
    def __init__(self, page, fixtures=None, no_store=False):
        handler = type("TestHandler", (Handler,), {"fixtures": fixtures, "no_store": no_store})
        self.httpd = http.server.ThreadingHTTPServer(
            ("127.0.0.1", 0), functools.partial(handler, directory=page))
        self.httpd.arrived = threading.Event()
        self.httpd.posted = None
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)

    def __enter__(self):
        self.thread.start()
        return f"http://127.0.0.1:{self.httpd.server_address[1]}/"

    def __exit__(self, *args):
        self.stop()

    def stop(self):
        """Stops serving and closes the listening socket: its port refuses connections."""
        if self.thread.is_alive():
            self.httpd.shutdown()
            self.thread.join()
        self.httpd.server_close()


def run_browser(browser, url, extra, seconds=BROWSER_SECONDS, real_time=False):
    """Chromium's standard output for `url` (the DOM with --dump-dom). With real_time, the
    page's clock is the wall clock and Chromium stops after `seconds` - 20 s instead of when
    virtual time runs out (virtual time stands still while a script runs)."""
    with tempfile.TemporaryDirectory(prefix="fosssim-chromium-") as profile:
        command = ["timeout", "-k", "10", str(seconds), browser, "--headless", "--no-sandbox",
                   "--disable-gpu", "--hide-scrollbars", "--no-first-run",
                   f"--user-data-dir={profile}",
                   # Chromium dumps the DOM or takes the screenshot once this much virtual time
                   # has passed with nothing left to load: the page's work runs before that.
                   f"--timeout={1000 * (seconds - 20)}" if real_time
                   else "--virtual-time-budget=600000", *extra, url]
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0:
            raise SystemExit(f"FAILED: {' '.join(command)} exited {done.returncode}:\n"
                             f"{done.stderr[-2000:]}")
        return done.stdout


def page_result(browser, url, **options):
    """The text the page wrote into #test-result, or a failure when it never finished."""
    dom = run_browser(browser, url, ["--dump-dom"], **options)
    found = re.search(r'<pre id="test-result"( data-done="1")?>(.*?)</pre>', dom, re.S)
    if not found:
        raise SystemExit(f"FAILED: no #test-result in the page's DOM:\n{dom[:2000]}")
    if not found.group(1):
        raise SystemExit("FAILED: the page did not finish the test (no data-done)")
    return html.unescape(found.group(2))


def fail(message):
    print(f"FAILED: {message}")
    sys.exit(1)


def native_or_skip(native):
    if not native or not os.path.exists(native):
        print(f"skipped: no native FOSSSim at {native} to compare with")
        sys.exit(0)


def read_manifest(path):
    """scene -> (trajectory size, SHA-256) of the regression manifest (oracle/manifest)."""
    manifest = {}
    with open(path) as lines:
        for line in lines:
            fields = line.rstrip("\n").split("\t")
            if len(fields) >= 5:
                manifest[fields[0]] = (fields[3], fields[4])
    return manifest


def test_digests(args, browser):
    """The trajectory digests computed in the page equal the native manifest's."""
    manifest = read_manifest(args.manifest)
    with Server(args.page) as base:
        text = page_result(browser, f"{base}index.html?test=digests&scenes={','.join(args.items)}")
    rows = {row.split("\t")[0]: row.split("\t")[1:] for row in text.splitlines() if row}
    bad = 0
    for scene in args.items:
        expected = manifest.get(scene)
        got = rows.get(scene)
        if expected is None:
            fail(f"{scene}: no entry in {args.manifest}")
        if got is None or tuple(got) != expected:
            print(f"{scene}: the page gave {got}, the manifest has {list(expected)}")
            bad += 1
        else:
            print(f"{scene}: same bytes in the browser ({got[0]} bytes, sha256 {got[1]})")
    if bad:
        fail(f"{bad} of {len(args.items)} scenes differ from the native manifest")


BROKEN_SCENE = ('<scene>\n<duration time="1"/>\n'
                '<particle m="1" px="0" py="0" vx="0" vy="0" fixde="0"/>\n</scene>\n')


def test_error(args, browser):
    """A scene with errors shows each with file, line and message, as the command line."""
    query = urllib.parse.urlencode({"test": "error", "scene": BROKEN_SCENE})
    with Server(args.page) as base:
        text = page_result(browser, f"{base}index.html?{query}")
    print(text)
    for expected in [
            "scene.xml:1: error: <scene>: the required element <integrator> is missing",
            'scene.xml:3: error: <particle> 0: attribute "fixed" is missing (the element has '
            '"fixde", which is not read: a misspelling?)']:
        if expected not in text.splitlines():
            fail(f"the page does not show the line {expected!r}")


def run_native(native, arguments):
    return subprocess.run(["timeout", "-k", "10", "600", native, *arguments],
                          capture_output=True, text=True)


def test_grade(args, browser):
    """Grading an uploaded trajectory in the page gives the native -i report and verdict: the
    native run's own trajectory (passes) and one with a byte of its last frame changed."""
    native_or_skip(args.native)
    scene = args.items[0]
    source = os.path.join(args.source, scene)
    os.makedirs(args.work, exist_ok=True)
    good = os.path.join(args.work, "good.bin")
    bad = os.path.join(args.work, "bad.bin")
    made = run_native(args.native, ["-s", source, "-d", "0", "-q", "-o", good])
    if made.returncode != 0:
        fail(f"the native run failed: {made.stderr}")
    data = bytearray(open(good, "rb").read())
    data[-3] ^= 0x40  # a mantissa byte of the last double: a change of about 1e-5 relative
    with open(bad, "wb") as out:
        out.write(data)
    with Server(args.page, fixtures=args.work) as base:
        for upload in (good, bad):
            native = run_native(args.native, ["-s", source, "-d", "0", "-q", "-i", upload])
            passed = native.returncode == 0
            expected = (native.stdout + native.stderr +
                        ("verdict: passed" if passed else "verdict: failed"))
            query = urllib.parse.urlencode(
                {"test": "grade", "scene": scene, "upload": "fixtures/" + os.path.basename(upload)})
            text = page_result(browser, f"{base}index.html?{query}")
            if text != expected:
                fail(f"{os.path.basename(upload)}: the page's report\n{text}\n"
                     f"differs from the native -i output\n{expected}")
            print(f"{os.path.basename(upload)}: the native report and verdict "
                  f"({'passed' if passed else 'failed'}, exit {native.returncode})")
    if not expected.endswith("verdict: failed"):
        fail("the changed trajectory passed: the test checks nothing")


def read_png(path):
    """(width, height, rows of (r, g, b)) of an 8-bit RGB or RGBA PNG without interlacing."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail(f"{path}: not a PNG")
    at, chunks, header = 8, [], None
    while at < len(data):
        length = int.from_bytes(data[at:at + 4], "big")
        kind = data[at + 4:at + 8]
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = body
        elif kind == b"IDAT":
            chunks.append(body)
        at += 12 + length
    width, height = int.from_bytes(header[0:4], "big"), int.from_bytes(header[4:8], "big")
    depth, color, interlace = header[8], header[9], header[12]
    if depth != 8 or color not in (2, 6) or interlace != 0:
        fail(f"{path}: depth {depth}, colour type {color}, interlace {interlace} not read here")
    channels = 3 if color == 2 else 4
    raw = zlib.decompress(b"".join(chunks))
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def foreground(rows, top):
    """The pixels (x, y), y >= top, that differ from the background (the bottom-right pixel)."""
    background = rows[-1][-1]
    return {(x, y) for y in range(top, len(rows)) for x, pixel in enumerate(rows[y])
            if sum(abs(p - q) for p, q in zip(pixel, background)) > 60}


def test_picture(args, browser):
    """A screenshot of the page's canvas after K steps is not blank and has its drawing where
    the native picture of the same state (FOSSSim -g 1) has it."""
    native_or_skip(args.native)
    scene, steps = args.items[0], int(args.items[1])
    source = os.path.join(args.source, scene)
    dt = float(ElementTree.parse(source).getroot().find("integrator").get("dt"))
    os.makedirs(args.work, exist_ok=True)
    folder = os.path.join(args.work, "native")
    made = run_native(args.native, ["-s", source, "-d", "0", "-q", "-g", "1", "--png-dir", folder,
                                    "--size", "640x480", "--duration", repr(steps * dt)])
    if made.returncode != 0:
        fail(f"the native pictures failed: {made.stderr}")
    native_png = os.path.join(folder, f"frame_{steps:05d}.png")
    page_png = os.path.join(args.work, "page.png")
    if os.path.exists(page_png):
        os.remove(page_png)
    query = urllib.parse.urlencode({"test": "picture", "scene": scene, "steps": steps})
    with Server(args.page) as base:
        run_browser(browser, f"{base}index.html?{query}",
                    [f"--screenshot={page_png}", "--window-size=640,480"])
    _, _, page_rows = read_png(page_png)
    _, _, native_rows = read_png(native_png)
    # The native picture writes the time at the top-left corner; the page shows it beside the
    # canvas. Rows above 40 are left out of the comparison.
    page, native = foreground(page_rows, 40), foreground(native_rows, 40)
    if len(page) < 50:
        fail(f"the page's picture is blank ({len(page)} pixels of drawing)")
    # Chromium and Cairo smooth edges differently, so a pixel of one picture's drawing counts
    # as placed when the other picture has drawing within one pixel of it.
    def near(pixels, other):
        return sum(any((x + i, y + j) in other for i in (-1, 0, 1) for j in (-1, 0, 1))
                   for x, y in pixels) / len(pixels)
    page_placed, native_placed = near(page, native), near(native, page)
    print(f"{len(page)} pixels of drawing in the page, {len(native)} in the native picture; "
          f"{100 * page_placed:.1f} % of the page's within a pixel of the native drawing, "
          f"{100 * native_placed:.1f} % of the native within a pixel of the page's")
    if min(page_placed, native_placed) < 0.98:
        fail("the page does not draw the particles where the native picture has them")


def test_drag(args, browser):
    """Dragging with the mouse: synthetic mouse events on the canvas grab the free particle of a
    scene without forces and pull it; its positions must be the drag spring's steps worked by
    hand. The spring (viewer/particle_grab.h) pulls toward T = x0 + d, d the cursor's shift in
    metres (the grab keeps the offset between cursor and particle), with k = m / h² under
    symplectic Euler. From rest: v1 = h k (T - x0) / m = d / h, x1 = x0 + h v1 = x0 + d, exactly
    the target; v2 = v1 + h k (T - x1) / m = d / h, x2 = x0 + 2d; after the button is released
    nothing pulls, v3 = v2 and x3 = x0 + 3d. The fixed particle stays put."""
    with Server(args.page) as base:
        text = page_result(browser, f"{base}index.html?test=drag")
    print(text)
    rows = dict(line.split("\t", 1) for line in text.splitlines() if "\t" in line)
    if "x3" not in rows:
        fail(f"the page did not drag: {text}")
    scale = float(rows["pixels_per_metre"])
    shift = json.loads(rows["shift"])
    d = (shift[0] / scale, -shift[1] / scale)  # canvas y grows downwards, the scene's upwards
    if not scale > 10 or math.hypot(*d) < 0.05:
        fail(f"the drag is too small to check anything: {scale} pixels per metre")
    x = [json.loads(rows[f"x{k}"]) for k in range(4)]
    tolerance = 1e-9 * math.hypot(*d)
    for k in (1, 2, 3):
        for axis in (0, 1):
            expected = x[0][axis] + k * d[axis]
            if abs(x[k][axis] - expected) > tolerance:
                fail(f"step {k}: the particle is at {x[k][:2]}, the drag spring puts it at "
                     f"{[x[0][a] + k * d[a] for a in (0, 1)]}")
        if x[k][2:] != x[0][2:]:
            fail(f"step {k}: the fixed particle moved: {x[k][2:]}")
    print(f"dragged {math.hypot(*d):.4f} m: x1 = x0 + d, x2 = x0 + 2d, released x3 = x0 + 3d, "
          f"within {tolerance:.1e} m")


def native_trajectory(native, source, work, label):
    """(size, sha256) of the trajectory `FOSSSim -s source -d 0 -o` writes."""
    out = os.path.join(work, re.sub(r"[^A-Za-z0-9_.-]", "_", label) + ".bin")
    made = run_native(native, ["-s", source, "-d", "0", "-q", "-o", out])
    if made.returncode != 0:
        fail(f"the native run of {source} failed: {made.stderr}")
    data = open(out, "rb").read()
    return str(len(data)), hashlib.sha256(data).hexdigest()


def test_references(args, browser):
    """Scenes that name other files (a tet mesh, an OBJ mesh, a JSON scene's OBJ) load in the
    page: picked from the suites, whose files the page fetches, and opened by a student together
    with their files (matched by base name). Each trajectory has the native size; the scenes
    outside the local/global solver (whose sparse Cholesky differs here: docs/web.md) have the
    native bytes. Opened without its mesh, a scene shows the loader's missing-file error."""
    native_or_skip(args.native)
    os.makedirs(args.work, exist_ok=True)
    user = args.user.split(",")
    query = urllib.parse.urlencode({"test": "references", "scenes": ",".join(args.items),
                                    "user": ",".join(user)})
    with Server(args.page) as base:
        text = page_result(browser, f"{base}index.html?{query}")
    print(text)
    rows = {row.split("\t")[0]: row.split("\t")[1:] for row in text.splitlines() if row}
    checks = [(scene, scene) for scene in args.items]
    checks.append((f"user:{os.path.basename(user[0])}", user[0]))
    for label, scene in checks:
        source = os.path.join(args.source, scene)
        size, digest = native_trajectory(args.native, source, args.work, label)
        got = rows.get(label)
        if got is None or got[0] == "ERROR":
            fail(f"{label}: the page did not run it: {got}")
        local_global = 'type="local-global"' in open(source).read() or scene.endswith(".json")
        if got[0] != size or (not local_global and got[1] != digest):
            fail(f"{label}: the page gave {got}, the native run {[size, digest]}")
        print(f"{label}: {'the native size' if local_global else 'the native bytes'} "
              f"({size} bytes)")
    alone = rows.get(f"alone:{os.path.basename(user[0])}", [""])[0]
    mesh = os.path.basename(user[1])
    if mesh not in alone or "No such file" not in alone:
        fail(f"opened alone, the scene does not say that {mesh} is missing: {alone!r}")


OFFLINE_SECONDS = 240  # the offline test's Chromium, from its start to its close
WAIT_SECONDS = 90      # the longest wait for one thing in that run (a page's test, the worker)
CACHE_SECONDS = 20     # the longest wait for the worker to store a scene it fetched

# JavaScript polled in the page (devtools_pipe.Browser.wait_for). A document of this test's
# own navigation has no window.fosssimOld, which marks the document it replaces.
TEST_RESULT_JS = """(() => {
  const out = document.getElementById("test-result");
  return !window.fosssimOld && out && out.dataset.done === "1" ? out.textContent : null;
})()"""
CONTROLLED_JS = ("navigator.serviceWorker.controller && "
                 "navigator.serviceWorker.controller.state === 'activated'")
CACHED_JS = """caches.open("fosssim-page").then((cache) => cache.keys())
  .then((requests) => requests.map((r) => new URL(r.url).pathname))"""
PROBE_JS = """fetch("scenes/not-a-scene-offline-probe.xml")
  .then((response) => `answered: HTTP ${response.status}`, (e) => `failed: ${e.message}`)"""


def offline_run(chromium, page, url, expected, what):
    """Opens the page's digest test at `url` and checks the scene's (size, SHA-256)."""
    chromium.evaluate(page, "window.fosssimOld = true")
    try:
        chromium.navigate(page, url)
    except DevToolsError as problem:
        fail(f"{what}: the page does not load: {problem}")
    text = chromium.wait_for(page, TEST_RESULT_JS, WAIT_SECONDS,
                             f"{what}: the page's result (#test-result)")
    scene, *got = text.split("\t")
    if tuple(got) != expected:
        fail(f"{what}: the page gave {text!r}, the manifest has {list(expected)}")
    print(f"{what}: {scene} runs to the manifest's bytes ({got[0]} bytes, sha256 {got[1]})")


def offline_checks(chromium, page, url, expected, what):
    """With the server gone: the page runs the scene, under its worker's control, and a file it
    never fetched does not load (nothing but the worker's cache answers)."""
    offline_run(chromium, page, url, expected, what)
    if not chromium.evaluate(page, CONTROLLED_JS):
        fail(f"{what}: the page loaded but no service worker controls it")
    probe = chromium.evaluate(page, PROBE_JS)
    if not probe.startswith("failed"):
        fail(f"{what}: a file the page never fetched still loads ({probe}): "
             "something else than the service worker's cache answers")
    print(f"{what}: a file never fetched does not load ({probe})")


def bypassed_worker_fails(chromium, page, url):
    """The control: with the service worker bypassed the page must not load, so nothing else
    served it (Chromium's HTTP cache, a server still answering). The bypass takes effect only
    where the Network domain is enabled."""
    chromium.send("Network.enable", session=page)
    chromium.send("Network.setBypassServiceWorker", {"bypass": True}, session=page)
    try:
        chromium.evaluate(page, "window.fosssimOld = true")
        chromium.navigate(page, url)
        fail("server stopped, the page loads with its service worker bypassed: "
             "the test does not show that the worker served it")
    except DevToolsError as refused:
        print(f"server stopped, the service worker bypassed: the page does not load ({refused})")
    chromium.send("Network.setBypassServiceWorker", {"bypass": False}, session=page)


def emulate_offline(chromium, page):
    """The network emulated offline in the page and in its service worker, whose own fetch()
    the page's emulation does not reach."""
    workers = [chromium.attach(worker) for worker in chromium.targets("service_worker")]
    if not workers:
        fail("no service worker target to take offline")
    for session in workers:
        chromium.send("Network.enable", session=session)
    for session in [page] + workers:
        chromium.send("Network.emulateNetworkConditions",
                      {"offline": True, "latency": 0, "downloadThroughput": -1,
                       "uploadThroughput": -1}, session=session)


def test_offline(args, browser):
    """Offline use: once its service worker has taken control, the page runs a scene with the
    server stopped, and with the network off. Chromium is driven in real time through its
    DevTools protocol (web/devtools_pipe.py): under --virtual-time-budget, which the other tests
    use, navigator.serviceWorker.register() never settles.

    The page is opened (it registers the worker, which caches the page, fosssim.js and the
    scene index as it installs) until the worker is activated and controls it; then the page
    computes a manifest scene's trajectory digest online, which fetches the scene through the
    worker (it caches it). The server is stopped (its port refuses connections) and the same
    URL opened again: it must be controlled by the worker, run the scene to the manifest's
    bytes, and fail to fetch a file it never fetched before. The control: the same URL opened
    with the worker bypassed must fail to load, so nothing else served it (Chromium's HTTP
    cache, which the server's no-store keeps empty; it served the page without it). Then the
    page and the worker are emulated offline too, and the page must run the scene again."""
    scene = args.items[0]
    expected = read_manifest(args.manifest).get(scene)
    if expected is None:
        fail(f"{scene}: no entry in {args.manifest}")
    # Stopped from outside (`timeout`, ctest), the test still closes Chromium, which runs in a
    # process group of its own, and removes its folder: SIGTERM unwinds like a failure.
    signal.signal(signal.SIGTERM, lambda *_: fail("terminated (SIGTERM)"))
    server = Server(args.page, no_store=True)
    try:
        with server as base, Browser(browser, OFFLINE_SECONDS) as chromium:
            url = f"{base}index.html?test=digests&scenes={scene}"
            _, page = chromium.new_page()
            chromium.navigate(page, f"{base}index.html")
            chromium.wait_for(page, "window.fosssimReady === true", WAIT_SECONDS,
                              "the page loading FOSSSim (window.fosssimReady)")
            chromium.wait_for(page, CONTROLLED_JS, WAIT_SECONDS,
                              "an activated service worker controlling the page "
                              "(navigator.serviceWorker.controller)")
            print("online: the service worker is activated and controls the page")
            offline_run(chromium, page, url, expected, "online")
            # The worker stores what it fetched after answering: wait for the scene to be
            # there. Not an assertion (the offline runs below are): when it never comes, they
            # fail on what is missing.
            try:
                chromium.wait_for(
                    page, f"({CACHED_JS}).then((paths) => paths.includes('/scenes/{scene}'))",
                    CACHE_SECONDS, f"scenes/{scene} in the service worker's cache")
            except DevToolsError as problem:
                print(f"online: {problem}")
            cached = chromium.evaluate(page, CACHED_JS)
            print(f"online: the service worker's cache holds {', '.join(sorted(cached))}")

            server.stop()
            port = urllib.parse.urlsplit(base).port
            try:
                socket.create_connection(("127.0.0.1", port), timeout=5).close()
                fail(f"the server still answers on port {port} after it was stopped")
            except ConnectionRefusedError:
                pass
            offline_checks(chromium, page, url, expected,
                           f"server stopped (port {port} refuses connections)")
            bypassed_worker_fails(chromium, page, url)
            emulate_offline(chromium, page)
            offline_checks(chromium, page, url, expected, "server stopped and network offline")
    except DevToolsError as problem:
        fail(str(problem))


def test_timing(args, browser):
    """Prints the page's load time and a scene's time per step, in the browser and natively."""
    scene = os.path.abspath(args.items[0])
    query = urllib.parse.urlencode({"test": "timing", "url": "fixtures/" + os.path.basename(scene)})
    server = Server(args.page, fixtures=os.path.dirname(scene))
    with server as base, tempfile.TemporaryDirectory(prefix="fosssim-chromium-") as profile:
        # Real time: no --virtual-time-budget (its clock stands still while a script runs);
        # the page posts its figures and Chromium is stopped then.
        browser_run = subprocess.Popen(
            ["timeout", "-k", "10", "300", browser, "--headless", "--no-sandbox", "--disable-gpu",
             "--no-first-run", f"--user-data-dir={profile}", f"{base}index.html?{query}"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        arrived = server.httpd.arrived.wait(280)
        browser_run.terminate()
        browser_run.wait()
    if not arrived:
        fail("the timing page posted nothing")
    text = server.httpd.posted
    figures = dict(line.split("\t") for line in text.splitlines())
    print(f"page load (navigation start to FOSSSim ready): {figures['load_ms']} ms")
    print(f"browser: {figures['steps']} steps, {figures['ms_per_step']} ms per step")
    if args.native and os.path.exists(args.native):
        start = time.perf_counter()
        done = run_native(args.native, ["-s", scene, "-d", "0", "-q"])
        elapsed = time.perf_counter() - start
        if done.returncode != 0:
            fail(f"the native run failed: {done.stderr}")
        native = 1000 * elapsed / int(figures["steps"])
        print(f"native: {native:.3f} ms per step (the whole run, loading included); "
              f"browser / native = {float(figures['ms_per_step']) / native:.2f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("test", choices=["digests", "error", "grade", "picture", "drag",
                                         "references", "offline", "timing"])
    parser.add_argument("items", nargs="*")
    parser.add_argument("--page", required=True)
    parser.add_argument("--browser", required=True)
    parser.add_argument("--source", default=".")
    parser.add_argument("--manifest")
    parser.add_argument("--native")
    parser.add_argument("--work")
    parser.add_argument("--user", help="references: a scene and the files it names, comma-separated")
    args = parser.parse_intermixed_args()
    if shutil.which(args.browser) is None:
        fail(f"no browser {args.browser}; tools/install-deps.sh installs Debian's chromium")
    {"digests": test_digests, "error": test_error, "grade": test_grade,
     "picture": test_picture, "drag": test_drag, "references": test_references,
     "offline": test_offline, "timing": test_timing}[args.test](args, args.browser)
    if args.test != "timing":
        print("passed")


if __name__ == "__main__":
    main()
