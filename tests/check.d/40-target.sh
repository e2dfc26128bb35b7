# Cortex-M4F (float, mps2-an386) and Cortex-M7 (double, mps2-an500) images
# on qemu-system-arm (port/target.mk): the port self-test, the reference
# vectors of every public routine (tests/target), the navigation filter run
# through recorded sequences against the host's double run
# (tests/target/ins_replay.c), the real foot-mounted walk against the
# host's run in the image's precision (tests/target/walk_replay.c), the
# first 70 s of the real car drive likewise (tests/target/drive_replay.c),
# and the runners' own tests (one corrupted vector must fail exactly one
# check; three perturbed replay references, three perturbed walk references
# and three perturbed drive references, exactly three checks each). The
# POSIX port runs the same self-test on the host; the template port must
# compile.
check port-posix make -s test-port-posix BUILD="$BUILD"
check port-template cc -std=c99 -Wall -Wextra -Wpedantic -Werror -Iport \
    -fsyntax-only port/template/se23_port.c
# Every public function of include/se23/*.h has reference vectors (a row of
# tests/target/tv_list.h and a generator in tools/target/gen_*.cpp).
# The contract page's table (tools/doc/pages/contract.md) is the one the
# headers' @return paragraphs give.
check contract-page-current /usr/bin/python3 tools/target/se23_api.py --contract-check \
    tools/doc/pages/contract.md
check target-vectors-cover-api /usr/bin/python3 tools/target/se23_api.py --coverage \
    tests/target/tv_list.h
check target-images make -s -j1 target BUILD="$BUILD"
for v in m4f-float:mps2-an386 m7-double:mps2-an500; do
    for img in port_selftest tv_test ins_replay walk_replay drive_replay; do
        check "target-${v%%:*}-$img" sh tools/target/qemu-run.sh "${v#*:}" \
            "$BUILD/target/${v%%:*}/$img.elf"
    done
done
check target-corrupt-vector-fails make -s test-target-corrupt BUILD="$BUILD"
check target-ins-replay-corrupt-fails make -s test-target-ins-corrupt BUILD="$BUILD"
check target-walk-replay-corrupt-fails make -s test-target-walk-corrupt BUILD="$BUILD"
check target-drive-replay-corrupt-fails make -s test-target-drive-corrupt BUILD="$BUILD"
# Instruction counts (make bench-target): every operation returns SE23_OK and
# two runs give identical counts.
check target-bench-deterministic sh -c 'make -s bench-target BUILD="$1" >/dev/null &&
    cp "$1/target/bench.md" "$1/target/bench.first.md" &&
    make -s bench-target BUILD="$1" >/dev/null &&
    cmp "$1/target/bench.md" "$1/target/bench.first.md" && cat "$1/target/bench.md"' sh "$BUILD"
# The manual pages' tables of these figures are the ones measured now
# (tools/doc/tables.py; make doc-tables pastes them): the instruction
# counts, and the stack, size and hot-path tables that report.py writes
# from them and from the gates' analysis of this build's objects.
check target-bench-table-current /usr/bin/python3 tools/doc/tables.py --check \
    --build "$BUILD" target-bench
check target-report-table-current sh -c '/usr/bin/python3 tools/target/report.py "$1" \
    --only functions && /usr/bin/python3 tools/doc/tables.py --check --build "$1" \
    target-m4f-float target-m7-double target-hot-path' sh "$BUILD"
# A planted stale figure (one instruction count of the page changed) fails it.
tgt_stale_fails() {
    ts_pages="$BUILD/check/stale-pages"
    rm -rf "$ts_pages" && mkdir -p "$ts_pages" &&
        sed '/table:target-bench begin/,/table:target-bench end/ s/^\(| se23_so3_hat | \)\([0-9]\)/\11\2/' \
            tools/doc/pages/cortex-m-functions.md >"$ts_pages/cortex-m-functions.md" &&
        ! cmp -s tools/doc/pages/cortex-m-functions.md "$ts_pages/cortex-m-functions.md" &&
        ! /usr/bin/python3 tools/doc/tables.py --check --build "$BUILD" --pages "$ts_pages" \
            target-bench >"$ts_pages/out.txt" 2>&1 &&
        cat "$ts_pages/out.txt" && grep -q '^+| se23_so3_hat ' "$ts_pages/out.txt"
}
check target-table-check-fails-when-stale tgt_stale_fails
