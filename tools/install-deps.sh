#!/bin/sh
# Installs the Debian packages listed in tools/debian-packages.txt that are
# not installed yet, as root or through sudo. Does nothing when all are
# present. Needs nothing but sh and apt (no make: it bootstraps make too).
#
#   sh tools/install-deps.sh [BUILD_DIR]     (make passes its build folder)
#
# Says what is missing and what it will cost (apt's own figures) before
# anything is downloaded; apt's output goes to BUILD_DIR/deps/apt.log and
# the screen shows one progress line (redrawn on a terminal, a plain line
# every 15 s in a log). Without root or sudo it prints the command to run.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
list="$here/debian-packages.txt"
logdir="${1:-build}/deps"
log="$logdir/apt.log"

missing=""
for pkg in $(grep -v '^#' "$list" | tr -s ' \n' ' '); do
    if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed'; then
        missing="$missing $pkg"
    fi
done
[ -z "$missing" ] && exit 0
apt_install="apt-get install -y --no-install-recommends$missing"

if [ "$(id -u)" -eq 0 ]; then
    sudo=""
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    sudo="sudo"
elif command -v sudo >/dev/null 2>&1 && [ -t 0 ]; then
    sudo="sudo" # asks for the password once
else
    echo "install-deps: missing Debian packages:$missing" >&2
    echo "install-deps: no root and no sudo here; as root, run:" >&2
    echo "    apt-get update && $apt_install" >&2
    exit 1
fi

mkdir -p "$logdir"
: >"$log"
export DEBIAN_FRONTEND=noninteractive

# progress TEXT: one line, redrawn in place on a terminal.
progress() {
    if [ -t 1 ]; then
        printf '\rinstall-deps: %-60s' "$1"
    else
        echo "install-deps: $1"
    fi
}

# watch PID TOTAL: while PID runs, the packages downloaded (files in apt's
# archive cache) and unpacked (in the log) out of TOTAL.
watch() {
    period=2
    [ -t 1 ] || period=15
    while sleep "$period" && kill -0 "$1" 2>/dev/null; do
        unpacked=$(grep -c '^Unpacking ' "$log" || true)
        if [ "$unpacked" -eq 0 ]; then
            got=$(grep -c '^Get:' "$log" || true)
            progress "downloading: $got of $2 packages"
        else
            progress "installing: $unpacked of $2 packages unpacked"
        fi
    done
}

echo "install-deps: missing:$missing"
echo "install-deps: updating the package lists (log: $log)"
$sudo apt-get update >>"$log" 2>&1 || {
    echo "install-deps: apt-get update failed; see $log" >&2
    exit 1
}
# apt's own figures, before anything is downloaded.
# shellcheck disable=SC2086
plan=$(apt-get install --print-uris --no-install-recommends $missing 2>>"$log") || {
    echo "install-deps: apt cannot install:$missing; see $log" >&2
    exit 1
}
total=$(echo "$plan" | sed -n 's/.* \([0-9]*\) newly installed.*/\1/p')
echo "install-deps: $total packages with their dependencies:" \
    "$(echo "$plan" | sed -n 's/^Need to get \(.*\) of archives\./download \1,/p')" \
    "$(echo "$plan" | sed -n 's/^After this operation, \(.*\) of additional disk space.*/\1 on disk/p')"

# shellcheck disable=SC2086
$sudo $apt_install >>"$log" 2>&1 &
pid=$!
watch "$pid" "$total" &
watcher=$!
rc=0
wait "$pid" || rc=$?
kill "$watcher" 2>/dev/null || true
[ -t 1 ] && echo
if [ "$rc" -ne 0 ]; then
    echo "install-deps: apt-get install failed (status $rc); the end of $log:" >&2
    tail -n 20 "$log" >&2
    exit 1
fi
echo "install-deps: done, $total packages installed"
