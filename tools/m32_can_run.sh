#!/bin/sh
# SPDX-License-Identifier: MIT
# Says whether this machine runs 32-bit x86 programs, for `make test
# M32=1`: builds a program of one line with CC's -m32 in DIR and runs it.
# Exit 0 if it runs, 1 (with a message) if the kernel refuses it.
#
#   tools/m32_can_run.sh CC DIR
#
# A kernel built without IA-32 emulation, or one that has it switched off
# (some virtual machines), refuses every i386 program with "Exec format
# error" (the shell's exit status 126).  `make test M32=1` then builds the
# library and the tool alone (every 32-bit warning is still an error) and
# says why the tests did not run.  A probe that does not even build is
# not this: the build that follows reports it.
set -u
[ $# -eq 2 ] || { echo "usage: $0 CC DIR" >&2; exit 2; }
cc=$1; dir=$2
mkdir -p "$dir" || exit 0
printf 'int main(void) { return sizeof(void *) == 4 ? 0 : 1; }\n' >"$dir/m32_probe.c"
"$cc" -m32 -o "$dir/m32_probe" "$dir/m32_probe.c" 2>/dev/null || exit 0
"$dir/m32_probe" 2>/dev/null
rc=$?
if [ "$rc" -eq 126 ]; then
    echo "make test M32=1: this machine cannot run 32-bit x86 programs (the kernel refuses them:" >&2
    echo "  Exec format error): the library and the tool are built, the tests are not run." >&2
    exit 1
fi
exit 0
