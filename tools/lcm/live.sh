#!/bin/sh
# Live run over UDP multicast: se23-sim -> udpm -> se23-ins -> udpm, recorded
# by lcm-logger, then se23-report on the recording.
#
#   sh tools/lcm/live.sh HARNESS_BUILD_DIR      (make demo-live passes build/harness)
#
# udpm://239.255.76.67:7667?ttl=0 needs a multicast route on lo. The script
# re-executes itself inside a private user + network namespace
# (unshare -rn) and adds the route there: the host's interfaces and routes
# are never touched and no packet leaves this machine (ttl=0, lo only).
#
# Environment: LIVE_SPEED (4: simulated time runs 4x real time; 1 = real
# time), LIVE_DURATION (60 s), LIVE_SCENARIO (uav), LIVE_IMU (mems),
# LIVE_SEED (1), LIVE_WRAP (a command prefix for se23-ins, e.g. valgrind ...),
# LIVE_DIR (HARNESS_BUILD_DIR/live), LIVE_NO_REPORT (1: skip the report).
set -eu
H=${1:-build/harness}
URL="udpm://239.255.76.67:7667?ttl=0"
BIN="$H/bin"
RUN=${LIVE_DIR:-$H/live}

if [ "${SE23_IN_NETNS:-0}" != 1 ]; then
    command -v unshare >/dev/null || { echo "live.sh: needs unshare (util-linux)" >&2; exit 1; }
    mkdir -p "$RUN"
    SE23_IN_NETNS=1 LIVE_DIR="$RUN" unshare -rn sh "$0" "$H"
    [ "${LIVE_NO_REPORT:-0}" = 1 ] && exit 0
    echo
    exec "$BIN/se23-report" --plots "$RUN/plots" --plot-script tools/report/plot.py "$RUN/live.log"
fi

# --- inside the private network namespace ---
ip link set lo up
ip link set lo multicast on
ip route add 224.0.0.0/4 dev lo
SPEED=${LIVE_SPEED:-4}
DUR=${LIVE_DURATION:-60}
rm -f "$RUN/live.log" "$RUN/ins.ready"
echo "== live run in a private network namespace: $URL, ${DUR} s at ${SPEED}x real time"
lcm-logger -q --lcm-url="$URL" -f "$RUN/live.log" &
logger=$!
# shellcheck disable=SC2086
${LIVE_WRAP:-} "$BIN/se23-ins" --in "$URL" --imu "${LIVE_IMU:-mems}" --imu-rate 200 --earth on \
    --exit-on-end --idle-timeout 30 --ready-file "$RUN/ins.ready" --progress \
    >"$RUN/ins-summary.txt" &
ins=$!
# the subscribers must be up before the initial state is published
n=0
while [ ! -e "$RUN/ins.ready" ]; do
    n=$((n + 1))
    [ "$n" -le 600 ] || { echo "live.sh: se23-ins did not start" >&2; kill "$ins" "$logger"; exit 1; }
    sleep 0.1
done
sleep 0.5 # and lcm-logger
"$BIN/se23-sim" --url "$URL" --scenario "${LIVE_SCENARIO:-uav}" --duration "$DUR" \
    --imu "${LIVE_IMU:-mems}" --imu-rate 200 --earth on --gnss-rate 5 \
    --seed "${LIVE_SEED:-1}" --speed "$SPEED"
rc=0
wait "$ins" || rc=$?
sleep 0.5 # the logger flushes every 100 ms
kill -INT "$logger"
wait "$logger" || true
echo "   se23-ins exit status $rc; recording: $RUN/live.log; INS accounting: $RUN/ins-summary.txt"
exit "$rc"
