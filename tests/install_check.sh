#!/bin/sh
# SPDX-License-Identifier: MIT
# The README's install recipe, as written: installs iskra into a scratch
# prefix (outside the system library path), builds docs/hello_iskra.c with
# `pkg-config --cflags --libs iskra` only, and runs it WITHOUT
# LD_LIBRARY_PATH: the program must find libiskra.so by itself (the rpath
# iskra.pc carries for such a prefix).  Then the same with the static
# library, the installed iskra tool and its manual pages, and uninstall.
# Prints "install check: ok" on success; exit status says the rest.
set -eu
prefix="$(pwd)/out/install-check"
rm -rf "$prefix"
make --no-print-directory -s install PREFIX="$prefix" >/dev/null
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
unset LD_LIBRARY_PATH || true
work="$prefix/work"; mkdir -p "$work"
fail() { echo "install check: $*" >&2; exit 1; }

# shellcheck disable=SC2046
cc -std=c11 -Wall -Wextra -Werror docs/hello_iskra.c -o "$work/hello" $(pkg-config --cflags --libs iskra)
# It is linked against the shared library (so this checks the run-time lookup) ...
# (the soname carries MAJOR.MINOR, read from iskra/version.h)
so=$(sed -n 's/^#define ISKRA_VERSION_MAJOR \([0-9]*\)$/\1/p' include/iskra/version.h).$(sed -n 's/^#define ISKRA_VERSION_MINOR \([0-9]*\)$/\1/p' include/iskra/version.h)
readelf -d "$work/hello" | grep -q "NEEDED.*libiskra\.so\.$so\]" || fail "hello does not use libiskra.so.$so"
readelf -d "$work/hello" | grep -Eq "R(UN)?PATH.*$prefix/lib" || fail "hello has no rpath to $prefix/lib"
# ... and starts, calls the library and writes its picture, with no help from the environment.
(cd "$work" && env -u LD_LIBRARY_PATH ./hello) || fail "hello does not run without LD_LIBRARY_PATH"
test -s "$work/hello.png" || fail "hello wrote no hello.png"
"$prefix/bin/iskra" --version >/dev/null
# The manual pages, where man looks (PREFIX/share/man/manN).
cmp -s man/iskra.1 "$prefix/share/man/man1/iskra.1" || fail "iskra.1 is not installed in share/man/man1"
cmp -s man/iskra-scene.5 "$prefix/share/man/man5/iskra-scene.5" || fail "iskra-scene.5 is not installed in share/man/man5"

# The static library alone works too.
mkdir -p "$work/static"
# shellcheck disable=SC2046
cc -std=c11 docs/hello_iskra.c -o "$work/hello-static" -I"$prefix/include" "$prefix/lib/libiskra.a" \
   $(pkg-config --libs libpng libgif inih) -lm
readelf -d "$work/hello-static" | grep -q 'NEEDED.*libiskra' && fail "hello-static needs libiskra.so"
(cd "$work/static" && ../hello-static)
# Both programs drew the same picture (and the installed tool reads it).
"$prefix/bin/iskra" compare "$work/hello.png" "$work/static/hello.png" >/dev/null \
    || fail "the shared and static builds drew different pictures"

# The README's reference-image examples, built against the installed library
# and used as a user would: the first run with ISKRA_REFIMG_UPDATE=1 makes
# the references, the next passes, a changed reference fails with the
# actual and diff images left behind.
for ex in refimg_assert refimg_criterion; do
    d="$work/$ex"; mkdir -p "$d"
    extra=""; [ "$ex" = refimg_criterion ] && extra=criterion
    # shellcheck disable=SC2046
    cc -std=c11 -Wall -Wextra -Werror "docs/$ex.c" -o "$d/run" $(pkg-config --cflags --libs iskra $extra)
    (cd "$d" && ISKRA_REFIMG_UPDATE=1 ./run >/dev/null 2>&1) || fail "$ex: the update run failed"
    (cd "$d" && ./run >/dev/null 2>&1) || fail "$ex: the check after the update failed"
    ref=$(ls "$d"/ref/*.png | head -n 1)
    cp "$work/hello.png" "$ref"
    if (cd "$d" && ./run >"$d/log" 2>&1 || exit 1); then fail "$ex: passed against a wrong reference"; fi
    grep -q "pixels differ\|reference" "$d/log" || fail "$ex: the failure does not say what differs"
    ls "$d"/out/refimg/*.actual.png "$d"/out/refimg/*.diff.png >/dev/null 2>&1 || fail "$ex: no actual/diff images"
done

make --no-print-directory -s uninstall PREFIX="$prefix" >/dev/null
test ! -e "$prefix/lib/libiskra.so" && test ! -e "$prefix/include/iskra.h"
test ! -e "$prefix/share/man/man1/iskra.1" || fail "uninstall left iskra.1"
test ! -e "$prefix/share/man/man5/iskra-scene.5" || fail "uninstall left iskra-scene.5"
echo "install check: ok"
