#!/bin/sh
# `make run`: renders every example into out/ and says where.  (With a
# display, the scene player takes over once `iskra play` exists.)
set -eu
BUILD=${BUILD:-build}
mkdir -p out
n=0
for e in "$BUILD"/examples/*; do
    [ -x "$e" ] || continue
    name=$(basename "$e")
    "$e" --png "out/$name.png"
    n=$((n + 1))
done
echo "iskra: rendered $n example images into $(pwd)/out/"
ls out/*.png | sed 's/^/  /'
