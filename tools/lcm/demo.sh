#!/bin/sh
# `make demo`: a simulated UAV flight (MEMS IMU at 200 Hz, Earth rotation on,
# GNSS at 5 Hz from an antenna on a lever arm, its fixes 100 ms late, 10 s
# at rest before the 60 s of flight) published over LCM by se23-sim into a
# file:// log, streamed through se23-ins (the library's filter, se23/ins.h:
# the lever arm, the late fixes fused at their own time, zero-velocity
# updates while at rest; it publishes its navigation state with the 15x15
# covariance into a second LCM log), then se23-report: table + plots.
#
#   sh tools/lcm/demo.sh HARNESS_BUILD_DIR      (make demo passes build/harness)
#
# Environment: DEMO_SEED (1), DEMO_SCENARIO (uav), DEMO_IMU (mems),
# DEMO_DURATION (scenario default, 60 s for uav).
set -eu
H=${1:-build/harness}
BIN="$H/bin"
RUN="$H/demo"
SEED=${DEMO_SEED:-1}
LEVER=0.4,-0.2,-0.6   # GNSS antenna, body frame FRD [m]
LATENCY=0.1           # GNSS fix latency [s]
REST=10               # stationary start [s]
SCEN=${DEMO_SCENARIO:-uav}
IMU=${DEMO_IMU:-mems}
DUR=${DEMO_DURATION:-}
mkdir -p "$RUN"
rm -f "$RUN/sim.log" "$RUN/ins.log"
start=$(date +%s)

echo "== se23 demo: $SCEN flight, $IMU IMU at 200 Hz, Earth rotation on, GNSS 5 Hz (seed $SEED)"
echo "   antenna lever arm $LEVER m, fixes ${LATENCY} s late, ${REST} s at rest first"
echo "   sim -> LCM log $RUN/sim.log -> se23-ins -> LCM log $RUN/ins.log -> report"
# shellcheck disable=SC2086
"$BIN/se23-sim" --scenario "$SCEN" ${DUR:+--duration "$DUR"} --imu "$IMU" --imu-rate 200 \
    --earth on --gnss-rate 5 --seed "$SEED" --lever "$LEVER" --gnss-latency "$LATENCY" \
    --stationary "$REST" --progress --url "file://$RUN/sim.log?mode=w"
"$BIN/se23-ins" --imu "$IMU" --imu-rate 200 --earth on --lever "$LEVER" --zupt on --progress \
    --in "file://$RUN/sim.log?speed=0" --out "file://$RUN/ins.log?mode=w" >"$RUN/ins-summary.txt"
echo
"$BIN/se23-report" --plots "$RUN/plots" --plot-script tools/report/plot.py \
    "$RUN/sim.log" "$RUN/ins.log"
echo
echo "   INS input accounting: $RUN/ins-summary.txt; logs: $RUN/sim.log, $RUN/ins.log"
echo "== demo done in $(($(date +%s) - start)) s"
