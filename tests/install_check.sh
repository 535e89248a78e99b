#!/bin/sh
# Installs iskra into a scratch prefix, builds docs/hello_iskra.c with
# `pkg-config --cflags --libs iskra` only, runs it, and checks the PNG.
# Prints "install check: ok" on success; exit status says the rest.
set -eu
prefix="$(pwd)/out/install-check"
rm -rf "$prefix"
make --no-print-directory -s install PREFIX="$prefix" >/dev/null
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
work="$prefix/work"; mkdir -p "$work"
# shellcheck disable=SC2046
cc -std=c11 -Wall -Wextra -Werror docs/hello_iskra.c -o "$work/hello" $(pkg-config --cflags --libs iskra)
(cd "$work" && LD_LIBRARY_PATH="$prefix/lib" ./hello)
test -s "$work/hello.png"
"$prefix/bin/iskra" --version >/dev/null
# The static library alone works too (pkg-config --static).
cc -std=c11 docs/hello_iskra.c -o "$work/hello-static" -I"$prefix/include" "$prefix/lib/libiskra.a" \
   $(pkg-config --libs libpng inih) -lm
(cd "$work" && ./hello-static)
"$prefix/bin/iskra" compare "$work/hello.png" "$work/hello.png" >/dev/null
make --no-print-directory -s uninstall PREFIX="$prefix" >/dev/null
test ! -e "$prefix/lib/libiskra.so" && test ! -e "$prefix/include/iskra.h"
echo "install check: ok"
