#!/bin/sh
# `make walk CSV=... [IMPORT="..."] [LAT=...]` (and `make demo-walk`, the
# x-io walk): a foot-mounted recording from its CSV through the library's
# pedestrian filter, in one line.
#  1. se23-import: the column mapping and units of IMPORT (se23-import
#     options; none reads x-io's CSV), the rate measured from the
#     timestamps (or --time-col 0 --rate HZ for a file without them), the
#     unit checks; the rate travels in the log;
#  2. se23-ins --preset foot at the log's rate, in double, and se23-ins-float
#     (the Cortex-M4F precision);
#  3. se23-walk: distance, stances, the closure at the start of the last
#     stance and at the end with the filter's normalised error, plots;
#  4. the same filter with the floor assumption (--floor-sigma 0.01), for
#     comparison, and the samples beyond the sensor's range.
#
#   sh tools/walk/walk.sh HARNESS_BUILD_DIR RUN_DIR CSV [MAX_CLOSURE_M]
#
# LAT: latitude [deg] for gravity (45). With MAX_CLOSURE_M, exits 1 if a
# precision's 3D closure error exceeds it.
set -eu
H=$1
RUN=$2
CSV=$3
MAX=${4:-}
BIN="$H/bin"
mkdir -p "$RUN"
rm -f "$RUN/imu.log" "$RUN/ins.log" "$RUN/ins-float.log" "$RUN/ins-floor.log"
echo "== se23 walk: $CSV"
# shellcheck disable=SC2086 # IMPORT splits into options on purpose
if ! "$BIN/se23-import" --out "file://$RUN/imu.log?mode=w" ${IMPORT:-} "$CSV" \
    >"$RUN/import.txt" 2>"$RUN/import-errors.txt"; then
    cat "$RUN/import-errors.txt" >&2
    echo "se23 walk: the import refused $CSV (options: ${IMPORT:-none})" >&2
    exit 1
fi
echo "   import: $(head -1 "$RUN/import.txt")"
grep -E "nominal interval|unit check" "$RUN/import.txt" | sed 's/^se23-import: /   /'
# shellcheck disable=SC2086 # $3 (extra options) splits on purpose
ins_run() {
    "$BIN/$1" --preset foot --lat "${LAT:-45}" --nav-rate 100000 ${3:-} \
        --in "file://$RUN/imu.log?speed=0" --out "file://$RUN/$2.log?mode=w" >"$RUN/$2-summary.txt"
}
ins_run se23-ins ins
ins_run se23-ins-float ins-float
ins_run se23-ins ins-floor "--floor-sigma 0.01"
echo
"$BIN/se23-walk" --plots "$RUN/plots" --plot-script tools/walk/plot_walk.py \
    ${MAX:+--max-closure "$MAX"} "$RUN/ins.log"
awk '$1 == "imu_range" { r = $2 }
     END { printf "  sensor range       %s sample(s) beyond it%s\n", r,
           (r > 0) ? " (FLAGGED: refused one by one, each bridged by the next sample)" : "" }' \
    "$RUN/ins-summary.txt"
echo
echo "   float (se23-ins-float, the M4F precision):"
"$BIN/se23-walk" ${MAX:+--max-closure "$MAX"} "$RUN/ins-float.log" | grep -E "closure|at the end"
echo
floor=$(awk '$1 == "floor_used" { u = $2 } $1 == "floor_levels" { l = $2 }
             END { printf "%s stance updates, %s level(s)", u, l }' "$RUN/ins-floor-summary.txt")
echo "   with the floor assumption (--floor-sigma 0.01; $floor), double:"
"$BIN/se23-walk" --csv "$RUN/plots/walk-floor.csv" "$RUN/ins-floor.log" |
    grep -E "closure error|1-sigma|at the end"
echo
echo "   filter accounting: $RUN/{ins,ins-float,ins-floor}-summary.txt; import: $RUN/import.txt"
