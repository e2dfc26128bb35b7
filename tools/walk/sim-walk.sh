#!/bin/sh
# The walk's simulated twin: se23-sim's "walk" scenario (a foot-mounted
# IMU, 16 strides of 1.4 m closing a 22.4 m circle, 5 s at rest before and
# after; tools/sim/traj.c) with the mems error profile at 400 Hz, run
# through the same filter and preset as make demo-walk. The truth closes
# the loop exactly, so the closure error is the filter's alone. Each run
# may rotate the simulated accelerometer's triad against the gyroscope's
# (se23-sim --accel-misalign): what a misalignment does to a walk whose
# every other error is in the filter's model.
#
#   sh tools/walk/sim-walk.sh HARNESS_BUILD_DIR [RX,RY,RZ ...]
#
# Each rotation vector in degrees, body frame FRD (y is the axis the foot
# pitches about); default: none, 0.25 and 0.5 about y, -0.5 about y, 0.5
# about x and about z. SEED (environment, default 1) seeds the sensor
# errors. Prints one line per vector: the 3D / horizontal / vertical
# closure, its normalised error against the filter's covariance (3 dof)
# and the mean NIS of the live ZUPTs; then (walk only) plots the height
# of each stance of every run, and of the real walk (without and with the
# floor) if make demo-walk has run (tools/walk/plot_twin.py; PYTHON,
# default /usr/bin/python3 with matplotlib), into
# HARNESS_BUILD_DIR/walk-sim/twin_heights.png. INS_OPTS:
# more se23-ins options (e.g. --floor-sigma 0.01: the filter with the floor).
# SCENARIO=stairs: the same walk on a stepped path (8 strides up a 0.15 m
# riser each, 8 down; the foot's truth at each stance is on a new level).
set -eu
H=${1:-build/harness}
[ $# -gt 0 ] && shift
BIN="$H/bin"
RUN="$H/walk-sim"
VECTORS=${*:-"0,0,0 0,0.25,0 0,0.5,0 0,-0.5,0 0.5,0,0 0,0,0.5"}
mkdir -p "$RUN"
REAL="$H/walk/plots/walk.csv"
REAL_FLOOR="$H/walk/plots/walk-floor.csv"
set --
[ -f "$REAL" ] && set -- "real walk (make demo-walk)=$REAL"
[ -f "$REAL_FLOOR" ] && set -- "$@" "real walk with the floor=$REAL_FLOOR"
echo "== se23 walk-sim: the simulated ${SCENARIO:-walk} (mems at 400 Hz, seed ${SEED:-1}, double, preset foot ${INS_OPTS:-})"
printf '%-16s %8s %8s %8s %10s %9s\n' "misalign [deg]" "3D [m]" "horiz" "vert" "norm. err" "ZUPT NIS"
for r in $VECTORS; do
    "$BIN/se23-sim" --scenario "${SCENARIO:-walk}" --imu-rate 400 --imu mems --earth off --lat 51.45 \
        --gnss-rate 0 --init-sigma 0,0,0 --seed "${SEED:-1}" --accel-misalign "$r" \
        --url "file://$RUN/sim.log?mode=w"
    # shellcheck disable=SC2086 # INS_OPTS splits into options on purpose
    "$BIN/se23-ins" --preset foot --imu-rate 400 --lat 51.45 --nav-rate 400 ${INS_OPTS:-} \
        --in "file://$RUN/sim.log?speed=0" --out "file://$RUN/ins.log?mode=w" >"$RUN/summary.txt"
    nis=$(awk '$1 == "zupt_nis_mean" { print $2 }' "$RUN/summary.txt")
    "$BIN/se23-walk" --csv "$RUN/walk-$r.csv" "$RUN/ins.log" >"$RUN/walk.txt"
    set -- "$@" "twin, accelerometer rotated by $r deg=$RUN/walk-$r.csv"
    awk -v r="$r" -v nis="$nis" '
        $1 == "closure" && $2 == "error" { c3 = $3; ch = $6; cv = $9 }
        /normalised closure error/ { for (i = 1; i <= NF; i++) if ($i == "error") ne = $(i + 1) }
        END { printf "%-16s %8s %8s %8s %10s %9s\n", r, c3, ch, cv, ne, nis }' "$RUN/walk.txt"
done
if [ "${SCENARIO:-walk}" != walk ]; then
    echo "   plot: only for the walk (its stances' true height is 0 throughout)"
elif "${PYTHON:-/usr/bin/python3}" tools/walk/plot_twin.py --out "$RUN/twin_heights.png" "$@"; then
    echo "   plot: $RUN/twin_heights.png"
else
    echo "   plot: failed (needs ${PYTHON:-/usr/bin/python3} with matplotlib)"
fi
