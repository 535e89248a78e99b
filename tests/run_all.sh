#!/bin/sh
# Runs every test binary in $BUILD/tests from the repository root and prints
# one closing line "N passed, N failed" (tests counted across binaries).
# Set ISKRA_TEST_FILTER to a Criterion --filter pattern to run a subset.
set -u
BUILD=${BUILD:-build}
export ISKRA_BUILD="$BUILD"
# SDL under the test suite never needs a real display.
export SDL_VIDEODRIVER=${SDL_VIDEODRIVER:-dummy}
export SDL_AUDIODRIVER=${SDL_AUDIODRIVER:-dummy}
if [ -f tests/lsan.supp ]; then
    export LSAN_OPTIONS="suppressions=$(pwd)/tests/lsan.supp:print_suppressions=0"
fi
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
passed=0; failed=0; bad_bins=""
log=$(mktemp); trap 'rm -f "$log"' EXIT
for t in "$BUILD"/tests/test_*; do
    [ -x "$t" ] || continue
    name=$(basename "$t")
    t0=$(date +%s.%N)
    if [ -n "${ISKRA_TEST_FILTER:-}" ]; then
        "$t" --filter="$ISKRA_TEST_FILTER" >"$log" 2>&1; rc=$?
    else
        "$t" >"$log" 2>&1; rc=$?
    fi
    secs=$(echo "$t0 $(date +%s.%N)" | awk '{printf "%.1f", $2 - $1}')
    syn=$(grep -a "Synthesis:" "$log" | tail -n 1)
    # [====] Synthesis: Tested: 12 | Passing: 12 | Failing: 0 | Crashing: 0
    tested=$(echo "$syn" | sed -n 's/.*Tested: \([0-9]*\).*/\1/p')
    passing=$(echo "$syn" | sed -n 's/.*Passing: \([0-9]*\).*/\1/p')
    tested=${tested:-0}; passing=${passing:-0}
    fails=$((tested - passing))
    if [ "$rc" -ne 0 ] && [ "$fails" -eq 0 ]; then fails=1; fi
    passed=$((passed + passing)); failed=$((failed + fails))
    if [ "$fails" -ne 0 ]; then
        bad_bins="$bad_bins $name"
        echo "---- $name (exit $rc, $secs s) ----"; cat "$log"
    else
        echo "ok   $name: $passing tests ($secs s)"
    fi
done
# Threads never change a byte (a plain program; CI also runs it under TSan).
if [ -x "$BUILD/tests/threads_check" ] && [ -z "${ISKRA_TEST_FILTER:-}" ]; then
    if "$BUILD/tests/threads_check" >"$log" 2>&1; then
        passed=$((passed + 1)); echo "ok   threads_check"
    else
        failed=$((failed + 1)); bad_bins="$bad_bins threads_check"
        echo "---- threads_check ----"; cat "$log"
    fi
fi
# Every public header as C++ (built by the Makefile with the C++ compiler).
if [ -x "$BUILD/tests/cxx_link" ] && [ -z "${ISKRA_TEST_FILTER:-}" ]; then
    if "$BUILD/tests/cxx_link" >"$log" 2>&1; then
        passed=$((passed + 1)); echo "ok   cxx_link"
    else
        failed=$((failed + 1)); bad_bins="$bad_bins cxx_link"
        echo "---- cxx_link ----"; cat "$log"
    fi
fi
# Every public header's usage example and docs/hello_iskra.c, built with
# this build's compiler and flags and run (a header without one fails).
if [ -z "${ISKRA_TEST_FILTER:-}" ]; then
    if BUILD="$BUILD" sh tests/header_examples.sh >"$log" 2>&1; then
        passed=$((passed + 1)); echo "ok   header_examples: $(tail -n 1 "$log" | sed 's/.*: //')"
    else
        failed=$((failed + 1)); bad_bins="$bad_bins header_examples"
        echo "---- header_examples ----"; cat "$log"
    fi
fi
# The install check (make install + a pkg-config build) runs once, on the
# normal build only: a sanitized libiskra would need sanitized users.
if [ "$BUILD" = build ] && [ -z "${ISKRA_TEST_FILTER:-}" ]; then
    if sh tests/install_check.sh >"$log" 2>&1; then
        passed=$((passed + 1)); echo "ok   install_check"
    else
        failed=$((failed + 1)); bad_bins="$bad_bins install_check"
        echo "---- install_check ----"; cat "$log"
    fi
fi
[ -n "$bad_bins" ] && echo "failing binaries:$bad_bins"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
