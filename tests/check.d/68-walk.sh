# The real walk end to end (make demo-walk): the CSV imported, run through
# the library's filter with the pedestrian preset under valgrind (double;
# the float run plain), and the loop-closure error asserted within a
# margin stated from the measured figure (README "A real walk": 0.056 m in
# double and in float; margin 25 %: 0.070 m, within the 82 mm).
# The same filter without its floor updates (0.137 m), without its
# zero-velocity updates, or with them far too strong must fail a bound.
# The programs are built by 60-harness.sh.
WB="$BUILD/harness/bin"
WW="$BUILD/check/walk"
WVG="$VALGRIND --suppressions=tools/lcm/valgrind-lcm.supp"
mkdir -p "$WW"

# w_run INS NAME [WRAPPER]: the imported walk through INS (se23-ins or
# se23-ins-float), the nav states into NAME.log, the accounting NAME.txt.
# shellcheck disable=SC2086 # $3 (a wrapper) and $4 (options) split on purpose
w_run() {
    ${3:-} "$WB/$1" --preset foot --imu-rate 400 --lat 51.45 --nav-rate 400 ${4:-} \
        --in "file://$WW/imu.log?speed=0" --out "file://$WW/$2.log?mode=w" >"$WW/$2.txt"
}
w_import() {
    "$WB/se23-import" --out "file://$WW/imu.log?mode=w" \
        tools/data/xio-gait-tracking/short_walk.csv >"$WW/import.txt"
}
check walk-import w_import
# The ZUPTs' mean NIS (0.671 measured, README "A real walk") within
# [0.5, 0.85]: the preset's ZUPT sigma still matches the walk's stance.
# The closure's normalised error against the filter's own covariance
# (11.1 measured) may not grow past that plus 25 %: 14. The walk is on one
# floor: one level, set at the first rest, and an update at each of the
# other stances (16 measured; at least 15).
w_double() {
    w_run se23-ins double "$WVG" &&
        "$WB/se23-walk" --max-closure 0.070 --max-closure-nis 14 "$WW/double.log" &&
        grep -q "^  imu_missing  *238\$" "$WW/double.txt" &&
        grep -q "^  floor_levels  *1\$" "$WW/double.txt" &&
        awk '$1 == "zupt_nis_mean" { ok = ($2 >= 0.5 && $2 <= 0.85) }
             $1 == "floor_used" { fl = ($2 >= 15) }
             END { exit (ok && fl) ? 0 : 1 }' "$WW/double.txt"
}
check walk-closure-double-valgrind w_double
w_float() {
    w_run se23-ins-float float && "$WB/se23-walk" --max-closure 0.070 "$WW/float.log"
}
check walk-closure-float w_float
# Without the floor updates (--floor-sigma 0) the vertical drift stays
# (0.137 m, normalised error 31.2; bounds plus 25 %: 0.172 m, 39) and the
# floor's bound fails: the floor is what meets it.
w_no_floor() {
    w_run se23-ins nofloor "" "--floor-sigma 0" &&
        "$WB/se23-walk" --max-closure 0.172 --max-closure-nis 39 "$WW/nofloor.log" &&
        ! "$WB/se23-walk" --max-closure 0.070 "$WW/nofloor.log"
}
check walk-closure-without-floor w_no_floor
# The bound can fail: the same walk with zero-velocity updates too weak to
# hold the foot (v = 0 to 10 m/s) drifts by metres.
w_weak_zupt() {
    w_run se23-ins weak "" "--zupt-sigma-v 10" &&
        ! "$WB/se23-walk" --max-closure 0.070 "$WW/weak.log"
}
check walk-closure-can-fail w_weak_zupt
# The normalised-error bound can fail: ZUPTs of 1 cm/s per sample, far
# stronger than a foot in stance holds, make the filter sure of its
# position to 7 mm while it drifts by 16 cm (1,491).
w_strong_zupt() {
    w_run se23-ins strong "" "--zupt-sigma-v 0.01" &&
        ! "$WB/se23-walk" --max-closure-nis 14 "$WW/strong.log"
}
check walk-closure-nis-can-fail w_strong_zupt
# The misalignment study (make walk-misalign, README "A real walk"), on
# the filter without the floor, whose vertical drift it explains: no
# rotation gives the closure of the run without the floor above; 0.5
# degrees about y takes more than 5 cm off it (0.064 m against 0.137 m).
w_misalign() {
    INS_OPTS="--floor-sigma 0" sh tools/walk/misalign-sweep.sh "$BUILD/harness" 0,0,0 0,0.5,0 \
        >"$WW/misalign.txt" &&
        cat "$WW/misalign.txt" &&
        wm_ref=$(awk '$1 == "0,0,0" { print $2 }' "$WW/misalign.txt") &&
        "$WB/se23-walk" "$WW/nofloor.log" | grep -q "closure error *$wm_ref m 3D" &&
        awk '$1 == "0,0,0" { a = $2 } $1 == "0,0.5,0" { b = $2 }
             END { exit (a != "" && b != "" && a - b > 0.05) ? 0 : 1 }' "$WW/misalign.txt"
}
check walk-misalign-sweep w_misalign
# The walk's simulated twin (make walk-sim, README "A real walk"), first
# without the floor: with every sensor error in the preset's model the
# filter closes the loop to 4 mm (4-9 mm over seeds 1-8; bound 20 mm) and
# its covariance covers that (normalised error 0.03; bound 11.34,
# chi-square 3 dof at 0.99); the accelerometer rotated by 0.5 degrees
# about the foot's pitch axis gives the real walk's signature: 0.131 m
# vertical (bound 0.10-0.16 m), 6 mm horizontal (bound 20 mm), normalised
# error 30.6 (above 11.34).
w_sim() {
    INS_OPTS="--floor-sigma 0" sh tools/walk/sim-walk.sh "$BUILD/harness" 0,0,0 0,0.5,0 \
        >"$WW/sim.txt" &&
        cat "$WW/sim.txt" &&
        awk '$1 == "0,0,0" { a = ($2 <= 0.02 && $5 <= 11.34) }
             $1 == "0,0.5,0" { b = ($4 >= 0.10 && $4 <= 0.16 && $3 <= 0.02 && $5 > 11.34) }
             END { exit (a && b) ? 0 : 1 }' "$WW/sim.txt"
}
check walk-sim-twin w_sim
# With the preset's floor the same misaligned twin closes to 12 mm (bound
# 20 mm), its covariance covering it (normalised error 3.0, bound 11.34).
w_sim_floor() {
    sh tools/walk/sim-walk.sh "$BUILD/harness" 0,0.5,0 >"$WW/sim-floor.txt" &&
        cat "$WW/sim-floor.txt" &&
        awk '$1 == "0,0.5,0" { a = ($2 <= 0.02 && $5 <= 11.34) } END { exit a ? 0 : 1 }' \
            "$WW/sim-floor.txt"
}
check walk-sim-twin-floor w_sim_floor
# The same twin on a stepped path (SCENARIO=stairs: 8 strides up a 0.15 m
# riser, 8 down): every stance is on a new level, which the preset's floor
# must see (17 levels: the first rest and 16 risers; no floor update pulls
# a stance back to the old level), and the loop closes as without the
# floor (4 mm; bound 20 mm, normalised error 0.03, bound 11.34).
w_sim_stairs() {
    SCENARIO=stairs sh tools/walk/sim-walk.sh "$BUILD/harness" 0,0,0 >"$WW/sim-stairs.txt" &&
        cat "$WW/sim-stairs.txt" &&
        grep -q "^  floor_levels  *17\$" "$BUILD/harness/walk-sim/summary.txt" &&
        grep -q "^  floor_used  *0\$" "$BUILD/harness/walk-sim/summary.txt" &&
        awk '$1 == "0,0,0" { a = ($2 <= 0.02 && $5 <= 11.34) } END { exit a ? 0 : 1 }' \
            "$WW/sim-stairs.txt"
}
check walk-sim-stairs w_sim_stairs
