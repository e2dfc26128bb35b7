# libFuzzer targets (tests/fuzz, `make fuzz`): one per public header in both
# precisions and one for the tools' LCM log reader, built with clang
# -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all. Here a
# smoke run of each (tests/fuzz/run.sh smoke): every regression input of
# tests/fuzz/corpus/<target> replayed, then FUZZ_RUNS runs from a fixed seed
# and an empty corpus under $BUILD/fuzz/smoke, the same inputs on every run
# (-use_cmp=0, tests/fuzz/run.sh). The oracle can fail: with
# FUZZ_STRICT_PSD=1 the kept input of the one known open finding (fuzz.h,
# tools/doc/pages/fuzzing-soak.md) must abort the float kalman target.
FZ="$BUILD/fuzz"
mkdir -p "$FZ"
fz_probe() {
    printf '%s\n' 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n);' \
        'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n)' \
        '{ (void)d; (void)n; return 0; }' >"$FZ/probe.c" &&
        clang -fsanitize=fuzzer,address,undefined "$FZ/probe.c" -o "$FZ/probe"
}
if ! fz_probe >"$LOGDIR/fuzz-probe.log" 2>&1; then
    skip fuzz "clang -fsanitize=fuzzer does not link: packages clang, libclang-rt-dev"
else
    check fuzz-build make -s -j"$JOBS" fuzz-build BUILD="$BUILD"
    for fz_bin in "$FZ"/bin/fuzz_*; do
        [ -x "$fz_bin" ] || continue
        check "fuzz-smoke-$(basename "$fz_bin")" \
            sh tests/fuzz/run.sh smoke "$FZ" "${FUZZ_RUNS:-20000}" "$fz_bin"
    done
    fz_strict_fails() {
        fz_known=$(ls tests/fuzz/corpus/kalman/known-* 2>/dev/null | head -n 1)
        [ -n "$fz_known" ] || return 1
        "$FZ/bin/fuzz_kalman-float" -artifact_prefix="$FZ/" "$fz_known" \
            >"$FZ/strict-default.log" 2>&1 &&
            ! FUZZ_STRICT_PSD=1 "$FZ/bin/fuzz_kalman-float" -artifact_prefix="$FZ/" "$fz_known" \
                >"$FZ/strict.log" 2>&1 &&
            grep -q "fuzz oracle (float build)" "$FZ/strict.log"
    }
    check fuzz-oracle-can-fail fz_strict_fails
    # The fuzzing table of tools/doc/pages/fuzzing-soak.md (make fuzz, 23
    # minutes: its figures are not remeasured here) has one row per target
    # built now, in make fuzz's order.
    fz_rows() {
        fz_names=$(cd "$FZ/bin" && ls fuzz_*) || return 1
        # shellcheck disable=SC2086
        set -- $fz_names
        /usr/bin/python3 tools/doc/tables.py --rows fuzz "$@" "all $#"
    }
    check fuzz-table-rows fz_rows
    # The smoke runs are reproducible: two runs of the kalman target (which
    # compares addresses) reach the same coverage, features and corpus.
    fz_reached() {
        sh tests/fuzz/run.sh smoke "$FZ" "${FUZZ_RUNS:-20000}" "$FZ/bin/fuzz_kalman-double" \
            >/dev/null &&
            sed -n 's/.*DONE *\(cov: [0-9]* ft: [0-9]* corp: [0-9]*\).*/\1/p' \
                "$FZ/smoke/fuzz_kalman-double/log"
    }
    fz_same_twice() {
        fz_a=$(fz_reached) && fz_b=$(fz_reached) && [ -n "$fz_a" ] && [ "$fz_a" = "$fz_b" ] ||
            { echo "two smoke runs reached '$fz_a' and '$fz_b'"; return 1; }
    }
    check fuzz-smoke-reproducible fz_same_twice
fi
