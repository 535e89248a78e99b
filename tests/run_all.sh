#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs every test binary in $BUILD/tests from the repository root, and the
# checks that are programs or scripts (threads_check, cxx_link, the header
# examples, the build tree's shared libraries, the install check), and
# prints one closing line "N passed, N failed" (tests counted across
# binaries).  A binary whose tests were skipped says how many and why.
#
# The jobs run ISKRA_TEST_JOBS at a time (default: the online cores).
# Criterion already spreads one binary's tests over the cores, but many
# binaries are a few long tests, so one binary at a time left a core idle
# about a third of the run.  Each job writes its own log and result; they are
# reported in one fixed order whatever finished first.  No two binaries share
# a scratch directory (each writes under out/<its name>), which is what lets
# them run together.  The install check runs alone at the end: it calls make.
#
# Set ISKRA_TEST_FILTER to a Criterion --filter pattern to run a subset,
# ISKRA_TEST_SKIP to test binaries to leave out (names, space-separated).
set -u
BUILD=${BUILD:-build}
export BUILD ISKRA_BUILD="$BUILD" # the jobs (and header_examples.sh) read it
# SDL under the test suite never needs a real display.
export SDL_VIDEODRIVER=${SDL_VIDEODRIVER:-dummy}
export SDL_AUDIODRIVER=${SDL_AUDIODRIVER:-dummy}
if [ -f tests/lsan.supp ]; then
    export LSAN_OPTIONS="suppressions=$(pwd)/tests/lsan.supp:print_suppressions=0"
fi
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

# run_all.sh --job DIR NAME: runs one job, writes DIR/NAME.log and
# DIR/NAME.res ("passed failed seconds exit-status summary").
if [ "${1:-}" = --job ]; then
    dir=$2; name=$3; log="$dir/$name.log"
    case $name in
    test_* | threads_check | cxx_link) set -- "$BUILD/tests/$name" ;;
    header_examples | install_check | build_tree_link) set -- sh "tests/$name.sh" ;;
    *) exit 0 ;; # no such job: no result, which the report counts as a failure
    esac
    # Criterion's TAP report (beside its usual output) names the skipped
    # tests and why they were skipped.
    case $name in test_*) set -- "$@" --tap="$dir/$name.tap" ;; esac
    case $name in test_*) [ -n "${ISKRA_TEST_FILTER:-}" ] && set -- "$@" --filter="$ISKRA_TEST_FILTER" ;; esac
    t0=$(date +%s.%N)
    "$@" >"$log" 2>&1; rc=$?
    secs=$(echo "$t0 $(date +%s.%N)" | awk '{printf "%.1f", $2 - $1}')
    case $name in
    test_*)
        # [====] Synthesis: Tested: 12 | Passing: 12 | Failing: 0 | Crashing: 0
        syn=$(grep -a "Synthesis:" "$log" | tail -n 1)
        tested=$(echo "$syn" | sed -n 's/.*Tested: \([0-9]*\).*/\1/p')
        passing=$(echo "$syn" | sed -n 's/.*Passing: \([0-9]*\).*/\1/p')
        tested=${tested:-0}; passing=${passing:-0}
        fails=$((tested - passing))
        what="$passing tests"
        # "ok - x::y  # SKIP why": a skipped test is no pass; say how many
        # and why (each distinct reason once)
        skipped=$(grep -c '^ok .* # SKIP' "$dir/$name.tap" 2>/dev/null)
        if [ "${skipped:-0}" -gt 0 ]; then
            why=$(sed -n 's/^ok .* # SKIP *//p' "$dir/$name.tap" | sort -u | awk '{printf "%s%s", (NR > 1 ? "; " : ""), $0}')
            what="$what, $skipped skipped: ${why:-no reason given}"
        fi ;;
    *)
        # a check that is one program: one test, passed when it exits with 0
        passing=$((rc == 0)); fails=0; what=""
        [ "$name" = header_examples ] && what=$(tail -n 1 "$log" | sed 's/.*: //') ;;
    esac
    if [ "$rc" -ne 0 ] && [ "$fails" -eq 0 ]; then fails=1; fi
    echo "$passing $fails $secs $rc $what" >"$dir/$name.res"
    exit 0
fi

jobs=${ISKRA_TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
case $jobs in '' | *[!0-9]* | 0) echo "ISKRA_TEST_JOBS: a whole number of at least 1, not '$jobs'" >&2; exit 2 ;; esac
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
list="$dir/jobs"
: >"$list"
for t in "$BUILD"/tests/test_*; do
    [ -x "$t" ] || continue
    case " ${ISKRA_TEST_SKIP:-} " in *" $(basename "$t") "*) echo "skip $(basename "$t") (ISKRA_TEST_SKIP)"; continue ;; esac
    basename "$t" >>"$list"
done
if [ -z "${ISKRA_TEST_FILTER:-}" ]; then
    # Threads never change a byte (a plain program; CI also runs it under TSan).
    [ -x "$BUILD/tests/threads_check" ] && echo threads_check >>"$list"
    # Every public header as C++ (built by the Makefile with the C++ compiler).
    [ -x "$BUILD/tests/cxx_link" ] && echo cxx_link >>"$list"
    # Every public header's usage example and docs/hello_iskra.c, built with
    # this build's compiler and flags and run (a header without one fails).
    echo header_examples >>"$list"
    # A program linked against $BUILD/lib's shared libraries starts.
    echo build_tree_link >>"$list"
fi
xargs -P "$jobs" -n 1 sh "$0" --job "$dir" <"$list"
# The install check (make install + a pkg-config build) runs once, on the
# normal build only (a sanitized libiskra would need sanitized users), and
# alone: its make must not run beside binaries it could relink.
if [ "$BUILD" = build ] && [ -z "${ISKRA_TEST_FILTER:-}" ]; then
    echo install_check >>"$list"
    sh "$0" --job "$dir" install_check
fi

passed=0; failed=0; bad_bins=""
while read -r name; do
    if [ -f "$dir/$name.res" ]; then
        read -r p f secs rc what <"$dir/$name.res"
    else
        p=0; f=1; secs=0; rc=lost; what=""
    fi
    passed=$((passed + p)); failed=$((failed + f))
    if [ "$f" -ne 0 ]; then
        bad_bins="$bad_bins $name"
        echo "---- $name (exit $rc, $secs s) ----"; cat "$dir/$name.log" 2>/dev/null
    else
        echo "ok   $name${what:+: $what} ($secs s)"
    fi
done <"$list"
[ -n "$bad_bins" ] && echo "failing binaries:$bad_bins"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
