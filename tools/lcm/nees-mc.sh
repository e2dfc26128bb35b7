#!/bin/sh
# Monte Carlo consistency of the library's filter through the harness:
# RUNS independent simulated UAV flights (seeds 1..RUNS; each draws its own
# sensor noise, biases, GNSS noise and initial error) with the GNSS antenna
# on a lever arm, fixes 100 ms late and 5 s at rest first (ZUPT on), run
# through se23-ins with STATES states (9: a sensor without biases; 15: with
# the profile's biases). At the final epoch of each run the NEES of the
# estimated error (9-dim pose, or 15-dim with biases) is chi^2 with STATES
# degrees of freedom for a consistent filter; one epoch per run keeps the
# samples independent, so their mean over RUNS runs must lie in the
# chi^2 95 % band of a mean of RUNS samples (Wilson-Hilferty quantiles).
#
#   sh tools/lcm/nees-mc.sh HARNESS_BUILD_DIR STATES [RUNS [DURATION [INS_OPTS]]]
#
# INS_OPTS are appended to se23-ins's options (make check uses them to show
# that a mis-modelled filter, e.g. without its lever arm, fails).
#
# Prints one progress line per run on stderr and the result on stdout;
# exits 1 if the mean is outside the band.
set -eu
# shellcheck disable=SC2086 # INS_OPTS is split into options on purpose
H=$1
STATES=$2
RUNS=${3:-40}
DUR=${4:-30}
INS_OPTS=${5:-}
BIN="$H/bin"
W="$H/nees-mc-$STATES"
mkdir -p "$W"
case $STATES in
9) BIAS=off ;;
15) BIAS=on ;;
*) echo "nees-mc: STATES must be 9 or 15" >&2; exit 2 ;;
esac
: >"$W/nees.txt"
k=1
while [ "$k" -le "$RUNS" ]; do
    printf '\rnees-mc %s states: run %d / %d' "$STATES" "$k" "$RUNS" >&2
    "$BIN/se23-sim" --scenario uav --duration "$DUR" --imu mems --earth on --seed "$k" \
        --biases "$BIAS" --lever 0.4,-0.2,-0.6 --gnss-latency 0.1 --stationary 5 \
        --url "file://$W/sim.log?mode=w" >/dev/null
    "$BIN/se23-ins" --imu mems --earth on --bias-states "$BIAS" --lever 0.4,-0.2,-0.6 \
        --zupt on $INS_OPTS --in "file://$W/sim.log?speed=0" --out "file://$W/ins.log?mode=w" \
        >/dev/null
    "$BIN/se23-report" --plots "$W/plots" --plot-script "" "$W/sim.log" "$W/ins.log" >/dev/null
    col=$([ "$STATES" = 9 ] && echo nees9 || echo nees15)
    awk -F, -v c="$col" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == c) j = i }
        END { print $j }' "$W/plots/errors.csv" >>"$W/nees.txt"
    k=$((k + 1))
done
echo >&2
awk -v dof="$STATES" -v runs="$RUNS" '
    { s += $1; n++ }
    END {
        k = dof * n; z = 1.959963984540054
        a = 1 - 2 / (9 * k); b = sqrt(2 / (9 * k))
        lo = k * (a - z * b) ^ 3 / n; hi = k * (a + z * b) ^ 3 / n
        m = s / n
        ok = (n == runs && m >= lo && m <= hi)
        printf "nees-mc: %d states, %d runs, final-epoch mean NEES %.2f, chi2 95%% band [%.2f, %.2f]: %s\n",
            dof, n, m, lo, hi, ok ? "consistent" : "NOT consistent"
        exit ok ? 0 : 1
    }' "$W/nees.txt"
