# Hostile LCM logs (issue 12: T1, T2, T3, T6; T11). The tools read logs with their
# own reader (tools/lcm/logfile.c): a corrupt event is reported with its byte
# offset, reading goes on at the next valid event, the bytes skipped are
# counted, and the exit status says so (3). se23-report's early exits leak
# nothing under valgrind. Uses HB, HW, HVG and the logs of 60-harness.sh.
HL="$BUILD/check/logs"
mkdir -p "$HL"

# l_status NAME WANT_RC PATTERN CMD...: CMD exits with WANT_RC (not a signal,
# not valgrind's 99) and its output says PATTERN.
l_status() {
    ls_out="$HL/$1.out"
    ls_rc=$2
    ls_pat=$3
    shift 3
    "$@" >"$ls_out" 2>&1
    ls_got=$?
    cat "$ls_out"
    echo "exit status $ls_got (expected $ls_rc)"
    [ "$ls_got" -eq "$ls_rc" ] && grep -q -- "$ls_pat" "$ls_out"
}

# T1: a 52-byte log whose one event claims a data length of INT32_MAX (LCM
# 1.3.1's reader callocs datalen + 1, which wraps, and dereferences the NULL).
# Big-endian header: sync ED A1 DA 01, event number 0, timestamp 0, channel
# length 8, data length 7F FF FF FF; then "SE23_IMU" and 16 zero bytes.
l_huge_log() {
    printf '\355\241\332\001\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\010\177\377\377\377' \
        >"$HL/huge.log"
    printf 'SE23_IMU\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0' >>"$HL/huge.log"
    [ "$(wc -c <"$HL/huge.log")" -eq 52 ]
}
L_HUGE_MSG="huge.log: corrupt event at byte 0: data length 2147483647"
l_huge_ins() {
    l_huge_log &&
        l_status huge-ins 3 "$L_HUGE_MSG" "$HB/se23-ins" --in "file://$HL/huge.log?speed=0" \
            --out "file://$HL/huge.ins.log?mode=w" &&
        grep -q "^  log_skipped_bytes  *52\$" "$HL/huge-ins.out"
}
check logs-huge-datalen-ins l_huge_ins
l_huge_report() {
    l_huge_log && l_status huge-report 1 "$L_HUGE_MSG" "$HB/se23-report" "$HL/huge.log"
}
check logs-huge-datalen-report l_huge_report

# T2, T3: se23-report's early exits (no truth, cannot read, no nav state
# matching a truth time) are errors, and free everything (valgrind).
check logs-report-no-truth l_status no-truth 1 "no truth in the log" \
    $HVG "$HB/se23-report" "$HW/e2e-uav.ins.log"
l_early_exits() {
    l_status cannot-read 1 "cannot read $HL/absent.log" \
        $HVG "$HB/se23-report" "$HL/absent.log" &&
        l_status no-match 1 "no nav state matches a truth time" \
            $HVG "$HB/se23-report" "$HW/e2e-uav.sim.log"
}
check logs-report-early-exits-valgrind l_early_exits

# T6: every framing case of se23-corrupt --framing (tools/lcm/corrupt_framing.c)
# in one log: se23-ins must lose exactly the broken events (its counters as
# expected, log_skipped_bytes the bytes of the cases) and exit 3; se23-report
# must still pass --check on the rest, and exit 3 for the skipped bytes. All
# under valgrind.
l_resync() {
    $HVG "$HB/se23-corrupt" --framing "$HW/corrupt.sim.log" "$HL/framing.log" \
        >"$HL/framing.expect" || return 1
    lr_skipped=$(awk '$2 == "log_skipped_bytes" {print $3}' "$HL/framing.expect")
    l_status framing-ins 3 "framing.log: corrupt event at byte" \
        $HVG "$HB/se23-ins" --in "file://$HL/framing.log?speed=0" \
        --out "file://$HL/framing.ins.log?mode=w" &&
        h_expect "$HL/framing.expect" "$HL/framing-ins.out" &&
        l_status framing-report 3 "LOG CORRUPT: $lr_skipped bytes skipped in 7 places" \
            $HVG "$HB/se23-report" --check "$HL/framing.log" "$HL/framing.ins.log" &&
        grep -q "^CHECK PASSED" "$HL/framing-report.out"
}
check logs-resync-framing-valgrind l_resync

# T11: nav states and truth records that decode but hold what no INS or
# simulator produces (se23-corrupt --nav, tools/lcm/corrupt_nav.c: NaN,
# non-rotations, a corrupted exponent, negative or corrupted variances,
# impossible status bits, counters and times) are left out of se23-report's
# statistics (tools/report/logread.h, "Screening"), counted by reason, and
# the exit status says so (3); the report prints no NaN and still passes
# --check on the rest. Under valgrind. Without the screening (--no-screen)
# the same logs give an RMS of nan and an astronomical NEES: the check can
# fail.
l_expect() { # l_expect FILE CHANNEL REASON: se23-corrupt --nav's count
    awk -v ch="$2" -v r="$3" '$1 == "expect" && $2 == ch && $3 == r {print $4}' "$1"
}
l_screen() {
    $HVG "$HB/se23-corrupt" --nav "$HW/e2e-uav.ins.log" "$HL/screen.ins.log" \
        >"$HL/screen-ins.expect" &&
        $HVG "$HB/se23-corrupt" --nav "$HW/e2e-uav.sim.log" "$HL/screen.sim.log" \
            >"$HL/screen-sim.expect" || return 1
    ls_nav=$(l_expect "$HL/screen-ins.expect" nav all)
    ls_truth=$(l_expect "$HL/screen-sim.expect" truth all)
    ls_line="nav states left out as corrupt (report): $ls_nav"
    ls_line="$ls_line (non-finite $(l_expect "$HL/screen-ins.expect" nav non-finite)"
    ls_line="$ls_line, not a rotation $(l_expect "$HL/screen-ins.expect" nav rotation)"
    ls_line="$ls_line, covariance $(l_expect "$HL/screen-ins.expect" nav covariance)"
    ls_line="$ls_line, status $(l_expect "$HL/screen-ins.expect" nav status)); truth records: $ls_truth"
    echo "expected: $ls_line"
    [ "$ls_nav" -gt 0 ] && [ "$ls_truth" -gt 0 ] &&
        l_status screen-report 3 \
            "LOG CORRUPT: $ls_nav nav states and $ls_truth truth records left out (exit status 3)" \
            $HVG "$HB/se23-report" --check "$HL/screen.sim.log" "$HL/screen.ins.log" &&
        grep -qF "$ls_line" "$HL/screen-report.out" &&
        grep -q "^CHECK PASSED" "$HL/screen-report.out" &&
        ! grep -qiw nan "$HL/screen-report.out" &&
        grep -q "mean NEES, pose (9 dof): *[0-9]\.[0-9][0-9]  " "$HL/screen-report.out"
}
check logs-screen-nav-truth-valgrind l_screen
l_screen_can_fail() {
    "$HB/se23-report" --no-screen "$HL/screen.sim.log" "$HL/screen.ins.log" \
        >"$HL/screen-off.out" 2>&1
    cat "$HL/screen-off.out"
    grep -qiw nan "$HL/screen-off.out" &&
        ! grep -q "mean NEES, pose (9 dof): *[0-9]\.[0-9][0-9]  " "$HL/screen-off.out"
}
check logs-screen-can-fail l_screen_can_fail
