#!/bin/sh
# SPDX-License-Identifier: MIT
# Writes the manual pages iskra.1 and iskra-scene.5 from their templates
# (man/iskra.1.in, man/iskra-scene.5.in) and the iskra program, so they
# cannot drift from what the program does:
#     .\" commands   one subsection per command of `iskra --help`: its
#                   summary, then its `iskra COMMAND --help` text
#     .\" keys       `iskra keys --man`: every section and key of the key
#                   table (src/scene/keys.c)
#     @VERSION@      the version `iskra --version` prints
# usage: tools/gen_man.sh [ISKRA] [OUTDIR]
#   ISKRA   the iskra program (default build/bin/iskra)
#   OUTDIR  where to write the pages (default man, next to the templates)
# `make man` runs it; tests/test_man_pages.c runs it into a scratch
# directory and fails when the pages differ from the committed ones.
set -eu
bin=${1:-build/bin/iskra}
out=${2:-man}
mkdir -p "$out"
version=$("$bin" --version | sed 's/^iskra //')

# roff TEXT...: text as roff lines, as `iskra keys --man` escapes it:
# backslashes as \e, '-' as \- (options and names are typed), a leading
# '.' or "'" made text.
roff() {
    sed -e 's/\\/\\e/g' -e 's/-/\\-/g' -e "s/^\\([.']\\)/\\\\\\&\\1/"
}

# The commands' subsections: "  NAME  summary" lines of `iskra --help`.
commands() {
    "$bin" --help | sed -n '/^commands:$/,/^$/p' | sed -n 's/^  \([a-z][a-z]*\)  *\(.*\)$/\1 \2/p' |
        while read -r name summary; do
            printf '.SS "iskra %s"\n' "$name"
            printf '%s\n' "$summary" | awk '{ print toupper(substr($0, 1, 1)) substr($0, 2) "." }' | roff
            printf '.PP\n.nf\n'
            "$bin" "$name" --help | roff
            printf '.fi\n'
        done
}

# page TEMPLATE OUT: the template with its markers replaced.
page() {
    tmp="$2.tmp.$$"
    trap 'rm -f "$tmp"' EXIT
    while IFS= read -r line; do
        case $line in
        '.\" commands') commands ;;
        '.\" keys') "$bin" keys --man ;;
        *) printf '%s\n' "$line" | sed "s/@VERSION@/$version/g" ;;
        esac
    done <"$1" >"$tmp"
    mv "$tmp" "$2"
    trap - EXIT
}

page man/iskra.1.in "$out/iskra.1"
page man/iskra-scene.5.in "$out/iskra-scene.5"
