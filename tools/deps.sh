#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs the Debian packages iskra needs that are missing; does nothing
# when all are present.  Usage: tools/deps.sh PKG...   (called by `make deps`)
set -eu
command -v dpkg-query >/dev/null 2>&1 || {
    echo "deps: not a Debian system; make sure these are installed: $*" >&2
    exit 0
}
missing=""
for p in "$@"; do
    st=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
    case "$st" in
        *"install ok installed"*) ;;
        *) missing="$missing $p" ;;
    esac
done
[ -z "$missing" ] && exit 0
echo "deps: installing$missing"
SUDO=""
if [ "$(id -u)" != 0 ]; then
    command -v sudo >/dev/null 2>&1 || { echo "deps: need root (or sudo) to install:$missing" >&2; exit 1; }
    SUDO=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq --no-install-recommends $missing
