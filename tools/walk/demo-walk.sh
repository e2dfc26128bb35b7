#!/bin/sh
# `make demo-walk`: a real foot-mounted walk (x-io NGIMU, ~400 Hz, 41.6 s, a
# closed loop of ~25 m; tools/data/xio-gait-tracking) imported from its CSV
# into an LCM IMU log (se23-import, with its hygiene counters), run through
# the library's filter with the pedestrian preset (se23-ins --preset foot:
# alignment at the first rest, ZUPT at stance, ZARU at rest, the floor
# level at each stance, no GNSS), in double and in float (se23-ins-float:
# the Cortex-M4F precision), then se23-walk: loop-closure error, distance,
# stance phases, plots; last, the closure of the same filter without the
# floor assumption (--floor-sigma 0), for comparison.
#
#   sh tools/walk/demo-walk.sh HARNESS_BUILD_DIR [MAX_CLOSURE_M]
#
# With MAX_CLOSURE_M (make check), exits 1 if either precision's 3D closure
# error exceeds it.
set -eu
H=${1:-build/harness}
MAX=${2:-}
BIN="$H/bin"
RUN="$H/walk"
CSV=tools/data/xio-gait-tracking/short_walk.csv
mkdir -p "$RUN"
rm -f "$RUN/imu.log" "$RUN/ins.log" "$RUN/ins-float.log"
echo "== se23 demo-walk: $CSV (x-io NGIMU on a foot, closed loop)"
"$BIN/se23-import" --out "file://$RUN/imu.log?mode=w" "$CSV" >"$RUN/import.txt"
echo "   import: $(head -1 "$RUN/import.txt")"
# shellcheck disable=SC2086 # $3 (extra options) splits on purpose
ins_run() {
    "$BIN/$1" --preset foot --imu-rate 400 --lat 51.45 --nav-rate 400 ${3:-} \
        --in "file://$RUN/imu.log?speed=0" --out "file://$RUN/$2.log?mode=w" >"$RUN/$2-summary.txt"
}
ins_run se23-ins ins
ins_run se23-ins-float ins-float
ins_run se23-ins ins-nofloor "--floor-sigma 0"
floor=$(awk '$1 == "floor_used" { u = $2 } $1 == "floor_levels" { l = $2 }
             END { printf "%s stance updates, %s level(s)", u, l }' "$RUN/ins-summary.txt")
echo
"$BIN/se23-walk" --plots "$RUN/plots" --plot-script tools/walk/plot_walk.py \
    ${MAX:+--max-closure "$MAX"} "$RUN/ins.log"
echo "  floor              $floor"
echo
echo "   float (se23-ins-float, the M4F precision):"
"$BIN/se23-walk" ${MAX:+--max-closure "$MAX"} "$RUN/ins-float.log" | grep -E "closure|stance"
echo
echo "   without the floor assumption (--floor-sigma 0), double:"
"$BIN/se23-walk" --csv "$RUN/plots/walk-nofloor.csv" "$RUN/ins-nofloor.log" |
    grep -E "closure error|1-sigma"
echo
echo "   filter accounting: $RUN/{ins,ins-float,ins-nofloor}-summary.txt; import: $RUN/import.txt"
