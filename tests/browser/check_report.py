#!/usr/bin/env python3
"""Loads an msmesh HTML report in headless Chromium through chromedriver (WebDriver, plain
HTTP: standard library only) and checks what a person would see:

  - the page loads from a file:// URL with no network, and the viewer reports "ready";
  - no console errors (browser log entries of level SEVERE) and no uncaught exceptions
    (window.msmeshErrors), also after switching mesh, colour mode and wireframe;
  - the WebGL canvas shows the mesh: both the viewer's own pixel count and a real screenshot
    of the page, whose canvas area must have enough non-white pixels and colours.

Usage: check_report.py REPORT.html OUT_DIR   (chromium and chromedriver on PATH, or
CHROMIUM / CHROMEDRIVER in the environment). Writes OUT_DIR/screenshot.png. Exit 0 = pass.
"""
import base64
import json
import os
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request
import zlib

# The launch flags of a robust headless run: no sandbox (root in CI), no GPU (software WebGL
# through SwiftShader, which Chromium only enables on request), no network side-channels.
CHROME_FLAGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader", "--disable-quic",
    "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--disable-dev-shm-usage", "--window-size=1200,900", "--hide-scrollbars",
]
TIMEOUT = 60  # seconds for the page to become ready


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


class WebDriver:
    def __init__(self, port):
        self.base = "http://127.0.0.1:%d" % port
        self.session = None

    def call(self, method, path, body=None, timeout=60):
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(self.base + path, data=data, method=method,
                                     headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=timeout) as r:
                return json.loads(r.read().decode() or "{}").get("value")
        except urllib.error.HTTPError as e:
            raise RuntimeError("WebDriver %s %s: %s" % (method, path, e.read().decode()[:2000]))

    def s(self, method, path, body=None):
        return self.call(method, "/session/%s%s" % (self.session, path), body)

    def script(self, js, *args):
        return self.s("POST", "/execute/sync", {"script": js, "args": list(args)})

    def logs(self):
        try:
            return self.s("POST", "/se/log", {"type": "browser"}) or []
        except RuntimeError:
            return self.s("POST", "/log", {"type": "browser"}) or []


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def decode_png(data):
    """8-bit RGB or RGBA, non-interlaced PNG (what Chromium writes) -> (w, h, channels, rows)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    i, idat, w = 8, b"", 0
    while i < len(data):
        n, = struct.unpack(">I", data[i:i + 4])
        kind, body = data[i + 4:i + 8], data[i + 8:i + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and ctype in (2, 6) and interlace == 0, "unsupported PNG layout"
            ch = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        i += 12 + n
    raw = zlib.decompress(idat)
    stride = w * ch
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - ch] if x >= ch else 0
            b = prev[x]
            c = prev[x - ch] if x >= ch else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, ch, rows


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    report, out_dir = os.path.abspath(sys.argv[1]), sys.argv[2]
    chromium = shutil.which(os.environ.get("CHROMIUM", "chromium")) or shutil.which("chromium-browser")
    driver = shutil.which(os.environ.get("CHROMEDRIVER", "chromedriver"))
    port = free_port()
    profile = tempfile.mkdtemp(prefix="msmesh-chromium-")
    log = open(os.path.join(out_dir, "chromedriver.log"), "w")
    proc = subprocess.Popen([driver, "--port=%d" % port], stdout=log, stderr=subprocess.STDOUT)
    wd = WebDriver(port)
    try:
        for _ in range(100):
            try:
                if wd.call("GET", "/status", timeout=2).get("ready"):
                    break
            except (OSError, RuntimeError):
                pass
            time.sleep(0.1)
        else:
            fail("chromedriver did not start (see chromedriver.log)")
        caps = {"capabilities": {"alwaysMatch": {
            "browserName": "chrome",
            "goog:chromeOptions": {"binary": chromium, "args": CHROME_FLAGS + ["--user-data-dir=" + profile]},
            "goog:loggingPrefs": {"browser": "ALL"},
        }}}
        created = wd.call("POST", "/session", caps, timeout=90)
        wd.session = created["sessionId"]
        wd.s("POST", "/url", {"url": "file://" + report})

        deadline = time.time() + TIMEOUT
        status = None
        while time.time() < deadline:
            status = wd.script("return document.body && document.body.dataset.viewer || null;")
            if status in ("ready", "error", "no-webgl"):
                break
            time.sleep(0.2)
        if status != "ready":
            fail("viewer status is %r, not 'ready' (errors: %s)" % (status, wd.script("return window.msmeshErrors;")))

        # Use it as a person would: every mesh, every colour mode, wireframe on.
        info = wd.script("""
            const v = window.msmeshViewer, out = {meshes: v.meshes.map(m => m.name), modes: v.modes, seen: []};
            for (let i = 0; i < v.meshes.length; ++i) {
              document.querySelectorAll('[data-mesh]')[i].click();
              for (const m of v.modes) {
                const sel = document.getElementById('msmesh-mode');
                sel.value = m; sel.dispatchEvent(new Event('change'));
                out.seen.push([v.meshes[i].name, m, v.coveredPixels().covered]);
              }
            }
            document.getElementById('msmesh-wire').click();
            // Back to the first view of the page for the screenshot.
            document.querySelectorAll('[data-mesh]')[v.data.initial_mesh].click();
            const sel = document.getElementById('msmesh-mode');
            sel.value = v.data.initial_color; sel.dispatchEvent(new Event('change'));
            document.getElementById('msmesh-wire').click();
            const r = v.renderer.domElement.getBoundingClientRect();
            out.canvas = [r.left, r.top, r.width, r.height, window.devicePixelRatio || 1];
            out.covered = v.coveredPixels();
            out.tables = document.querySelectorAll('table').length;
            out.plots = document.querySelectorAll('svg.plot').length;
            return out;""")
        print("meshes %s, colour modes %s, %d tables, %d plots" %
              (info["meshes"], info["modes"], info["tables"], info["plots"]))
        for name, mode, covered in info["seen"]:
            if covered < 1000:
                fail("mesh %s in mode %s covers only %d canvas pixels" % (name, mode, covered))
        cov = info["covered"]
        if cov["covered"] < 0.02 * cov["total"]:
            fail("the canvas is nearly empty: %d of %d pixels not background" % (cov["covered"], cov["total"]))

        errors = wd.script("return window.msmeshErrors;") or []
        severe = [e for e in wd.logs() if e.get("level") == "SEVERE"]
        if errors or severe:
            fail("page errors: %s; console: %s" % (errors, [e.get("message") for e in severe]))

        shot = base64.b64decode(wd.s("GET", "/screenshot"))
        path = os.path.join(out_dir, "screenshot.png")
        with open(path, "wb") as f:
            f.write(shot)
        w, h, ch, rows = decode_png(shot)
        left, top, cw, chh, dpr = info["canvas"]
        x0, y0 = max(0, int(left * dpr)), max(0, int(top * dpr))
        x1, y1 = min(w, int((left + cw) * dpr)), min(h, int((top + chh) * dpr))
        if x1 - x0 < 50 or y1 - y0 < 50:
            fail("the canvas is not on the screenshot (%s in %dx%d)" % (info["canvas"], w, h))
        colors, non_white, total = set(), 0, 0
        for y in range(y0, y1, 2):
            row = rows[y]
            for x in range(x0, x1, 2):
                px = tuple(row[x * ch:x * ch + 3])
                total += 1
                if min(px) < 245:
                    non_white += 1
                    colors.add(px)
        print("screenshot %s: canvas %dx%d, %.1f%% non-white, %d colours" %
              (path, x1 - x0, y1 - y0, 100.0 * non_white / total, len(colors)))
        if non_white < 0.03 * total or len(colors) < 20:
            fail("the screenshot's canvas looks empty or uniform")
        print("PASS: report viewer renders without errors")
        return 0
    finally:
        try:
            if wd.session:
                wd.call("DELETE", "/session/" + wd.session, timeout=20)
        except Exception:
            pass
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
        log.close()
        shutil.rmtree(profile, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
