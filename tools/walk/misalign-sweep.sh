#!/bin/sh
# The walk's closure against a misalignment of the accelerometer's triad
# relative to the gyroscope's (se23-import --accel-misalign): a sensitivity
# study, not a calibration; the preset and make demo-walk use none.
#
#   [INS_OPTS=...] sh tools/walk/misalign-sweep.sh HARNESS_BUILD_DIR [RX,RY,RZ ...]
#
# INS_OPTS: more se23-ins options (make walk-misalign: none; --floor-sigma
# 0.01 adds the floor, which hides the vertical drift the study explains).
# Each rotation vector in degrees (default: +-0.5 and +-1 about each axis);
# prints one line per vector: the 3D / horizontal / vertical closure and
# the mean NIS of the live ZUPTs (se23-ins's zupt_nis_mean), the walk's
# own verdict on the rotation.
set -eu
H=${1:-build/harness}
[ $# -gt 0 ] && shift
BIN="$H/bin"
RUN="$H/walk-misalign"
CSV=tools/data/xio-gait-tracking/short_walk.csv
VECTORS=${*:-"0,0,0 -1,0,0 -0.5,0,0 0.5,0,0 1,0,0 0,-1,0 0,-0.5,0 0,0.5,0 0,1,0 0,0,-1 0,0,-0.5 0,0,0.5 0,0,1"}
mkdir -p "$RUN"
echo "== se23 walk: closure against an accelerometer misalignment (double, preset foot ${INS_OPTS:-})"
printf '%-16s %8s %8s %8s %9s\n' "misalign [deg]" "3D [m]" "horiz" "vert" "ZUPT NIS"
for r in $VECTORS; do
    "$BIN/se23-import" --accel-misalign "$r" --out "file://$RUN/imu.log?mode=w" "$CSV" >/dev/null
    # shellcheck disable=SC2086 # INS_OPTS splits into options on purpose
    "$BIN/se23-ins" --preset foot --lat 51.45 --nav-rate 100000 ${INS_OPTS:-} \
        --in "file://$RUN/imu.log?speed=0" --out "file://$RUN/ins.log?mode=w" >"$RUN/summary.txt"
    nis=$(awk '$1 == "zupt_nis_mean" { print $2 }' "$RUN/summary.txt")
    "$BIN/se23-walk" "$RUN/ins.log" | sed -n 's/^  closure error *\([0-9.]*\) m 3D, \([0-9.]*\) m horizontal, \([0-9.]*\) m vertical$/\1 \2 \3/p' |
        while read -r c3 ch cv; do printf '%-16s %8s %8s %8s %9s\n' "$r" "$c3" "$ch" "$cv" "$nis"; done
done
