#!/bin/sh
# SPDX-License-Identifier: MIT
# `make run`: the main demo.  With a display it plays the campfire scene in
# the simulator's window; with none (no DISPLAY or WAYLAND_DISPLAY, or one
# that does not answer: `iskra play` then says so and exits 1) it renders
# the scene to out/SCENE.png plus a short sequence in out/SCENE/ and says
# where.
set -u
BUILD=${BUILD:-build}
ISKRA="$BUILD/bin/iskra"
if [ ! -x "$ISKRA" ]; then
    echo "run_demo: $ISKRA is missing (run make first)" >&2
    exit 1
fi
scene=fire_campfire
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    echo "iskra: playing '$scene' (P play, Space run/hold, R reset, N one frame, Tab hides the panel, Esc quits)"
    "$ISKRA" play "$scene"
    rc=$?
    if [ "$rc" -ne 1 ]; then
        exit "$rc"
    fi
    echo "iskra: no window could be shown (see above); rendering to out/ instead" >&2
else
    echo "iskra: no display (DISPLAY and WAYLAND_DISPLAY are not set); rendering to out/ instead" >&2
fi
mkdir -p out
"$ISKRA" render "$scene" --out "out/$scene.png" || exit 1
"$ISKRA" render "$scene" --frames 60 --every 6 --out-dir "out/$scene" || exit 1
echo "iskra: rendered the '$scene' scene to $(pwd)/out/$scene.png"
echo "       and frames 0..60 (every 6th) to $(pwd)/out/$scene/"
