#!/bin/sh
# SPDX-License-Identifier: MIT
# A program linked against the build tree's shared libraries starts: built
# with -L$BUILD/lib -liskra-sdl -liskra (the test suite's compiler and flags,
# $BUILD/gen/header_examples.env), it needs libiskra.so.MAJOR.MINOR and
# libiskra-sdl.so.MAJOR.MINOR (the sonames), and runs with
# LD_LIBRARY_PATH=$BUILD/lib alone: the build tree holds a file or link of
# each soname, as an installed tree does.  (A 32-bit build, M32=1, keeps
# the path to its fetched i386 libraries after it: SDL2 and libpng live
# there, not on the system.)  The program opens a window
# (SDL_VIDEODRIVER=dummy), draws into a canvas and checks that the library
# it runs with is the one its headers describe.
# Prints "build tree link: ok"; exit status 0 on success.
set -u
BUILD=${BUILD:-build}
fail() { echo "build tree link: $*" >&2; exit 1; }
env_file="$BUILD/gen/header_examples.env"
[ -f "$env_file" ] || fail "no $env_file (make test writes it)"
# EX_CC, EX_CFLAGS (-Werror, the sanitizers of a SANITIZE build)
# shellcheck source=/dev/null
. "./$env_file"
so=$(sed -n 's/^#define ISKRA_VERSION_MAJOR \([0-9]*\)$/\1/p' include/iskra/version.h).$(sed -n 's/^#define ISKRA_VERSION_MINOR \([0-9]*\)$/\1/p' include/iskra/version.h)
work="$BUILD/build_tree_link"
rm -rf "$work" && mkdir -p "$work" || exit 1
cat >"$work/prog.c" <<'EOF'
#include <iskra.h>
#include <iskra/sdl.h>
#include <stdio.h>
#include <string.h>

int main(void)
{
    if (strcmp(isk_version(), ISKRA_VERSION_STRING) != 0) {
        fprintf(stderr, "library %s, headers %s\n", isk_version(), ISKRA_VERSION_STRING);
        return 1;
    }
    isk_window *w;
    isk_error err;
    if (isk_window_open(&w, "link", 64, 48, &err) != ISK_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    isk_window_close(w);
    isk_canvas c;
    if (isk_canvas_init(&c, 64, 48) != ISK_OK)
        return 1;
    isk_canvas_fill(&c, ISK_BLACK);
    isk_fill_circle_aa(&c, 32, 24, 10, ISK_YELLOW, ISK_BLEND_OVER);
    int lit = isk_canvas_at(&c, 32, 24)[0] == 255;
    isk_canvas_free(&c);
    puts(lit ? "drawn" : "not drawn");
    return !lit;
}
EOF
# shellcheck disable=SC2086
$EX_CC $EX_CFLAGS -Iinclude "$work/prog.c" -o "$work/prog" -L"$BUILD/lib" -liskra-sdl -liskra -lm \
    || fail "cannot build a program against $BUILD/lib"
for lib in libiskra libiskra-sdl; do
    readelf -d "$work/prog" | grep -q "NEEDED.*\[$lib\.so\.$so\]" || fail "the program does not need $lib.so.$so"
    [ -e "$BUILD/lib/$lib.so.$so" ] || fail "$BUILD/lib has no $lib.so.$so (the soname)"
done
out=$(SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy LD_LIBRARY_PATH="$BUILD/lib${ISKRA_M32_LIBS:+:$ISKRA_M32_LIBS}" "$work/prog" 2>&1) \
    || fail "the program does not start with LD_LIBRARY_PATH=$BUILD/lib: $out"
[ "$out" = drawn ] || fail "unexpected output: $out"
echo "build tree link: ok"
