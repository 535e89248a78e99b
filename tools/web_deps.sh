#!/bin/sh
# SPDX-License-Identifier: MIT
# Builds the C libraries iskra links with (zlib, libpng, giflib) for the
# browser (wasm32-wasi), from Debian's own source packages, with Debian's
# patches applied: the web build then writes PNG and GIF files with the
# very code, and so the very bytes, of the native build.  Called by `make
# web`; does nothing when DIR is complete.
#
#   tools/web_deps.sh DIR CC [CFLAGS...]
#
# DIR/include and DIR/lib get the headers and static libraries.  The
# source packages come through apt from the machine's own Debian mirror
# (its "deb" lines, read as "deb-src"), with apt's state kept in DIR/apt:
# nothing is installed on the system.  libinih is not among them: Debian's
# mirror may lack its source, and its one file is in third_party/inih.
set -eu
[ $# -ge 2 ] || { echo "usage: $0 DIR CC [CFLAGS...]" >&2; exit 2; }
dir=$1
cc=$2
shift 2
cflags="$*"
pkgs="zlib libpng1.6 giflib"
stamp="$dir/.complete"
want="$pkgs | $cc $cflags"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then
    exit 0
fi
for tool in apt-get dpkg-source llvm-ar; do
    command -v $tool >/dev/null 2>&1 || { echo "web: needs $tool" >&2; exit 1; }
done
echo "web: building zlib, libpng and giflib for wasm32 from Debian's sources into $dir (once)"
rm -rf "$dir"
mkdir -p "$dir/apt/lists/partial" "$dir/apt/archives/partial" "$dir/src" "$dir/include" "$dir/lib" "$dir/obj"
abs=$(cd "$dir" && pwd)
: >"$abs/apt/status"

# The machine's Debian mirror (its first "deb" address that is not the
# security suite's) and release, as one source line.  The security suite's
# sources are not read: mirrors often lack them, and its fixes do not change
# what these libraries write.
mirror=$(cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources 2>/dev/null |
    sed -n -e 's/^[[:space:]]*deb[[:space:]]\{1,\}\(\[[^]]*\][[:space:]]*\)\{0,1\}\([^[:space:]]*\).*/\2/p' \
        -e 's/^URIs:[[:space:]]*\([^[:space:]]*\).*/\1/p' | grep -v security | grep -i debian | head -n 1)
release=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
[ -n "$mirror" ] && [ -n "$release" ] || { echo "web: no Debian mirror or release found in /etc/apt and /etc/os-release" >&2; exit 1; }
list="$abs/apt/sources.list"
echo "deb-src $mirror $release main" >"$list"
set -- -o "Dir::Etc::SourceList=$list" -o "Dir::Etc::SourceParts=$abs/apt/none" \
    -o "Dir::State::Lists=$abs/apt/lists" -o "Dir::State::status=$abs/apt/status" \
    -o "Dir::Cache=$abs/apt" -o "APT::Sandbox::User=$(id -un)"
if ! apt-get -q "$@" update >"$abs/apt/update.log" 2>&1; then
    grep -E '^(E|W|Err):' "$abs/apt/update.log" | sed 's/^/web: apt-get update: /' >&2
    ls "$abs"/apt/lists/*Sources* >/dev/null 2>&1 || {
        echo "web: no source package list could be fetched (log: $dir/apt/update.log)" >&2
        exit 1
    }
fi
# shellcheck disable=SC2086
(cd "$abs/src" && apt-get -q "$@" source --download-only $pkgs >"$abs/apt/source.log" 2>&1) || {
    tail -n 20 "$abs/apt/source.log" >&2
    exit 1
}
for dsc in "$abs"/src/*.dsc; do
    name=$(basename "$dsc" .dsc)
    (cd "$abs/src" && dpkg-source --no-check -x "$(basename "$dsc")" "${name%%_*}" >/dev/null)
done

# Each library: its sources (the library's own, no programs), compiled and
# archived; its public headers copied.
build() {
    lib=$1 srcdir=$2 extra=$3
    shift 3
    objs=""
    for c in "$@"; do
        o="$abs/obj/$lib-$c.o"
        # shellcheck disable=SC2086
        $cc $cflags $extra -I"$abs/include" -c "$srcdir/$c.c" -o "$o"
        objs="$objs $o"
    done
    # shellcheck disable=SC2086
    llvm-ar rcs "$abs/lib/lib$lib.a" $objs
}
z="$abs/src/zlib"
cp "$z/zlib.h" "$z/zconf.h" "$abs/include/"
build z "$z" "-w -DHAVE_UNISTD_H" adler32 compress crc32 deflate infback inffast inflate inftrees trees uncompr zutil
p="$abs/src/libpng1.6"
# wasm has no setjmp: libpng's configuration without it (and without the
# simplified API, which needs it); iskra's PNG writer does not use that API.
grep -v -e 'PNG_SETJMP_SUPPORTED' -e 'PNG_SIMPLIFIED_' "$p/scripts/pnglibconf.h.prebuilt" >"$abs/include/pnglibconf.h"
cp "$p/png.h" "$p/pngconf.h" "$abs/include/"
build png "$p" "-w" png pngerror pngget pngmem pngpread pngread pngrio pngrtran pngrutil pngset pngtrans \
    pngwio pngwrite pngwtran pngwutil
g="$abs/src/giflib"
cp "$g/gif_lib.h" "$abs/include/"
build gif "$g" "-w" dgif_lib egif_lib gif_err gif_font gif_hash gifalloc openbsd-reallocarray quantize
echo "$want" >"$stamp"
