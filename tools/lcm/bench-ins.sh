#!/bin/sh
# `make bench-ins`: se23-ins throughput on a recorded log of 1.2 million IMU
# samples (UAV flight, MEMS IMU at 2 kHz for 600 s, Earth rotation on, GNSS
# at 5 Hz), 15-state covariance, nav output at 10 Hz, file:// in and out.
# se23-ins is single-threaded; its CPU time (CLOCK_PROCESS_CPUTIME_ID,
# everything from the first lcm_handle to the end: LCM file reading and
# decoding, screening, propagation, covariance, GNSS updates, publishing)
# gives samples per second on one core. Best of BENCH_RUNS runs (3).
#
#   sh tools/lcm/bench-ins.sh HARNESS_BUILD_DIR
set -eu
H=${1:-build/harness}
BIN="$H/bin"
RUN="$H/bench"
RUNS=${BENCH_RUNS:-3}
mkdir -p "$RUN"
if [ ! -s "$RUN/bench.log" ] || [ "$BIN/se23-sim" -nt "$RUN/bench.log" ]; then
    echo "== recording 1.2 M IMU samples (2 kHz, 600 s) into $RUN/bench.log"
    "$BIN/se23-sim" --scenario uav --duration 600 --imu mems --imu-rate 2000 --earth on \
        --gnss-rate 5 --truth-rate 10 --seed 7 --progress --url "file://$RUN/bench.log?mode=w"
fi
echo "== se23-ins on $RUN/bench.log ($(du -m "$RUN/bench.log" | cut -f1) MB), best of $RUNS"
best=0
i=1
while [ "$i" -le "$RUNS" ]; do
    "$BIN/se23-ins" --imu mems --imu-rate 2000 --earth on --nav-rate 10 \
        --in "file://$RUN/bench.log?speed=0" --out "file://$RUN/bench-ins.log?mode=w" \
        >"$RUN/summary.txt"
    used=$(awk '$1 == "imu_used" {print $2}' "$RUN/summary.txt")
    cpu=$(awk '$1 == "cpu_seconds" {print $2}' "$RUN/summary.txt")
    rate=$(awk '$1 == "samples_per_s" {print $2}' "$RUN/summary.txt")
    echo "   run $i: $used samples in $cpu s CPU = $rate samples/s"
    [ "$rate" -gt "$best" ] && best=$rate
    i=$((i + 1))
done
echo "== se23-ins throughput: $best IMU samples/s on one core (15-state covariance, GNSS 5 Hz)"
lscpu | sed -n 's/^Model name: *//p' | head -n 1 | sed 's/^/   CPU: /'
