#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The web build's speed beside the native build's (make bench-web):

    tools/web_bench.py NATIVE WEB_DIR [--rounds N]

NATIVE is build/bench/bench_web_native, WEB_DIR the built page (build/web,
with bench.html, bench.wasm and bench-nosimd.wasm).  Each round runs the
kernels of bench/web/web_kernels.h three ways in turn: natively, then in
headless Chromium built with -msimd128, then without (the order turns
from round to round), so a change in the machine's load falls on every
side alike.  Every figure is the median over the rounds of a round's
median run, in ms, on one thread.

The table gives each kernel's times, the ratio of the browser's to the
native time, what simd128 buys, and whether all three made the same
bytes (each kernel's hash).  The first two rows are controls, the same
simple loops natively and in wasm: "arith", a chain of dependent
multiplications (the processor's share), and "memory", a drag step over
columns beyond the caches (the memory's share).  Their ratios are what
the machine's load did between the sides, and a kernel's ratio is the
code's only as far as it stands apart from theirs.  Then the full
frame's FPS in the browser against the 60 FPS target.  Exit status 1
when the bytes differ or a side fails.

Both sides run at the same priority: Chromium sets its processes' own
(where it may, the page's renderer at nice 0 whatever it was started
with), so the native program is given the page renderer's nice value;
on a machine shared with other work a side at a lower priority would get
less of the processor.  Where that cannot be done, the table says so.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from webdriver import Browser, Server, WebDriverError  # noqa: E402

TARGET_FPS = 60.0
SIDES = ("native", "simd128", "no simd")
MODULES = {"simd128": "bench.wasm", "no simd": "bench-nosimd.wasm"}
LINE = re.compile(r"^(\S+)\s+([0-9.]+)\s+([0-9a-f]{16})\s+(\d+)\s+(.*)$")


def proc_stat(pid):
    """(parent pid, nice) of a process from /proc, or None when it is gone."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return int(fields[1]), int(fields[16])
    except (OSError, IndexError, ValueError):
        return None


def renderer_nice(root):
    """The nice value of the page's renderer among the processes under
    `root` (the lowest of Chromium's renderers that show pages), or None."""
    parents, nices, renderers = {}, {}, []
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        st = proc_stat(int(name))
        if not st:
            continue
        parents[int(name)], nices[int(name)] = st
        try:
            with open("/proc/%s/cmdline" % name, "rb") as f:
                args = f.read().replace(b"\0", b" ").split()  # Chromium rewrites its argv as one string
        except OSError:
            continue
        if b"--type=renderer" in args and b"--top-chrome-webui" not in args:
            renderers.append(int(name))
    found = []
    for pid in renderers:
        p = pid
        while p in parents and p not in (0, 1, root):
            p = parents[p]
        if p == root:
            found.append(nices[pid])
    return min(found) if found else None


def run_native(program, nice):
    """[{name, ms, hash, what}] from the native program's lines, run at `nice`."""
    out = subprocess.run([program], check=True, stdout=subprocess.PIPE, text=True,
                         preexec_fn=lambda: os.setpriority(os.PRIO_PROCESS, 0, nice)).stdout
    rows = []
    for line in out.splitlines()[1:]:
        m = LINE.match(line)
        if not m:
            raise RuntimeError("%s: unexpected line: %r" % (program, line))
        rows.append({"name": m[1], "ms": float(m[2]), "hash": m[3], "what": m[5]})
    return rows


def run_browser(b, url, module):
    b.go("about:blank")  # a fresh page: a new module, its memory from nothing
    b.go(url + "bench.html")
    b.wait_for("document.body.dataset.ready === '1'")
    return b.run_async("window.iskraBench.run(arguments[0])", module)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("native", help="build/bench/bench_web_native")
    ap.add_argument("web_dir", help="the built page: build/web")
    ap.add_argument("--rounds", type=int, default=3, help="rounds of native, simd128, no simd (default 3)")
    a = ap.parse_args()
    if a.rounds < 1:
        ap.error("--rounds must be 1 or more")
    for f in [a.native] + [os.path.join(a.web_dir, m) for m in ("bench.html", "bench.js", *MODULES.values())]:
        if not os.path.exists(f):
            sys.exit("web_bench: %s is missing (make bench-web builds it)" % f)

    ms = {s: {} for s in SIDES}       # side -> kernel -> [round medians]
    hashes = {s: {} for s in SIDES}   # side -> kernel -> {hashes}
    names, what = [], {}
    with Browser() as b, Server(a.web_dir) as srv:
        b.go(srv.url + "bench.html")
        b.wait_for("document.body.dataset.ready === '1'")
        agent = b.run("return navigator.userAgent")
        page_nice = renderer_nice(b.proc.pid)
        own_nice = os.getpriority(os.PRIO_PROCESS, 0)
        native_nice = own_nice if page_nice is None else page_nice
        try:
            subprocess.run(["true"], check=True, preexec_fn=lambda: os.setpriority(os.PRIO_PROCESS, 0, native_nice))
        except (subprocess.SubprocessError, OSError):
            native_nice = own_nice
        if page_nice is None:
            priority = "native at nice %d; the page's renderer not found" % native_nice
        elif native_nice == page_nice:
            priority = "both at nice %d" % native_nice
        else:
            priority = "native at nice %d, the page's renderer at %d: NOT the same priority" % (native_nice, page_nice)
        for r in range(a.rounds):
            order = SIDES[r % 3:] + SIDES[:r % 3]
            print("round %d of %d: %s" % (r + 1, a.rounds, ", ".join(order)), flush=True)
            for side in order:
                rows = run_native(a.native, native_nice) if side == "native" else run_browser(b, srv.url, MODULES[side])
                for row in rows:
                    if row["name"] not in what:
                        names.append(row["name"])
                        what[row["name"]] = row["what"]
                    ms[side].setdefault(row["name"], []).append(row["ms"])
                    hashes[side].setdefault(row["name"], set()).add(row["hash"])

    chrome = re.search(r"(?:Headless)?Chrome/(\S+)", agent)
    print("\nbench-web: one thread, 800x600; medians over %d rounds of each kernel's median run, in ms; "
          "Chromium %s; %s" % (a.rounds, chrome[1] if chrome else agent, priority))
    print("%-8s %8s %8s %8s  %14s %14s %10s  %s" % ("kernel", "native", "simd128", "no simd", "simd128/native",
                                                   "no simd/native", "simd buys", "same bytes"))
    med = {s: {k: statistics.median(v) for k, v in ms[s].items()} for s in SIDES}
    failed = False
    for k in names:
        if any(k not in med[s] for s in SIDES):
            print("%-8s  not run on every side" % k)
            failed = True
            continue
        n, w, v = med["native"][k], med["simd128"][k], med["no simd"][k]
        seen = {s: hashes[s][k] for s in SIDES}
        same = all(len(h) == 1 for h in seen.values()) and len(set().union(*seen.values())) == 1
        failed |= not same
        print("%-8s %8.2f %8.2f %8.2f  %13.2fx %13.2fx %9.2fx  %s" % (
            k, n, w, v, w / n, v / n, v / w,
            "yes" if same else "NO: " + "; ".join("%s %s" % (s, ",".join(sorted(h))) for s, h in seen.items())))
    for k in names:
        print("  %-8s %s" % (k, what[k]))
    for k in names:
        if what[k].startswith("control") and all(k in med[s] for s in SIDES):
            print("control %s ran %.2fx (simd128), %.2fx (no simd) as long in the browser: the machine's part "
                  "in the ratios" % (k, med["simd128"][k] / med["native"][k], med["no simd"][k] / med["native"][k]))
    if "frame" in med["simd128"]:
        for side in ("simd128", "no simd"):
            fps = 1e3 / med[side]["frame"]
            print("frame in the browser (%s): %.2f ms, %.1f FPS: the %.0f FPS target %s (%.2f of it)" % (
                side, med[side]["frame"], fps, TARGET_FPS, "met" if fps >= TARGET_FPS else "NOT met",
                fps / TARGET_FPS))
        print("frame natively on one thread: %.2f ms, %.1f FPS" % (med["native"]["frame"], 1e3 / med["native"]["frame"]))
    if failed:
        print("web_bench: the sides did not make the same bytes", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (subprocess.CalledProcessError, WebDriverError, RuntimeError, OSError) as e:
        sys.exit("web_bench: %s" % e)
