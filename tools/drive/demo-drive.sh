#!/bin/sh
# `make demo-drive`: the shipped car drive (tools/data/car/
# rtklibexplorer-drive-0708: roof IMU at 100 Hz, RTK fixes at 4 Hz, 9 min,
# 4 km) through the library's car preset (se23-ins --preset car), in double
# and in float (se23-ins-float, the Cortex-M4F precision):
#  1. with every fix: the error against the RTK truth, its NEES, plots;
#  2. GNSS outages of 10, 30 and 60 s, one every length + 40 s from 60 s
#     after the first fix (the car then drives straight, turns, stops and
#     starts inside them), each run with the non-holonomic constraint (the
#     preset's) and without it (--nhc-sigma 0): the horizontal error at the
#     end of each outage against the distance driven in it, and its NEES;
#  3. one table over all runs (tools/drive/summary.py) and a plot of the
#     error growth.
#
#   sh tools/drive/demo-drive.sh HARNESS_BUILD_DIR
#
# Writes HARNESS_BUILD_DIR/drive/ (logs, CSVs, plots, summary.txt).
set -eu
H=${1:-build/harness}
BIN="$H/bin"
RUN="$H/drive"
DATA=tools/data/car/rtklibexplorer-drive-0708
. tools/drive/rtklibexplorer-0708.conf
mkdir -p "$RUN"
rm -f "$RUN"/*.log "$RUN"/*.csv "$RUN"/*.txt

# drive_import NAME [OUTAGE OPTIONS]: the drive into NAME.log
drive_import() {
    name=$1
    shift
    "$BIN/se23-drive-import" --rtklib "$DATA/imu_1934.csv" "$DATA/imu_1934.csv.tag" \
        "$DATA/gnss_1934_sf.pos" --axes="$AXES" --imu-time-offset "$IMU_TIME_OFFSET" "$@" \
        --out "file://$RUN/$name.log?mode=w" >"$RUN/$name-import.txt" 2>&1 || {
        cat "$RUN/$name-import.txt" >&2
        exit 1
    }
}
# drive_run LOG INS NAME [OPTIONS]: LOG through INS (se23-ins or
# se23-ins-float) into NAME.log, scored by se23-drive into NAME.csv
drive_run() {
    log=$1 ins=$2 name=$3
    shift 3
    "$BIN/$ins" --preset car --lat "$LAT" --height "$HEIGHT" --mount "$MOUNT" --lever "$LEVER" --nav-rate 100 "$@" \
        --in "file://$RUN/$log.log?speed=0" --out "file://$RUN/$name.log?mode=w" \
        >"$RUN/$name-ins.txt" 2>&1
    "$BIN/se23-drive" --lever "$LEVER" --label "$name" --csv "$RUN/$name.csv" \
        "$RUN/$log.log" "$RUN/$name.log" >"$RUN/$name-report.txt" 2>&1
}

echo "== se23 drive: $DATA (RTK truth), car preset, lever $LEVER m, mount $MOUNT deg"
drive_import aided
for len in 10 30 60; do
    set --
    s=60
    while [ $((s + len)) -le 520 ]; do
        set -- "$@" --outage "$s,$len"
        s=$((s + len + 40))
    done
    drive_import "o$len" "$@"
done
for p in double float; do
    ins=se23-ins
    [ $p = float ] && ins=se23-ins-float
    printf '   %s: aided' $p
    drive_run aided $ins "aided-$p"
    for len in 10 30 60; do
        printf ', %s s outages' $len
        drive_run "o$len" $ins "o$len-nhc-$p"
        drive_run "o$len" $ins "o$len-none-$p" --nhc-sigma 0
    done
    echo
done
echo
/usr/bin/python3 tools/drive/summary.py --plot "$RUN/drive_outages.png" "$RUN" | tee "$RUN/summary.txt"
"$BIN/se23-drive" --lever "$LEVER" --plots "$RUN/plots" "$RUN/o30.log" "$RUN/o30-nhc-double.log" \
    >/dev/null 2>&1 || true
echo "   plots: $RUN/drive_outages.png, $RUN/plots/ (the 30 s outages, double);" \
    "per-run reports: $RUN/*-report.txt"
