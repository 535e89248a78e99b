#!/bin/sh
# SPDX-License-Identifier: MIT
# Fetches Debian's i386 builds of the libraries iskra links with into a
# directory of the build, for `make test M32=1` (called by `make deps
# M32=1`; does nothing when the directory is complete).
#
#   tools/m32_sysroot.sh DIR RUNTIME_PKGS -- DEV_PKGS
#
# DIR/root gets the files of the runtime packages and of every library they
# need (the i386 C library, libgcc and libstdc++ excepted: those are the
# multilib compiler's, /usr/lib32), and of the -dev packages (headers,
# .pc files, the libX.so links); nothing is installed on the system.
#
# Why not `dpkg --add-architecture i386` and `apt-get install libpng-dev:i386
# ...`: a multiarch library must be of the very same version on both
# architectures, and a machine's amd64 libraries come from the security
# suite.  When the mirror's i386 index of that suite cannot be read (it
# happens: "File has unexpected size ... Mirror sync in progress?"), apt
# has older i386 versions only and refuses the whole install (libgit2,
# pcre2 and libssh2 were so on Debian 12).  Here versions need not match:
# these files are linked with and loaded only by the build's programs
# (through their rpath), and the package lists are the directory's own
# (DIR/apt), fetched with apt's ordinary client for i386 alone, so an index
# that fails to download is only a warning.
set -eu
[ $# -ge 2 ] || { echo "usage: $0 DIR RUNTIME_PKGS -- DEV_PKGS" >&2; exit 2; }
dir=$1; shift
runtime=""
while [ $# -gt 0 ] && [ "$1" != -- ]; do runtime="$runtime $1"; shift; done
[ $# -gt 0 ] && shift
dev="$*"

stamp="$dir/root/.complete"
want="$runtime -- $dev"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then
    exit 0
fi
for tool in apt-get apt-cache dpkg-deb; do
    command -v $tool >/dev/null 2>&1 || { echo "m32: needs $tool (a Debian system)" >&2; exit 1; }
done

echo "m32: fetching Debian's i386 libraries into $dir (once: about 15 MB, 40 MB unpacked)"
rm -rf "$dir/root" "$dir/debs"
mkdir -p "$dir/apt/lists/partial" "$dir/apt/archives/partial" "$dir/debs" "$dir/root"
: >"$dir/apt/status"
abs=$(cd "$dir" && pwd)
# apt's own state in DIR/apt, for i386 alone; downloads as the caller
# (root's _apt sandbox user cannot write into a build directory).
set -- -o "APT::Architecture=i386" -o "APT::Architectures::=i386" \
    -o "Dir::State::Lists=$abs/apt/lists" -o "Dir::State::status=$abs/apt/status" \
    -o "Dir::Cache=$abs/apt" -o "Dir::Cache::archives=$abs/apt/archives" \
    -o "APT::Sandbox::User=$(id -un)"
if ! apt-get -q "$@" update >"$dir/apt/update.log" 2>&1; then
    # an index that failed (a mirror mid-sync) leaves the others usable
    grep -E '^(E|W|Err):' "$dir/apt/update.log" | sed 's/^/m32: apt-get update: /' >&2
    ls "$dir"/apt/lists/*_main_binary-i386_Packages* >/dev/null 2>&1 || {
        echo "m32: no i386 package list could be fetched (log: $dir/apt/update.log)" >&2
        exit 1
    }
    echo "m32: going on with the package lists that were fetched" >&2
fi

# The runtime packages and every library they need, recursively (the
# names apt-cache prints unindented; <virtual> ones have no files).
# shellcheck disable=SC2086
closure=$(apt-cache "$@" depends --recurse --no-recommends --no-suggests --no-conflicts --no-breaks \
    --no-replaces --no-enhances $runtime | grep -E '^(lib|zlib)' | sed 's/:i386$//' |
    grep -vxE 'libc6|libgcc-s1|libstdc\+\+6' | sort -u)
# shellcheck disable=SC2086
(cd "$dir/debs" && apt-get -q "$@" download $closure $dev >"$abs/apt/download.log" 2>&1) || {
    tail -n 20 "$dir/apt/download.log" >&2
    exit 1
}
for deb in "$dir"/debs/*.deb; do
    dpkg-deb -x "$deb" "$dir/root"
done
# A -dev package's absolute links (libz.so -> /lib/i386-linux-gnu/...)
# point into the directory instead.
find "$dir/root" -type l | while read -r link; do
    target=$(readlink "$link")
    case $target in /*) ln -sfn "$abs/root$target" "$link" ;; esac
done
# the package lists and apt's caches are not needed again (the logs stay)
rm -rf "$dir/debs" "$dir/apt/lists" "$dir/apt/archives" "$dir"/apt/*.bin
echo "$want" >"$stamp"
# shellcheck disable=SC2086
set -- $closure $dev
echo "m32: $# packages in $dir/root"
