#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs the Debian packages iskra needs that are missing; does nothing
# when all are present.  Usage: tools/deps.sh PKG...   (called by `make deps`)
#
# Another apt-get or dpkg at work (a fresh cloud machine runs its
# unattended upgrades at first boot) holds apt's locks: this waits for it,
# saying which process it waits for, up to ISKRA_DEPS_LOCK_WAIT seconds
# (default 900), then stops with a message.  An `apt-get update` that
# fails for another reason (a mirror mid-sync) is a warning: the install
# is tried with the package lists there are.
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

wait_max=${ISKRA_DEPS_LOCK_WAIT:-900}
case $wait_max in '' | *[!0-9]*) echo "deps: ISKRA_DEPS_LOCK_WAIT: seconds, a whole number, not '$wait_max'" >&2; exit 2 ;; esac
deadline=$(($(date +%s) + wait_max))
log=$(mktemp)
trap 'rm -f "$log"' EXIT

# apt_retry CMD...: runs an apt-get command; while it fails because another
# process holds one of apt's locks (apt says "Could not get lock FILE. It
# is held by process PID (NAME)", or "Unable to lock directory ..."), waits
# and runs it again, until the deadline.  Its messages are in English
# (LC_ALL=C) so that they can be recognised; they are shown after it ends.
# Exit status: the command's (gave_up is set when the wait ran out).
gave_up=""
apt_retry() {
    said=""
    while :; do
        rc=0
        LC_ALL=C "$@" 2>"$log" || rc=$?
        held=$(grep -E 'Could not get lock|Unable to acquire the dpkg frontend lock|Unable to lock' "$log" | head -n 1 || true)
        if [ "$rc" -eq 0 ] || [ -z "$held" ]; then
            cat "$log" >&2
            return "$rc"
        fi
        held=${held#E: }
        now=$(date +%s)
        if [ "$now" -ge "$deadline" ]; then
            echo "deps: gave up after waiting $wait_max s for another package manager: $held" >&2
            echo "deps: run 'make deps' again when it has finished (ISKRA_DEPS_LOCK_WAIT=SECONDS waits longer)" >&2
            gave_up=1
            return "$rc"
        fi
        if [ "$held" != "$said" ]; then
            echo "deps: another package manager is at work ($held); waiting for it, at most $((deadline - now)) s more" >&2
            said=$held
        fi
        sleep 5
    done
}

if ! apt_retry $SUDO apt-get update -qq; then
    [ -z "$gave_up" ] || exit 1
    echo "deps: apt-get update failed (above); trying the install with the package lists there are" >&2
fi
# shellcheck disable=SC2086
apt_retry $SUDO apt-get install -y -qq --no-install-recommends $missing
