# se23-import (tools/import/): hostile CSV IMU logs, each written here into
# $BUILD/check/import/ and imported under valgrind (LCM's own leak
# suppressed, as in 60-harness.sh): the exit status, the counters of the
# summary and the line-numbered messages must be as expected, and every
# row accounted for (rows = written + repeated + backwards + malformed).
# Then the real walk (tools/data/xio-gait-tracking/short_walk.csv) with the
# counts its README states, and logs read back by se23-importcheck: as many
# samples as rows written, sequence numbers skipping exactly the lost
# samples, the first sample converted right (deg/s -> rad/s, g -> m/s^2,
# axes, time units). The programs are built by 60-harness.sh.
IB="$BUILD/harness/bin"
IW="$BUILD/check/import"
IVG="$VALGRIND --suppressions=tools/lcm/valgrind-lcm.supp"
I_HDR="Time (s),Gyroscope X (deg/s),Gyroscope Y (deg/s),Gyroscope Z (deg/s)"
I_HDR="$I_HDR,Accelerometer X (g),Accelerometer Y (g),Accelerometer Z (g)"
I_WALK=tools/data/xio-gait-tracking/short_walk.csv
mkdir -p "$IW"

# i_import CSV NAME WANT_RC [OPTIONS...]: imports CSV into $IW/NAME.log
# under valgrind; summary in NAME.out, messages in NAME.err. The exit
# status must be WANT_RC (valgrind's own is 99).
i_import() {
    ir_in=$1
    ir_name=$2
    ir_rc=$3
    shift 3
    rm -f "$IW/$ir_name.log"
    $IVG "$IB/se23-import" --out "file://$IW/$ir_name.log?mode=w" "$@" "$ir_in" \
        >"$IW/$ir_name.out" 2>"$IW/$ir_name.err"
    ir_got=$?
    cat "$IW/$ir_name.out" "$IW/$ir_name.err"
    echo "exit status $ir_got (expected $ir_rc)"
    [ "$ir_got" -eq "$ir_rc" ]
}

# i_run NAME WANT_RC [OPTIONS...]: i_import of $IW/NAME.csv.
i_run() {
    ir_name=$1
    shift
    i_import "$IW/$ir_name.csv" "$ir_name" "$@"
}

# i_expect NAME COUNTER=VALUE...: the counters of NAME.out; and every row
# read is written, dropped as repeated or backwards, or malformed.
i_expect() {
    ie_out="$IW/$1.out"
    shift
    ie_fail=0
    for ie_kv in "$@"; do
        ie_key=${ie_kv%%=*}
        ie_want=${ie_kv#*=}
        ie_got=$(awk -v k="$ie_key" '$1 == k {print $2}' "$ie_out")
        if [ "$ie_got" = "$ie_want" ]; then
            echo "ok   $ie_key = $ie_want"
        else
            echo "FAIL $ie_key: expected $ie_want, got $ie_got"
            ie_fail=1
        fi
    done
    awk '{v[$1] = $2} END {
        s = v["rows_written"] + v["dup_time"] + v["backwards"] + v["malformed"]
        m = v["malformed_columns"] + v["malformed_number"] + v["malformed_nonfinite"] + \
            v["malformed_long"]
        if (v["rows"] == "" || s != v["rows"] || m != v["malformed"]) {
            printf "FAIL accounting: rows %s, written + dropped + malformed %d, ", v["rows"], s
            printf "malformed %s = %d\n", v["malformed"], m
            exit 1
        }
        print "ok   every row accounted for"
    }' "$ie_out" && [ "$ie_fail" = 0 ]
}

# i_msg NAME PATTERN: the messages of NAME say PATTERN.
i_msg() {
    if grep -q -- "$2" "$IW/$1.err"; then
        echo "ok   message: $2"
    else
        echo "FAIL no message: $2"
        return 1
    fi
}

# i_back NAME KEY=VALUE...: se23-importcheck (under valgrind) reads NAME.log
# back; each KEY's first value must be VALUE.
i_back() {
    ib_name=$1
    shift
    $IVG "$IB/se23-importcheck" "$IW/$ib_name.log" >"$IW/$ib_name.back" || return 1
    cat "$IW/$ib_name.back"
    ib_fail=0
    for ib_kv in "$@"; do
        ib_got=$(awk -v k="${ib_kv%%=*}" '$1 == k {print $2}' "$IW/$ib_name.back")
        if [ "$ib_got" != "${ib_kv#*=}" ]; then
            echo "FAIL read back ${ib_kv%%=*}: expected ${ib_kv#*=}, got $ib_got"
            ib_fail=1
        fi
    done
    [ "$ib_fail" = 0 ]
}

# i_rows NAME LINE...: NAME.csv is the x-io header and the lines given.
i_rows() {
    ir_f="$IW/$1.csv"
    shift
    echo "$I_HDR" >"$ir_f"
    for ir_l in "$@"; do
        echo "$ir_l" >>"$ir_f"
    done
}

# Empty file, header only: status 1, say so, write no log.
i_empty() {
    : >"$IW/empty.csv"
    i_run empty 1 && i_expect empty rows=0 rows_written=0 header_lines=0 &&
        i_msg empty "no valid row found (the file is empty); nothing written" &&
        [ ! -e "$IW/empty.log" ]
}
check import-empty-file i_empty
i_header_only() {
    echo "$I_HDR" >"$IW/header.csv"
    i_run header 1 && i_expect header rows=0 header_lines=1 &&
        i_msg header "no data row after 1 header line(s)" && [ ! -e "$IW/header.log" ]
}
check import-header-only i_header_only

# Wrong field count (6 and 8 of 7), skipped with their line numbers; a
# trailing comma or blank is not a field.
i_columns() {
    i_rows columns "0,1,2,3,0,0,1" "0.0025,1,2,3,0,0" "0.005,1,2,3,0,0,1,9" \
        "0.0075,1,2,3,0,0,1," "0.01 , 1, 2 ,3,0,0,1 , ,  " "0.0125,1,2,3,0,0,1"
    i_run columns 0 && i_expect columns rows=6 rows_written=4 malformed=2 \
        malformed_columns=2 gaps=1 lost_samples=2 last_seq=6 &&
        i_msg columns "columns.csv:3: 6 field(s), expected 7, skipped" &&
        i_msg columns "columns.csv:4: 8 field(s), expected 7, skipped"
}
check import-wrong-column-count i_columns

# Text in a number field (gyro, accel, time, an empty field, a NUL byte).
i_text() {
    i_rows text "0,1,2,3,0,0,1" "0.0025,1,abc,3,0,0,1" "0.005,1,2,3,0,0,1g" \
        "12:00:01,1,2,3,0,0,1" "0.0075,1,,3,0,0,1" "0.01,1,2,3,0,0,1"
    printf '0.0125,1,2\0003,0,0,1\n0.015,1,2,3,0,0,1\n' >>"$IW/text.csv"
    i_run text 0 && i_expect text rows=8 rows_written=3 malformed=5 malformed_number=5 &&
        i_msg text 'text.csv:3: column 3: not a number: "abc", skipped' &&
        i_msg text 'text.csv:4: column 7: not a number: "1g", skipped' &&
        i_msg text 'text.csv:5: column 1: not a number: "12:00:01", skipped' &&
        i_msg text 'text.csv:6: column 3: not a number: "", skipped' &&
        i_msg text "text.csv:8: NUL byte in the line, skipped"
}
check import-text-in-number i_text

# NaN, Inf, out of the double range; at most --max-messages 2 messages,
# then a count.
i_nonfinite() {
    i_rows nan "0,1,2,3,0,0,1" "0.0025,nan,2,3,0,0,1" "0.005,1,2,3,NaN,0,1" \
        "0.0075,1,2,3,0,-Inf,1" "0.01,1,2,1e999,0,0,1" "nan,1,2,3,0,0,1" "0.0125,1,2,3,0,0,1"
    i_run nan 0 --max-messages 2 && i_expect nan rows=7 rows_written=2 malformed=5 \
        malformed_nonfinite=5 &&
        i_msg nan 'nan.csv:3: column 2: not finite (NaN, Inf or out of range): "nan"' &&
        i_msg nan "nan.csv: 3 more row messages not shown (--max-messages 2)" &&
        [ "$(grep -c 'not finite' "$IW/nan.err")" -eq 2 ]
}
check import-nan-inf i_nonfinite

# A line of 1 MB between valid rows: skipped to its end (bounded buffer),
# the rows after it still read (the skipped sample counts as lost); a row
# of exactly 4096 bytes is not too long.
i_long_line() {
    i_rows long "0,1,2,3,0,0,1"
    {
        printf '0.0025,1,2,3,0,0,'
        head -c 1048576 /dev/zero | tr '\0' '1'
        printf '\n0.005,1,2,3,0,0,1\n'
        awk 'BEGIN { s = "0.0075,1,2,3,0,0,1"; while (length(s) < 4096) s = s " "; print s }'
        printf '0.01,1,2,3,0,0,1\n'
    } >>"$IW/long.csv"
    i_run long 0 && i_expect long rows=5 rows_written=4 malformed=1 malformed_long=1 \
        gaps=1 lost_samples=1 last_seq=5 &&
        i_msg long "long.csv:3: line longer than 4096 bytes, skipped"
}
check import-long-line-1mb i_long_line

# Time going backwards: dropped, compared with the last row written.
i_backwards() {
    i_rows back "0,1,2,3,0,0,1" "0.01,1,2,3,0,0,1" "0.02,1,2,3,0,0,1" "0.015,9,9,9,0,0,1" \
        "0.005,9,9,9,0,0,1" "0.03,1,2,3,0,0,1"
    i_run back 0 --rate 100 && i_expect back rows=6 rows_written=4 backwards=2 gaps=0 \
        last_seq=4 &&
        i_msg back "back.csv:5: time 0.015000000 s before the previous row's 0.020000000 s"
}
check import-time-backwards i_backwards

# Repeated timestamps, with the same values and with others: dropped.
i_duplicates() {
    i_rows dup "0,1,2,3,0,0,1" "0.01,1,2,3,0,0,1" "0.01,1,2,3,0,0,1" "0.02,1,2,3,0,0,1" \
        "0.02,1,2,4,0,0,1" "0.020,1,2,3,0,0,1" "0.03,1,2,3,0,0,1"
    i_run dup 0 && i_expect dup rows=7 rows_written=4 dup_time=3 dup_time_same=2 gaps=0 \
        last_seq=4
}
check import-duplicate-timestamps i_duplicates

# Gaps at 100 Hz (the median interval: no --rate): 2 then 3 samples lost;
# the sequence numbers skip them.
i_gap() {
    i_rows gap "0,1,2,3,0,0,1" "0.01,1,2,3,0,0,1" "0.02,1,2,3,0,0,1" "0.05,1,2,3,0,0,1" \
        "0.06,1,2,3,0,0,1" "0.1,1,2,3,0,0,1" "0.11,1,2,3,0,0,1" "0.1249,1,2,3,0,0,1"
    i_run gap 0 && i_expect gap rows=8 rows_written=8 gaps=2 lost_samples=5 \
        longest_gap_s=0.040000000 nominal_interval_s=0.010000000 last_seq=13 &&
        i_back gap samples=8 seq_missing=5 seq_bad=0 time_bad=0 last_seq=13 \
            last_t_ns=124900000
}
check import-gap i_gap

# Values at the sensor's range (input units): counted, kept.
i_clipped() {
    i_rows clip "0,1,2,3,0,0,1" "0.01,2000,2,3,0,0,1" "0.02,1,-2000.5,3,0,0,1" \
        "0.03,1999.9,2,3,15.99,0,1" "0.04,1,2,3,0,16,1" "0.05,1,2,3,0,0,-17" \
        "0.06,-2000,2,3,-16,0,1"
    i_run clip 0 --gyro-range 2000 --accel-range 16 &&
        i_expect clip rows=7 rows_written=7 gyro_clipped=3 accel_clipped=3 malformed=0
}
check import-clipped i_clipped

# CRLF line ends (header too), trailing commas and blanks.
i_crlf() {
    printf '%s\r\n0,1,2,3,0,0,1\r\n0.01,1,2,3,0,0,1,\r\n' "$I_HDR" >"$IW/crlf.csv"
    printf '0.02,1,2,3,0,0,1 ,\t\r\n0.03 ,1,2,3,0,0,1\r\n' >>"$IW/crlf.csv"
    i_run crlf 0 && i_expect crlf rows=4 rows_written=4 malformed=0 gaps=0
}
check import-crlf i_crlf

# Bad usage: status 2 (axes not a signed permutation, columns not distinct,
# units, no --out or not a URL, no input); an unreadable input: 1.
i_usage() {
    for iu_args in "--axes x,x,z" "--axes x,y" "--axes x,y,w" "--axes x,y,z,x" "--axes +-x,y,z" \
        "--gyro-cols 1,2,3" "--accel-cols 5,6" "--time-col 0" "--time-unit h" \
        "--gyro-unit rpm" "--accel-unit mg" "--g 1" "--header -1" "--rate 0" "--out x.log" \
        "--accel-misalign 8,0,7" "--accel-misalign 1,2" "--accel-misalign 1,2,3,4" \
        "--accel-misalign nan,0,0" "--accel-misalign 0,x,0"; do
        # shellcheck disable=SC2086
        $IVG "$IB/se23-import" --out "file://$IW/usage.log?mode=w" $iu_args "$I_WALK" \
            >"$IW/usage.out" 2>&1
        iu_rc=$?
        echo "$iu_args: exit status $iu_rc"
        [ "$iu_rc" -eq 2 ] || return 1
    done
    $IVG "$IB/se23-import" "$I_WALK" >"$IW/usage.out" 2>&1
    [ $? -eq 2 ] && grep -q -- "--out is required" "$IW/usage.out" || return 1
    $IVG "$IB/se23-import" --out "file://$IW/usage.log?mode=w" >"$IW/usage.out" 2>&1
    [ $? -eq 2 ] && grep -q "no input file" "$IW/usage.out" || return 1
    i_import "$IW/absent.csv" absent 1 && i_msg absent "cannot read $IW/absent.csv"
}
check import-usage-and-unreadable i_usage

# Units, axes and exact times, read back: rad/s, m/s^2, ms, --axes y,-x,-z,
# no header; then Unix time in s keeps its nanoseconds (--header auto skips
# three header lines).
i_units_axes() {
    printf '1000.5,0.1,0.2,0.3,1.5,-2.5,9.75\n1003,0.1,0.2,0.3,1.5,-2.5,9.75\n' >"$IW/units.csv"
    i_run units 0 --header 0 --time-unit ms --gyro-unit rad/s --accel-unit m/s2 \
        --axes y,-x,-z &&
        i_back units samples=2 first_t_ns=1000500000 last_t_ns=1003000000 &&
        grep -qx "first_omega 0.20000000000000001 -0.10000000000000001 -0.29999999999999999" \
            "$IW/units.back" &&
        grep -qx "first_accel -2.5 -1.5 -9.75" "$IW/units.back"
}
check import-units-axes-roundtrip i_units_axes

# --accel-misalign rotates the accelerometer after --axes, not the gyro:
# 10 degrees about z (the largest accepted) and 0.6,-0.8,0 (1 degree about
# a tilted axis, Rodrigues' formula written out here), to 1e-12.
i_misalign() {
    printf '0,0.1,0.2,0.3,1.5,-2.5,9.75\n0.01,0.1,0.2,0.3,1.5,-2.5,9.75\n' >"$IW/mis.csv"
    i_run mis 0 --header 0 --gyro-unit rad/s --accel-unit m/s2 --axes y,-x,-z \
        --accel-misalign 0,0,10 && i_back mis samples=2 &&
        grep -qx "first_omega 0.20000000000000001 -0.10000000000000001 -0.29999999999999999" \
            "$IW/mis.back" &&
        awk 'BEGIN { t = 10 * atan2(0, -1) / 180; x = -2.5; y = -1.5 }
             $1 == "first_accel" { e = 0
                 e += ($2 - (cos(t) * x - sin(t) * y))^2; e += ($3 - (sin(t) * x + cos(t) * y))^2
                 e += ($4 + 9.75)^2; ok = (e < 1e-24) }
             END { exit ok ? 0 : 1 }' "$IW/mis.back" || return 1
    i_run mis 0 --header 0 --accel-unit m/s2 --accel-misalign 0.6,-0.8,0 && i_back mis &&
        awk 'BEGIN { t = atan2(0, -1) / 180; n[1] = 0.6; n[2] = -0.8; n[3] = 0
                 v[1] = 1.5; v[2] = -2.5; v[3] = 9.75
                 c[1] = n[2] * v[3] - n[3] * v[2]; c[2] = n[3] * v[1] - n[1] * v[3]
                 c[3] = n[1] * v[2] - n[2] * v[1]; d = n[1] * v[1] + n[2] * v[2] + n[3] * v[3]
                 for (i = 1; i <= 3; i++) w[i] = v[i] * cos(t) + c[i] * sin(t) + n[i] * d * (1 - cos(t)) }
             $1 == "first_accel" { ok = (($2 - w[1])^2 + ($3 - w[2])^2 + ($4 - w[3])^2 < 1e-24) }
             END { exit ok ? 0 : 1 }' "$IW/mis.back"
}
check import-accel-misalign i_misalign
i_unix_time() {
    printf 'x-io NGIMU\nrecorded 2023\n%s\n' "$I_HDR" >"$IW/unix.csv"
    printf '1700000000.123456789,1,2,3,0,0,1\n1700000000.126,1,2,3,0,0,1\n' >>"$IW/unix.csv"
    printf '17000000001294999995e-10,1,2,3,0,0,1\n' >>"$IW/unix.csv"
    i_run unix 0 --header auto && i_expect unix header_lines=3 rows=3 rows_written=3 &&
        i_back unix first_t_ns=1700000000123456789 last_t_ns=1700000000129500000
}
check import-unix-time-exact i_unix_time

# Issue 37 (fuzzing). S8: a value finite in the file but not once converted
# (1e308 g is 9.8e308 m/s^2, beyond the double range; a 10 degree
# --accel-misalign mixing two 1.7e308 m/s^2 axes) is skipped like a NaN,
# never written as Inf or NaN; a time beyond int64 nanoseconds too.
i_overflow() {
    i_rows over "0,1,2,3,0,0,1" "0.01,1,2,3,0,0,1e308" "0.02,1,2,3,0,0,1" \
        "9300000000,1,2,3,0,0,1" "0.03,1,2,3,0,0,1"
    i_run over 0 && i_expect over rows=5 rows_written=3 malformed=2 malformed_nonfinite=2 &&
        i_msg over 'over.csv:3: column 7: not finite once converted to rad/s, m/s^2: "1e308"' &&
        i_msg over 'over.csv:5: column 1: not finite (NaN, Inf or out of range): "9300000000"' &&
        i_back over samples=3 last_t_ns=30000000 || return 1
    i_rows overrot "0,1,2,3,0,0,9.8" "0.01,1,2,3,1.7e308,1.7e308,0" "0.02,1,2,3,0,0,9.8"
    i_run overrot 0 --accel-unit m/s2 --accel-misalign 0,0,10 &&
        i_expect overrot rows=3 rows_written=2 malformed_nonfinite=1 &&
        i_msg overrot 'overrot.csv:3: column 5: not finite once converted' &&
        i_back overrot samples=2 &&
        ! grep -E "^(first|last)_" "$IW/overrot.back" | grep -Eiq "nan|inf"
}
check import-overflow-after-conversion i_overflow

# S9: --out naming the input (the file itself, a symbolic link to it, a
# hard link with mode=a) is refused, status 2, the CSV left as it was.
i_out_is_in() {
    i_rows same "0,1,2,3,0,0,1" "0.01,1,2,3,0,0,1"
    cp "$IW/same.csv" "$IW/same.orig"
    ln -sf same.csv "$IW/same-sym.csv"
    ln -f "$IW/same.csv" "$IW/same-hard.csv"
    for io_out in "same.csv?mode=w" "same-sym.csv?mode=w" "same-hard.csv?mode=a"; do
        $IVG "$IB/se23-import" --out "file://$IW/$io_out" "$IW/same.csv" >"$IW/same.err" 2>&1
        io_rc=$?
        echo "--out file://$IW/$io_out: exit status $io_rc (expected 2)"
        [ "$io_rc" -eq 2 ] && cmp "$IW/same.csv" "$IW/same.orig" &&
            i_msg same "is the input file $IW/same.csv: refused, nothing written" || return 1
    done
}
check import-out-is-input-refused i_out_is_in

# A UTF-8 byte order mark before the first line is dropped: with --header 0
# the first row is data; with --header auto too (not taken for a header).
i_bom() {
    printf '\357\273\2770,1,2,3,0,0,1\n0.01,1,2,3,0,0,1\n' >"$IW/bom.csv"
    i_run bom 0 --header 0 && i_expect bom rows=2 rows_written=2 malformed=0 &&
        i_back bom first_t_ns=0 || return 1
    i_run bom 0 --header auto && i_expect bom header_lines=0 rows=2 rows_written=2
}
check import-utf8-bom i_bom

# A line without a line end within 4 MiB (CSV_RUNAWAY_MAX) refuses the
# file, status 1, naming the line: 5 MB of NULs after two rows (refused by
# the first pass: no log), the same in one pass (--rate, --unit-check off:
# the log keeps the rows before, and says so), and /dev/zero (without
# valgrind, 10 s at most: a timeout is status 124).
i_runaway() {
    i_rows runaway "0,1,2,3,0,0,1" "0.01,1,2,3,0,0,1"
    head -c 5000000 /dev/zero >>"$IW/runaway.csv"
    i_run runaway 1 && i_msg runaway "runaway.csv:4: no line end within 4194304 bytes" &&
        [ ! -e "$IW/runaway.log" ] || return 1
    i_run runaway 1 --rate 100 --unit-check off &&
        i_msg runaway "runaway.csv: stopped early; .* holds the 2 samples written before" ||
        return 1
    timeout 10 "$IB/se23-import" --out "file://$IW/zero.log?mode=w" /dev/zero \
        >"$IW/zero.out" 2>"$IW/zero.err"
    ir_got=$?
    cat "$IW/zero.err"
    echo "exit status $ir_got (expected 1)"
    [ "$ir_got" -eq 1 ] && i_msg zero "/dev/zero:1: no line end within 4194304 bytes"
}
check import-runaway-line-refused i_runaway

# The unit check: the first rest (|f| steady within 10 % for 0.5 s) must
# read 0.5 to 1.5 g. A file in m/s^2 that starts moving (0.2 s at 0.5 and
# 2 g) then rests at 9.8 m/s^2 (1 s at 100 Hz, noise 0.02 m/s^2) is refused
# as g, status 1, naming the rest and --accel-unit m/s2, no log; read as
# m/s2 it passes (1.000 g). The same file in g read as m/s2: refused,
# "use --accel-unit g". A rest at 3 g (29 m/s^2) fits no unit. With
# --unit-check off the file is imported as told.
# i_rest NAME SCALE: NAME.csv, that walk, accelerations times SCALE.
i_rest() {
    awk -v s="$2" 'BEGIN {
        print "t,gx,gy,gz,ax,ay,az"
        for (i = 0; i < 120; i++) {
            f = i < 20 ? 9.80665 * (i % 2 ? 0.5 : 2) : 9.80665 + 0.01 * (i % 3 - 1)
            printf "%.2f,0.1,-0.2,0.1,%.17g,%.17g,%.17g\n", i / 100, 0.6 * f * s, 0, 0.8 * f * s
        }
    }' >"$IW/$1.csv"
}
i_units_check() {
    i_rest rest-ms2 1 && i_rest rest-g 0.10197162129779283 && i_rest rest-3g 3 &&
        i_run rest-ms2 1 && [ ! -e "$IW/rest-ms2.log" ] &&
        i_msg rest-ms2 "rest-ms2.csv: the accelerometer reads 9.81 g at rest (t = 0.2.* to 0.7" &&
        i_msg rest-ms2 "is the file in m/s2? use --accel-unit m/s2" &&
        i_run rest-ms2 0 --accel-unit m/s2 &&
        grep -q "unit check: |f| = 1.000 g at rest (t = 0.200000000 to 0.700000000 s)" \
            "$IW/rest-ms2.out" &&
        i_run rest-g 1 --accel-unit m/s2 && i_msg rest-g "reads 0.102 g at rest" &&
        i_msg rest-g "is the file in g? use --accel-unit g" &&
        i_run rest-g 0 && i_run rest-3g 1 --accel-unit m/s2 && i_msg rest-3g "reads 3 g at rest" &&
        i_msg rest-3g "no --accel-unit fits" &&
        i_run rest-ms2 0 --unit-check off && grep -q "unit check off" "$IW/rest-ms2.out"
}
check import-unit-check-at-rest i_units_check

# se23-ins on a log where its filter never initialises (3 samples: too
# short for the preset's alignment; no SE23_INIT without it): status 4 and
# why on stderr, not 0 after aligning for ever. (No --imu-rate: the log's
# own, 66.7 Hz, the median of its two intervals.)
i_ins_never() {
    for in_opts in "--preset foot" ""; do
        # shellcheck disable=SC2086
        $IVG "$IB/se23-ins" $in_opts --in "file://$IW/over.log?speed=0" \
            --out "file://$IW/never.ins.log?mode=w" >"$IW/never.out" 2>"$IW/never.err"
        in_rc=$?
        cat "$IW/never.err"
        echo "se23-ins $in_opts: exit status $in_rc (expected 4)"
        [ "$in_rc" -eq 4 ] && i_msg never "the input ended and the filter never initialised" ||
            return 1
    done
}
check import-ins-never-initialised i_ins_never

# A file without a time column (gaitmap's layout: two header lines, a
# sample index): --time-col 0 needs --rate (status 2, saying so); with it,
# data row k is at k / 250 Hz, the malformed row 6 too: its sample counts
# as lost, the sequence numbers skip it. The log's first message says how
# the samples are timed (SE23_IMU_INFO: 250 Hz, source 2, the row index).
i_no_time_col() {
    {
        echo "sensor,left,left,left,left,left,left"
        echo "index,gx,gy,gz,ax,ay,az"
        for k in 0 1 2 3 4 5 7 8 9; do
            [ "$k" = 7 ] && echo "6,1,2,x,0,0,1"
            echo "$k,1,2,3,0,0,1"
        done
    } >"$IW/notime.csv"
    i_run notime 2 --header 2 --time-col 0 &&
        i_msg notime "--time-col 0 (no time column) needs --rate HZ: row k is at k / HZ" &&
        [ ! -e "$IW/notime.log" ] || return 1
    i_run notime 0 --header 2 --time-col 0 --rate 250 &&
        i_expect notime rows=10 rows_written=9 malformed=1 malformed_number=1 gaps=1 \
            lost_samples=1 last_seq=10 nominal_interval_s=0.004000000 &&
        grep -q "(250.000 Hz; row index, --rate 250 Hz)" "$IW/notime.out" &&
        i_back notime samples=9 seq_missing=1 first_t_ns=0 last_t_ns=36000000 info_events=1 \
            info_late=0 info_rate_hz=250 info_rate_source=2 info_n_intervals=0 other_events=0
}
check import-no-time-column i_no_time_col

# The rate travels with the log (tools/ins/main.c, RATE_TOLERANCE): 3 s at
# rest at 250 Hz, imported with --time-col 0 --rate 250, through se23-ins
# --preset foot: without --imu-rate the filter runs at the log's 250 Hz;
# --imu-rate 252 (0.8 % off) is taken; 255 and 247 (2 % and 1.2 % off) are
# refused, status 5, both rates named. A log without SE23_IMU_INFO (the
# simulator's) keeps the default 200 Hz.
# i_ins NAME WANT_RC [OPTIONS...]: se23-ins --preset foot on NAME.log under
# valgrind, the summary in NAME.ins.txt, the messages in NAME.ins.err.
i_ins() {
    in_name=$1
    in_rc=$2
    shift 2
    $IVG "$IB/se23-ins" --preset foot "$@" --in "file://$IW/$in_name.log?speed=0" \
        --out "file://$IW/$in_name.ins.log?mode=w" >"$IW/$in_name.ins.txt" \
        2>"$IW/$in_name.ins.err"
    in_got=$?
    cat "$IW/$in_name.ins.err"
    echo "se23-ins $*: exit status $in_got (expected $in_rc)"
    [ "$in_got" -eq "$in_rc" ]
}
# i_ins_rate NAME HZ FROM LOG_HZ: NAME.ins.txt says the filter ran at HZ,
# from FROM, and the log said LOG_HZ.
i_ins_rate() {
    awk -v hz="$2" -v from="$3" -v log_hz="$4" '
        $1 == "imu_rate_hz" { r = $2 } $1 == "imu_rate_from" { f = $2 }
        $1 == "log_imu_rate_hz" { l = $2 }
        END { printf "imu_rate_hz %s from %s, log %s\n", r, f, l
              exit !(r == hz && f == from && l == log_hz) }' "$IW/$1.ins.txt"
}
i_ins_log_rate() {
    awk 'BEGIN {
        print "index,gx,gy,gz,ax,ay,az"
        for (i = 0; i < 750; i++) printf "%d,0.01,-0.02,0.01,0,0,%.3f\n", i, 1 + (i % 2 - 0.5) / 500
    }' >"$IW/rest250.csv"
    i_run rest250 0 --time-col 0 --rate 250 &&
        i_ins rest250 0 && i_ins_rate rest250 250.000 SE23_IMU_INFO 250.000 &&
        i_ins rest250 0 --imu-rate 252 && i_ins_rate rest250 252.000 --imu-rate 250.000 || return 1
    for ir_hz in 255 247; do
        i_ins rest250 5 --imu-rate $ir_hz &&
            grep -q "se23-ins: --imu-rate $ir_hz Hz contradicts the log's 250 Hz (SE23_IMU_INFO" \
                "$IW/rest250.ins.err" || return 1
    done
    "$IB/se23-sim" --scenario static --duration 1 --gnss-rate 0 --url "file://$IW/sim.log?mode=w" &&
        i_ins sim 0 && i_ins_rate sim 200.000 default 0.000
}
check import-ins-takes-the-logs-rate i_ins_log_rate

# The gyroscope's unit (tools/import/gyrocheck.h). i_tilt NAME SCALE:
# NAME.csv at 100 Hz, a body at rest for 1 s, then tilted about x by 30
# degrees in 0.5 s (1.05 rad/s; pushed up at 1.5 g meanwhile: no rest) and
# back, 12 times; the gyroscope's numbers are rad/s times SCALE, the
# accelerometer's g. A rate 57.3 times too small (rad/s read as deg/s)
# turns the body by 0.5 degrees where the accelerometer shows 30 between
# rests: refused, "use --gyro-unit rad/s". One 57.3 times too large (deg/s
# read as rad/s) turns it by 30 rad (1,719 degrees) and misses every rest's
# tilt by far: refused, "use --gyro-unit deg/s". Read right, each passes,
# confirmed; with --unit-check off the wrong reading is imported as told.
i_tilt() {
    awk -v s="$2" 'BEGIN {
        pi = atan2(0, -1); print "t,gx,gy,gz,ax,ay,az"
        for (turn = 0; turn <= 12; turn++) {
            for (i = 0; i < 100; i++) row(0, 1)
            if (turn == 12) break
            step = (turn % 2 ? -pi : pi) / 6 / 50
            for (i = 0; i < 50; i++) { phi += step; row(step / 0.01, 1.5) }
        }
    }
    function row(w, push) {
        t = n / 100; n++
        printf "%.2f,%.17g,0,0,0,%.17g,%.17g\n", t, w * s, -push * sin(phi), -push * cos(phi)
    }' >"$IW/$1.csv"
}
i_gyro_tilt() {
    i_tilt tilt-rad 1 && i_tilt tilt-deg 57.29577951308232 || return 1
    i_run tilt-rad 1 && [ ! -e "$IW/tilt-rad.log" ] &&
        i_msg tilt-rad "tilt-rad.csv: the gyroscope's numbers are rad/s, not deg/s (.*12 rest" &&
        i_msg tilt-rad "is the file in rad/s? use --gyro-unit rad/s" &&
        i_run tilt-rad 0 --gyro-unit rad/s &&
        grep -q "gyro unit check: rad/s confirmed" "$IW/tilt-rad.out" || return 1
    i_run tilt-deg 1 --gyro-unit rad/s && [ ! -e "$IW/tilt-deg.log" ] &&
        i_msg tilt-deg "numbers are deg/s, not rad/s (.* 12 followed within 10 deg as deg/s and" &&
        i_msg tilt-deg "is the file in deg/s? use --gyro-unit deg/s" &&
        i_run tilt-deg 0 && grep -q "gyro unit check: deg/s confirmed" "$IW/tilt-deg.out" &&
        i_run tilt-rad 0 --unit-check off && grep -q "unit check off" "$IW/tilt-rad.out"
}
check import-gyro-unit-between-rests i_gyro_tilt

# Beyond every MEMS gyroscope's range: i_spin NAME N: 0.5 s at rest, then
# N samples turning about the vertical at 600 deg/s (a foot's swing; no
# tilt change), then rest. Read as rad/s, 600 is 8.6 times 4,000 deg/s:
# refused for N = 30; N = 9 (below GYRO_OVER_MIN: a glitch) decides
# nothing and passes undecided.
i_spin() {
    awk -v n="$2" 'BEGIN {
        print "t,gx,gy,gz,ax,ay,az"
        for (i = 0; i < 100 + n; i++) {
            w = i >= 50 && i < 50 + n ? 600 : 0
            printf "%.2f,0,0,%d,0,0,1\n", i / 100, w
        }
    }' >"$IW/$1.csv"
}
i_gyro_range() {
    i_spin spin 30 && i_spin glitch 9 &&
        i_run spin 1 --gyro-unit rad/s && [ ! -e "$IW/spin.log" ] &&
        i_msg spin "numbers are deg/s, not rad/s (30 samples beyond 4000 deg/s if rad/s" &&
        i_run spin 0 && grep -q "gyro unit check: deg/s confirmed" "$IW/spin.out" &&
        i_run glitch 0 --gyro-unit rad/s &&
        grep -q "gyro unit check: undecided, .*(9 samples beyond 4000 deg/s" "$IW/glitch.out"
}
check import-gyro-unit-beyond-mems-range i_gyro_range

# The real walk, with the defaults: the counts of its README.
I_WALK_COUNTS="rows=16539 rows_written=16334 dup_time=205 dup_time_same=205 backwards=0
    gaps=165 lost_samples=244 longest_gap_s=0.012552738 malformed=0 gyro_clipped=0
    accel_clipped=0 last_seq=16578"
i_walk() {
    # shellcheck disable=SC2086
    i_import "$I_WALK" walk 0 && i_expect walk $I_WALK_COUNTS &&
        grep -q "unit check: |f| = 0.999 g at rest (t = 0.000000000 to 0.502114296 s)" \
            "$IW/walk.out"
}
check import-walk i_walk

# The walk's log read back: one sample per row written, seq skipping the
# lost samples, and the first sample is the file's first row converted:
# deg/s * pi/180, g * 9.80665 (relative error below 1e-15).
i_walk_roundtrip() {
    i_back walk samples=16334 decode_errors=0 other_events=0 seq_missing=244 seq_bad=0 \
        time_bad=0 first_seq=1 first_t_ns=0 last_seq=16578 last_t_ns=41618029590 \
        info_events=1 info_late=0 info_rate_source=0 info_n_intervals=10000 || return 1
    awk -F, 'NR == 2 {
        pi = atan2(0, -1)
        printf "%.17g %.17g %.17g %.17g %.17g %.17g\n", $2 * pi / 180, $3 * pi / 180,
            $4 * pi / 180, $5 * 9.80665, $6 * 9.80665, $7 * 9.80665
    }' "$I_WALK" >"$IW/walk.first"
    awk 'NR == FNR { for (i = 1; i <= 6; i++) want[i] = $i; next }
        $1 == "first_omega" { for (i = 1; i <= 3; i++) got[i] = $(i + 1) }
        $1 == "first_accel" { for (i = 1; i <= 3; i++) got[3 + i] = $(i + 1) }
        END {
            bad = 0
            for (i = 1; i <= 6; i++) {
                d = got[i] - want[i]
                if (d < 0) d = -d
                w = want[i] < 0 ? -want[i] : want[i]
                if (got[i] == "" || d > 1e-15 * w) {
                    printf "FAIL value %d: %s, expected %.17g\n", i, got[i], want[i]
                    bad = 1
                }
            }
            if (!bad) print "ok   first sample converted (deg/s -> rad/s, g -> m/s^2)"
            exit bad
        }' "$IW/walk.first" "$IW/walk.back"
}
check import-walk-roundtrip i_walk_roundtrip
