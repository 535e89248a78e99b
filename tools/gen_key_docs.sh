#!/bin/sh
# SPDX-License-Identifier: MIT
# Regenerates the key tables of docs/scene-format.md from the key table
# (iskra keys --markdown SECTION), between the lines
#     <!-- keys SECTION -->   and   <!-- end keys -->
# usage: tools/gen_key_docs.sh [ISKRA] [DOC] [OUT]
#   ISKRA  the iskra program (default build/bin/iskra)
#   DOC    the document to read (default docs/scene-format.md)
#   OUT    where to write it (default: DOC itself, through a temporary file)
# tests/test_keys.c runs it into a copy and fails when the copy differs.
set -eu
bin=${1:-build/bin/iskra}
doc=${2:-docs/scene-format.md}
out=${3:-$doc}
tmp="$out.tmp.$$"
trap 'rm -f "$tmp"' EXIT
awk -v bin="$bin" '
    /^<!-- keys [a-z]+ -->$/ {
        print
        cmd = bin " keys --markdown " $3
        while ((cmd | getline line) > 0) print line
        if (close(cmd) != 0) { print "gen_key_docs: " cmd " failed" > "/dev/stderr"; exit 1 }
        skip = 1
        next
    }
    /^<!-- end keys -->$/ { skip = 0 }
    !skip { print }
' "$doc" > "$tmp"
mv "$tmp" "$out"
