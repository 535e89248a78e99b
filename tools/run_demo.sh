#!/bin/sh
# `make run`: the main demo.  With a display (DISPLAY or WAYLAND_DISPLAY set
# and a window that opens) it plays the campfire scene in a window; otherwise
# it renders it to out/SCENE.png plus a short sequence in out/SCENE/
# and says where.
set -u
BUILD=${BUILD:-build}
ISKRA="$BUILD/bin/iskra"
if [ ! -x "$ISKRA" ]; then
    echo "run_demo: $ISKRA is missing (run make first)" >&2
    exit 1
fi
scene=fire_campfire
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    echo "iskra: playing '$scene' (space pause, R reset, +/- substeps, F12 screenshot, H overlay, Esc quit)"
    if "$ISKRA" play "$scene"; then
        exit 0
    fi
    echo "iskra: no window could be opened; rendering instead" >&2
fi
mkdir -p out
"$ISKRA" render "$scene" --out "out/$scene.png" || exit 1
"$ISKRA" render "$scene" --frames 60 --every 6 --out-dir "out/$scene" || exit 1
echo "iskra: rendered the '$scene' scene to $(pwd)/out/$scene.png"
echo "       and frames 0..60 (every 6th) to $(pwd)/out/$scene/"
