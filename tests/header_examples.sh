#!/bin/sh
# SPDX-License-Identifier: MIT
# Every public header's usage example, docs/hello_iskra.c and the tutorial's
# docs/tutorial/fountain.c, compiled and
# run as a user would: the convention (docs/architecture.md, "Header
# examples") is that a header's top comment has one line starting with
# "Example" and ending with ":", followed by the example, indented four
# spaces after " * "; a line "// in main():" may separate top-level
# definitions (callbacks) from the body of main.
#
# Each example becomes a program (its body in a function of its own; #line
# points the compiler's messages at the header), compiled with the test
# suite's compiler and flags
# ($BUILD/gen/header_examples.env, written by the Makefile: -Werror always,
# the sanitizers of a SANITIZE build, the public include path only), linked
# against $BUILD's libiskra.a (and libiskra-sdl.a for a header that is or
# includes iskra/sdl.h) and run in an empty scratch directory of its own
# with SDL_VIDEODRIVER=dummy; it must exit with status 0 within a minute.
# A header without an example fails.  Exit status 0 when all pass; each
# failure names its header and shows the compiler's or the program's output.
set -u
BUILD=${BUILD:-build}
env_file="$BUILD/gen/header_examples.env"
if [ ! -f "$env_file" ]; then
    echo "header examples: no $env_file (make test writes it)" >&2
    exit 1
fi
# EX_CC, EX_CFLAGS, EX_LIBS, EX_SDL_LIBS
# shellcheck source=/dev/null
. "./$env_file"
export SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy
unset ISKRA_REFIMG_UPDATE || true

work="$BUILD/header_examples"
rm -rf "$work"
mkdir -p "$work/src" "$work/bin" "$work/run" || exit 1
top=$(pwd)

# extract HEADER C: writes the example wrapped as a program to C, or a
# message on stderr and exit status 1.
extract() {
    awk -v hdr="$1" -v out="$2" '
    function fail(msg) { print hdr ": " msg > "/dev/stderr"; bad = 1; exit 1 }
    function emit(s) { print s > out; nout++ }
    # the licence line, then the top comment
    NR == 1 && /^\/\* SPDX-License-Identifier: [^*]*\*\/$/ { spdx = 1; next }
    NR == 1 + spdx && !/^\/\*/ { fail("does not start with its top comment") }
    done { next }
    inblock && /^ \*     .*\*\/[ \t]*$/ {
        fail("line " NR ": the comment ends on a line of the example, which would not be run: put \" */\" on a line of its own")
    }
    /\*\// { done = 1; next }
    /^ \* Example.*:$/ {
        if (heading) fail("has two \"Example...:\" lines (lines " heading " and " NR ")")
        heading = NR; inblock = 1; next
    }
    inblock && n == 0 && /^ \*$/ { next }
    inblock && (/^ \*$/ || /^ \*     /) {
        # " *" becomes two blanks, so columns in messages match the header
        code[++n] = substr($0, 8); line[n] = "  " substr($0, 3); lineno[n] = NR; next
    }
    inblock { inblock = 0 }
    END {
        if (bad) exit 1
        if (!heading)
            fail("has no usage example: its top comment needs a line \"Example...:\" followed by code indented four spaces after \" * \" (docs/architecture.md, Header examples)")
        while (n > 0 && code[n] == "") n--
        if (n == 0) fail("line " heading ": no code indented four spaces after \" * \" follows the Example line")
        marker = 0
        for (i = 1; i <= n; i++)
            if (code[i] == "// in main():") {
                if (marker) fail("line " lineno[i] ": a second \"// in main():\" line")
                marker = i
            }
        inc = hdr; sub(/^include\//, "", inc)
        emit("/* The example of " hdr ", extracted by tests/header_examples.sh. */")
        emit("#include <iskra.h>")
        if (inc != "iskra.h") emit("#include <" inc ">")
        emit("#include <stdio.h>")
        if (marker) {
            emit(sprintf("#line %d \"%s\"", lineno[1], hdr))
            for (i = 1; i < marker; i++) emit(line[i])
        }
        # The body runs in a function of its own, called through a volatile
        # pointer so it is never inlined: when it returns, its locals are
        # off the stack and LeakSanitizer sees what it did not free.
        emit("static int example_main(void)")
        emit("{")
        emit(sprintf("#line %d \"%s\"", lineno[marker + 1], hdr))
        for (i = marker + 1; i <= n; i++) emit(line[i])
        emit(sprintf("#line %d \"%s\"", nout + 2, out))
        emit("    return 0;")
        emit("}")
        emit("int main(void)")
        emit("{")
        emit("    int (*volatile run)(void) = example_main;")
        emit("    return run();")
        emit("}")
    }' "$1"
}

passed=0; failed=0
fail() { failed=$((failed + 1)); printf 'FAIL %s: %s\n' "$1" "$2"; cat "$3"; echo; }

# check NAME SOURCE HEADER LIBS [FILE]: compile, link, run in run/NAME
# (which must then hold a non-empty FILE, when one is named).
check() {
    name=$1 src=$2 hdr=$3 libs=$4 want=${5:-} bin="$work/bin/$1" log="$work/$1.log"
    # shellcheck disable=SC2086
    if ! $EX_CC $EX_CFLAGS -o "$bin" "$src" $libs >"$log" 2>&1; then
        fail "$hdr" "the example does not compile (compiler output below, $EX_CC $EX_CFLAGS)" "$log"
        return
    fi
    mkdir -p "$work/run/$name"
    (cd "$work/run/$name" && timeout 60 "$top/$bin") >"$log" 2>&1
    rc=$?
    if [ "$rc" -eq 124 ]; then
        fail "$hdr" "the example did not finish within 60 s (its output below)" "$log"
    elif [ "$rc" -ne 0 ]; then
        fail "$hdr" "the example exited with status $rc, run in $work/run/$name (its output below)" "$log"
    elif [ -n "$want" ] && [ ! -s "$work/run/$name/$want" ]; then
        fail "$hdr" "the program wrote no $want (its output below)" "$log"
    else
        passed=$((passed + 1))
    fi
}

for hdr in include/iskra.h include/iskra/*.h; do
    name=$(basename "$hdr" .h)
    src="$work/src/$name.c"
    if ! extract "$hdr" "$src" 2>"$work/$name.log"; then
        failed=$((failed + 1)); printf 'FAIL %s\n\n' "$(cat "$work/$name.log")"
        continue
    fi
    libs=$EX_LIBS
    if [ "$name" = sdl ] || grep -q '^#include "iskra/sdl.h"' "$hdr"; then libs=$EX_SDL_LIBS; fi
    check "$name" "$src" "$hdr" "$libs"
done
check hello_iskra docs/hello_iskra.c docs/hello_iskra.c "$EX_LIBS" hello.png
# The tutorial's program (docs/tutorial.md; test_tutorial checks its pixels).
check tutorial_fountain docs/tutorial/fountain.c docs/tutorial/fountain.c "$EX_LIBS" fountain.png

echo "header examples: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
