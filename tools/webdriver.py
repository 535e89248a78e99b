# SPDX-License-Identifier: MIT
"""A small W3C WebDriver client for Debian's chromium and chromedriver,
with Python's standard library only (tools/web_test.py, tools/web_bench.py).

    with Browser(width=1366, height=768) as b, Server("build/web") as s:
        b.go(s.url + "#scene=fire_campfire")
        b.wait_for("document.body.dataset.ready === '1'")
        print(b.run("return window.iskraPage.builtins()"))
        b.click(200, 150)                  # a real pointer event at viewport pixels
        b.keys("10\\uE007")                 # typed keys (WebDriver's codes: Enter)
        b.screenshot("page.png")

The page is served from a folder by a local HTTP server on 127.0.0.1
(Server); the browser is headless.
"""
import base64
import functools
import http.server
import json
import os
import shutil
import socket
import subprocess
import threading
import time
import urllib.error
import urllib.request


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Server:
    """A static server for one folder on 127.0.0.1, in a thread."""

    def __init__(self, folder):
        handler = functools.partial(Quiet, directory=os.path.abspath(folder))
        self.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self.url = "http://127.0.0.1:%d/" % self.httpd.server_address[1]

    def __enter__(self):
        threading.Thread(target=self.httpd.serve_forever, daemon=True).start()
        return self

    def __exit__(self, *exc):
        self.httpd.shutdown()
        self.httpd.server_close()


class Quiet(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm",
                      ".js": "text/javascript"}

    def log_message(self, *args):
        pass


class WebDriverError(Exception):
    pass


class Browser:
    """Headless chromium through chromedriver."""

    def __init__(self, width=1366, height=768, chromium=None, driver=None):
        self.chromium = chromium or shutil.which("chromium") or "/usr/bin/chromium"
        self.driver = driver or shutil.which("chromedriver") or "/usr/bin/chromedriver"
        self.size = (width, height)
        self.proc = None
        self.session = None

    def __enter__(self):
        port = free_port()
        self.base = "http://127.0.0.1:%d" % port
        self.proc = subprocess.Popen([self.driver, "--port=%d" % port], stdout=subprocess.DEVNULL,
                                     stderr=subprocess.DEVNULL)
        deadline = time.time() + 30
        while True:
            try:
                self._call("GET", "/status")
                break
            except (urllib.error.URLError, ConnectionError, WebDriverError):
                if time.time() > deadline or self.proc.poll() is not None:
                    raise WebDriverError("chromedriver did not start (%s)" % self.driver)
                time.sleep(0.1)
        args = ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=%d,%d" % self.size, "--hide-scrollbars"]
        caps = {"capabilities": {"alwaysMatch": {"browserName": "chrome", "goog:chromeOptions": {
            "binary": self.chromium, "args": args}}}}
        self.session = self._call("POST", "/session", caps)["sessionId"]
        self._call("POST", self._s("/timeouts"), {"script": 600000, "pageLoad": 60000})
        return self

    def __exit__(self, *exc):
        try:
            if self.session:
                self._call("DELETE", self._s(""))
        finally:
            if self.proc:
                self.proc.terminate()
                self.proc.wait(10)

    def _s(self, path):
        return "/session/%s%s" % (self.session, path)

    def _call(self, method, path, body=None):
        data = json.dumps(body).encode() if body is not None else None
        req = urllib.request.Request(self.base + path, data=data, method=method,
                                     headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=700) as r:
                reply = json.loads(r.read() or b"{}")
        except urllib.error.HTTPError as e:
            reply = json.loads(e.read() or b"{}")
            v = reply.get("value", {})
            raise WebDriverError("%s %s: %s" % (method, path, v.get("message", v) if isinstance(v, dict) else v))
        return reply.get("value")

    def go(self, url):
        self._call("POST", self._s("/url"), {"url": url})

    def run(self, script, *args):
        """Runs JavaScript (a function body) in the page; its return value."""
        return self._call("POST", self._s("/execute/sync"), {"script": script, "args": list(args)})

    def run_async(self, expression, *args):
        """The value of a JavaScript expression that may be a promise."""
        script = ("const done = arguments[arguments.length - 1];"
                  "Promise.resolve().then(() => %s).then((v) => done({ok: v}), (e) => done({error: String(e)}));"
                  % expression)
        r = self._call("POST", self._s("/execute/async"), {"script": script, "args": list(args)})
        if "error" in r:
            raise WebDriverError(r["error"])
        return r["ok"]

    def wait_for(self, condition, seconds=60):
        deadline = time.time() + seconds
        while not self.run("return !!(%s)" % condition):
            if time.time() > deadline:
                raise WebDriverError("timed out waiting for: " + condition)
            time.sleep(0.05)

    def pointer(self, steps):
        """Real pointer input: steps are dicts of WebDriver pointer actions."""
        self._call("POST", self._s("/actions"), {"actions": [
            {"type": "pointer", "id": "mouse", "parameters": {"pointerType": "mouse"}, "actions": steps}]})
        self._call("DELETE", self._s("/actions"))

    def click(self, x, y, count=1):
        steps = [{"type": "pointerMove", "x": int(x), "y": int(y), "origin": "viewport", "duration": 0}]
        for _ in range(count):
            steps += [{"type": "pointerDown", "button": 0}, {"type": "pointerUp", "button": 0}]
        self.pointer(steps)

    def keys(self, text):
        """Real key presses: each character (WebDriver's codes for special keys)."""
        acts = []
        for ch in text:
            acts += [{"type": "keyDown", "value": ch}, {"type": "keyUp", "value": ch}]
        self._call("POST", self._s("/actions"), {"actions": [{"type": "key", "id": "keyboard", "actions": acts}]})
        self._call("DELETE", self._s("/actions"))

    def set_viewport(self, w, h):
        """Resizes the window so that the page's viewport is w x h."""
        iw, ih = self.run("return [window.innerWidth, window.innerHeight]")
        rect = self._call("GET", self._s("/window/rect"))
        self._call("POST", self._s("/window/rect"), {"width": rect["width"] + w - iw, "height": rect["height"] + h - ih})

    def screenshot(self, path):
        with open(path, "wb") as f:
            f.write(base64.b64decode(self._call("GET", self._s("/screenshot"))))

    def log(self):
        return self.run("return (window.__iskraLog || []).slice()")
