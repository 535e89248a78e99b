#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The web page in headless Chromium (make test-web):

    tools/web_test.py ISKRA WEB_DIR [--frames N] [--only NAME]

ISKRA is the native tool (build/bin/iskra), WEB_DIR the built page
(build/web).  Checks, each printed as "ok" or "FAIL" with why:
  - every built-in scene (the native tool's list, not typed here) drawn at
    frame N in the page hashes to the native `iskra render NAME --frames N`,
    and the simulator's canvas after N fixed-clock frames to `iskra play`'s;
  - real pointer and key events: a click on fig 22's canvas sets off an
    explosion; a value typed into Gravity is applied;
  - a mistake in the editor shows FILE:LINE: and the last good scene runs on;
  - a shared link, loaded fresh, shows the same scene and the same bytes;
  - the downloads (scene file, PNG, GIF of the next frames) are made;
  - the window fits a 1280x720 viewport, and is scaled by whole numbers;
  - the page (its three files) weighs at most 2 MB.
Exit status 0 when all pass.
"""
import argparse
import hashlib
import os
import re
import subprocess
import sys
import tempfile
import zlib
import struct

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from webdriver import Browser, Server  # noqa: E402

failures = []


def check(name, ok, why=""):
    print(("ok   " if ok else "FAIL ") + name + ("" if ok else ": " + why), flush=True)
    if not ok:
        failures.append(name)


def native_hash(iskra, scene, frames):
    """SHA-256 of the RGBA bytes of frame `frames` as the native tool renders it."""
    raw = subprocess.run([iskra, "render", scene, "--frames", str(frames), "--every", str(max(frames, 1)),
                          "--raw", "--out", "-"], check=True, stdout=subprocess.PIPE,
                         stderr=subprocess.DEVNULL).stdout
    count = 2 if frames > 0 else 1  # frames 0 and N
    return hashlib.sha256(raw[len(raw) - len(raw) // count:]).hexdigest()


def png_rgba(path):
    """RGBA8 rows of a non-interlaced 8-bit RGBA PNG (what libpng writes for iskra)."""
    b = open(path, "rb").read()
    assert b[:8] == b"\x89PNG\r\n\x1a\n"
    i, idat = 8, b""
    while i < len(b):
        n, t = struct.unpack(">I4s", b[i:i + 8])
        d = b[i + 8:i + 8 + n]
        if t == b"IHDR":
            w, h, depth, ctype, _, _, lace = struct.unpack(">IIBBBBB", d)
            assert (depth, ctype, lace) == (8, 6, 0)
        elif t == b"IDAT":
            idat += d
        i += 12 + n
    raw, out, prev, stride = zlib.decompress(idat), bytearray(), bytearray(w * 4), w * 4
    for y in range(h):
        f, row = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = row[x - 4] if x >= 4 else 0
            c = prev[x - 4] if x >= 4 else 0
            up = prev[x]
            if f == 1: row[x] = (row[x] + a) & 255
            elif f == 2: row[x] = (row[x] + up) & 255
            elif f == 3: row[x] = (row[x] + (a + up) // 2) & 255
            elif f == 4:
                p = a + up - c; pa, pb, pc = abs(p - a), abs(p - up), abs(p - c)
                row[x] = (row[x] + (a if pa <= pb and pa <= pc else up if pb <= pc else c)) & 255
        out += row; prev = row
    return w, h, bytes(out)

def native_play_hash(iskra, scene, frames, tmp):
    """SHA-256 of the simulator's canvas after `frames` shown frames of
    `iskra play --fixed-clock` (SDL's dummy driver: no window shown)."""
    shot = os.path.join(tmp, scene + ".png")
    env = dict(os.environ, SDL_VIDEODRIVER="dummy")
    subprocess.run([iskra, "play", scene, "--fixed-clock", "--frames", str(frames + 2), "--script",
                    "wait:%d canvas-shot:%s" % (frames - 1, shot)], check=True, env=env,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return hashlib.sha256(png_rgba(shot)[2]).hexdigest()


def open_page(b, url, fragment):
    b.go("about:blank")  # a new load, not a change of the fragment alone
    b.go(url + "?fixed-clock#" + fragment)
    b.wait_for("document.body.dataset.ready")
    ready = b.run("return document.body.dataset.ready")
    if ready != "1":
        raise RuntimeError("the page did not start: " + str(b.run("return document.getElementById('status').textContent")))


def scenes_match_native(b, url, iskra, frames, only, tmp):
    names = subprocess.run([iskra, "list"], check=True, stdout=subprocess.PIPE, text=True).stdout.split("\n")
    names = [n.split()[0] for n in names if n.strip()]
    open_page(b, url, "scene=" + names[0])
    page_names = b.run("return window.iskraPage.builtins()")
    check("the page offers the native tool's built-in scenes (%d)" % len(names), page_names == names,
          "page: %s" % page_names)
    for name in names:
        if only and name != only:
            continue
        want = native_hash(iskra, name, frames)
        got = b.run_async("window.iskraPage.renderHash(arguments[0], arguments[1])", name, frames)
        check("%s: frame %d as iskra render draws it" % (name, frames), got == want, "page %s, native %s" % (got, want))
        err = b.run("return window.iskraPage.open(arguments[0])", name)
        b.run("return window.iskraPage.frames(arguments[0])", frames)
        live = b.run_async("window.iskraPage.sceneHash()")
        want = native_play_hash(iskra, name, frames, tmp)
        check("%s: the simulator's canvas after %d frames as iskra play's" % (name, frames),
              not err and live == want, err or "page %s, native %s" % (live, want))


def click_widget(b, name, count=1):
    r = b.run("return window.iskraPage.widget(arguments[0])", name)
    if not r:
        raise RuntimeError("no widget " + name)
    b.click(r[0] + r[2] / 2, r[1] + r[3] / 2, count)


def pointer_and_keys(b, url):
    open_page(b, url, "scene=fig22_simulator_regular")
    b.run("return window.iskraPage.frames(2)")
    before = b.run("return window.iskraPage.particles()")
    c = b.run("const r = document.getElementById('screen').getBoundingClientRect(); return [r.left, r.top]")
    b.click(c[0] + 300, c[1] + 300)
    b.run("return window.iskraPage.frames(3)")
    after = b.run("return window.iskraPage.particles()")
    check("a click on fig 22's canvas explodes particles", before == 0 and after > 0,
          "particles %s before, %s after" % (before, after))
    click_widget(b, "gravity")
    b.run("return window.iskraPage.frames(1)")
    b.keys("2.5\ue007")  # Enter
    b.run("return window.iskraPage.frames(2)")
    text = b.run("return window.iskraPage.sceneText()") or ""
    check("a value typed into Gravity is applied", re.search(r"(?m)^g = 2\.5$", text) is not None,
          "scene text:\n" + text[:600])


def editor_mistake(b, url):
    open_page(b, url, "scene=fire_campfire")
    b.run("return window.iskraPage.frames(5)")
    good = b.run("return window.iskraPage.sceneText()")
    bad = good.replace("[scene]", "[scene]\nwidht = 3", 1)
    b.run("document.getElementById('edit').open = true; document.getElementById('editor').value = arguments[0]", bad)
    r = b.run("const r = document.getElementById('apply').getBoundingClientRect(); return [r.left, r.top, r.width, r.height]")
    b.run("document.getElementById('apply').scrollIntoView()")
    r = b.run("const r = document.getElementById('apply').getBoundingClientRect(); return [r.left, r.top, r.width, r.height]")
    b.click(r[0] + r[2] / 2, r[1] + r[3] / 2)
    msg = b.run("return window.iskraPage.editorMessage()")
    frame0 = b.run("return window.iskraPage.frames(0)")
    frame1 = b.run("return window.iskraPage.frames(3)")
    check("a typo in the editor shows FILE:LINE", re.match(r"scene\.ini:\d+: ", msg or "") is not None, repr(msg))
    check("the last good scene keeps running", frame1 == frame0 + 3 and frame0 >= 5, "frames %s -> %s" % (frame0, frame1))
    # The page has no files: a texture that is not a built-in one is named.
    pinwheel = b.run("return window.iskraPage.builtinText('looks_pinwheel')")
    other = re.sub(r"(?m)^texture = .*$", "texture = mine.png", pinwheel, count=1)
    msg = b.run("return window.iskraPage.apply(arguments[0])", other)
    check("a texture file the page cannot have is named", other != pinwheel and "mine.png: No such file" in msg, repr(msg))


def shared_link(b, url, frames):
    open_page(b, url, "scene=fire_campfire")
    text = b.run("return window.iskraPage.sceneText()").replace("seed = ", "seed = 7", 1)
    err = b.run("return window.iskraPage.apply(arguments[0])", text)
    b.run("return window.iskraPage.frames(arguments[0])", frames)
    first = b.run_async("window.iskraPage.sceneHash()")
    link = b.run_async("window.iskraPage.link()")
    b.go("about:blank")
    b.go(link.replace("#", "?fixed-clock#", 1) if "?" not in link else link)
    b.wait_for("document.body.dataset.ready")
    b.run("return window.iskraPage.frames(arguments[0])", frames)
    again = b.run_async("window.iskraPage.sceneHash()")
    check("a shared link, loaded fresh, gives the same bytes", not err and "#text=" in link and first == again,
          err or "link %s...: %s vs %s" % (link[:80], first, again))


def downloads(b, url):
    open_page(b, url, "scene=fire_campfire")
    b.run("return window.iskraPage.frames(2)")
    b.run("document.getElementById('png').scrollIntoView()")
    r = b.run("const r = document.getElementById('png').getBoundingClientRect(); return [r.left, r.top, r.width, r.height]")
    b.click(r[0] + r[2] / 2, r[1] + r[3] / 2)
    b.run("return window.iskraPage.frames(1)")
    f = b.run("return window.iskraPage.lastFile()")
    check("the PNG button makes a PNG of the frame", f is not None and f[0].endswith(".png") and f[1] > 1000, str(f))
    b.run("document.getElementById('gif-frames').value = 4; document.getElementById('gif').click()")
    b.run("return window.iskraPage.frames(4)")
    f = b.run("return window.iskraPage.lastFile()")
    check("the GIF button makes a GIF of the next frames", f is not None and f[0].endswith(".gif") and f[1] > 1000, str(f))


def fits(b, url):
    for w, h, scene in ((1280, 720, "fig22_simulator_regular"), (1366, 768, "fig22_simulator_regular"),
                        (1280, 720, "fire_campfire")):
        b.set_viewport(w, h)
        open_page(b, url, "scene=" + scene)
        ww, wh, scale = b.run("return window.iskraPage.size()")
        check("%s fits a %dx%d viewport" % (scene, w, h), ww * scale <= w and wh * scale <= h,
              "window %dx%d at %dx" % (ww, wh, scale))
    b.set_viewport(2560, 1440)
    open_page(b, url, "scene=fire_campfire")
    ww, wh, scale = b.run("return window.iskraPage.size()")
    css = b.run("const c = document.getElementById('screen'); return [c.getBoundingClientRect().width, c.width]")
    check("a large viewport scales by a whole number", scale >= 2 and css[0] == css[1] * scale, "%s at %s" % (css, scale))


def page_weight(web):
    """The page is its three files, at most 2 MB together."""
    files = ["index.html", "iskra.js", "iskra.wasm"]
    size = sum(os.path.getsize(os.path.join(web, f)) for f in files)
    check("the page weighs at most 2 MB (%.2f MB)" % (size / 1e6), size <= 2 * 1024 * 1024, "%d bytes" % size)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("iskra")
    ap.add_argument("web")
    ap.add_argument("--frames", type=int, default=30)
    ap.add_argument("--only")
    a = ap.parse_args()
    page_weight(a.web)
    with Server(a.web) as s, Browser(1366, 768) as b, tempfile.TemporaryDirectory() as tmp:
        scenes_match_native(b, s.url, a.iskra, a.frames, a.only, tmp)
        if not a.only:
            pointer_and_keys(b, s.url)
            editor_mistake(b, s.url)
            shared_link(b, s.url, a.frames)
            downloads(b, s.url)
            fits(b, s.url)
    print("web: %s" % ("all passed" if not failures else "%d failed: %s" % (len(failures), ", ".join(failures))))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
