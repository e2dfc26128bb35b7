#!/bin/sh
# qemu-run.sh BOARD IMAGE [QEMU ARGS...]: runs a Cortex-M image on QEMU's
# BOARD (mps2-an386, mps2-an500) with semihosting for stdio and exit status.
# Exits with the image's exit status (the target images return their number
# of failures); 124 if it hangs past $QEMU_TIMEOUT seconds (default 120).
set -u
board=$1
image=$2
shift 2
timeout "${QEMU_TIMEOUT:-120}" "${QEMU_ARM:-qemu-system-arm}" -M "$board" \
    -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native "$@" -kernel "$image"
rc=$?
echo "$(basename "$image") on $board: exit $rc"
exit $rc
