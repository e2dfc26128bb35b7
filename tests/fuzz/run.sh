#!/bin/sh
# Runs the libFuzzer targets of tests/fuzz (built by `make fuzz-build` into
# FZ/bin, one binary per target and precision, fuzz_logfile once).
#
#   sh tests/fuzz/run.sh fuzz FZ SECONDS [BIN...]
#       `make fuzz`: fuzzes each target for SECONDS (-jobs=1 -workers=1,
#       under $FUZZ_NICE), its corpus kept in FZ/corpus/<bin> and seeded
#       with tests/fuzz/corpus/<target>; prints the executions per target.
#       A crash (or leak, timeout, out-of-memory) is minimised into
#       tests/fuzz/corpus/<target>/<kind>-<sha1>, a regression input that
#       every later run replays, and the run exits 1.
#   sh tests/fuzz/run.sh smoke FZ RUNS [BIN...]
#       `make check` (tests/check.d/75-fuzz.sh), `make fuzz-smoke`: replays
#       every input of tests/fuzz/corpus/<target>, then RUNS runs from a
#       fixed seed and an empty corpus under FZ/smoke; writes nothing
#       outside FZ. Exits 1 if any target failed. The runs are the same
#       on every run and machine (for the same arithmetic): -use_cmp=0,
#       because libFuzzer's comparison-driven mutations take the operands
#       the target compares, addresses included, which ASLR changes from
#       run to run (two smoke runs of one binary reached different inputs).
#
# BIN: binaries to run (default: all of FZ/bin). <target> is the binary's
# name without fuzz_ and -double / -float: both precisions share a corpus.
set -u
mode=${1:?mode: fuzz or smoke}
FZ=${2:?FZ: the fuzz build folder}
N=${3:?SECONDS or RUNS}
shift 3
here=$(cd "$(dirname "$0")" && pwd)
seeds_root="$here/corpus"
FUZZ_NICE=${FUZZ_NICE-nice -n 10}
FZ=$(cd "$FZ" && pwd)
bins="$*"
if [ -z "$bins" ]; then
    bins=$(ls "$FZ"/bin/fuzz_* 2>/dev/null)
fi
[ -n "$bins" ] || { echo "run.sh: no fuzz binaries in $FZ/bin (make fuzz-build)" >&2; exit 1; }

# absolute paths: the fuzz mode runs each binary from its work folder
abs_bins=""
for b in $bins; do
    abs_bins="$abs_bins $(cd "$(dirname "$b")" && pwd)/$(basename "$b")"
done
bins=$abs_bins

target_of() {
    basename "$1" | sed 's/^fuzz_//; s/-double$//; s/-float$//'
}

# commas N: N with thousands separators (1234567 -> 1,234,567).
commas() {
    echo "$1" | sed -e ':a' -e 's/^\([0-9]*[0-9]\)\([0-9]\{3\}\)/\1,\2/' -e 'ta'
}

# stat NAME LOG: the value of libFuzzer's final stat::NAME in LOG.
stat() {
    sed -n "s/^stat::$1: *//p" "$2" | tail -n 1
}

status=0
case "$mode" in
smoke)
    printf '%-24s %9s %9s  %s\n' "target" "replayed" "runs" "result"
    for bin in $bins; do
        name=$(basename "$bin")
        t=$(target_of "$bin")
        seeds="$seeds_root/$t"
        work="$FZ/smoke/$name"
        rm -rf "$work"
        mkdir -p "$work/corpus"
        log="$work/log"
        ok=1
        replayed=0
        # every regression input, once
        if [ -d "$seeds" ] && [ -n "$(ls "$seeds" 2>/dev/null)" ]; then
            replayed=$(ls "$seeds" | wc -l | tr -d ' ')
            "$bin" -timeout=60 -artifact_prefix="$work/" "$seeds"/* >"$log.replay" 2>&1 || ok=0
        fi
        # then a short deterministic run
        if [ "$ok" -eq 1 ]; then
            if [ -d "$seeds" ]; then
                set -- "$work/corpus" "$seeds"
            else
                set -- "$work/corpus"
            fi
            "$bin" -runs="$N" -seed=1 -use_cmp=0 -timeout=60 -print_final_stats=1 \
                -artifact_prefix="$work/" "$@" >"$log" 2>&1 || ok=0
        fi
        runs=$(stat number_of_executed_units "$log" 2>/dev/null)
        if [ "$ok" -eq 1 ]; then
            printf '%-24s %9s %9s  ok\n' "$name" "$replayed" "${runs:-?}"
        else
            status=1
            printf '%-24s %9s %9s  FAIL (log: %s)\n' "$name" "$replayed" "${runs:-?}" \
                "$([ -s "$log" ] && echo "$log" || echo "$log.replay")"
            grep -h -m 3 -E 'fuzz oracle|ERROR: |runtime error|SUMMARY' "$log.replay" "$log" \
                2>/dev/null | sed 's/^/    | /'
        fi
    done
    ;;
fuzz)
    found=""
    # the table of tools/doc/pages/fuzzing-soak.md (make doc-tables pastes it)
    md="$FZ/fuzz.md.rows"
    : >"$md"
    total=0
    printf '%-24s %12s %9s %8s %6s  %s\n' "target" "executions" "exec/s" "corpus" "known" \
        "result"
    for bin in $bins; do
        name=$(basename "$bin")
        t=$(target_of "$bin")
        seeds="$seeds_root/$t"
        corpus="$FZ/corpus/$name"
        work="$FZ/run/$name"
        rm -rf "$work"
        mkdir -p "$corpus" "$work"
        if [ -d "$seeds" ]; then
            set -- "$corpus" "$seeds"
        else
            set -- "$corpus"
        fi
        # -jobs=1 -workers=1: one worker, its output in $work/fuzz-0.log
        (cd "$work" && $FUZZ_NICE "$bin" -max_total_time="$N" -jobs=1 -workers=1 \
            -timeout=60 -print_final_stats=1 -artifact_prefix="$work/" "$@" \
            >"$work/driver.log" 2>&1)
        log="$work/fuzz-0.log"
        [ -f "$log" ] || log="$work/driver.log"
        execs=$(stat number_of_executed_units "$log")
        rate=$(stat average_exec_per_sec "$log")
        known=$(sed -n 's/^fuzz: known open finding tolerated \([0-9]*\) times.*/\1/p' "$log" |
            tail -n 1)
        size=$(ls "$corpus" | wc -l | tr -d ' ')
        arts=$(ls "$work" | grep -E '^(crash|leak|timeout|oom|slow-unit)-' || true)
        result=ok
        for a in $arts; do
            kind=${a%%-*}
            mkdir -p "$seeds"
            min="$work/min-$a"
            # minimised, or as found if minimising fails
            "$bin" -minimize_crash=1 -max_total_time=60 -runs=100000 \
                -exact_artifact_path="$min" "$work/$a" >"$work/minimize-$a.log" 2>&1
            [ -s "$min" ] || cp "$work/$a" "$min"
            sum=$(sha1sum "$min" | cut -c1-40)
            cp "$min" "$seeds/$kind-$sum"
            found="$found $t/$kind-$sum"
            result="FAIL: $kind, kept as tests/fuzz/corpus/$t/$kind-$sum"
            status=1
        done
        printf '%-24s %12s %9s %8s %6s  %s\n' "$name" "${execs:-?}" "${rate:-?}" "$size" \
            "${known:-0}" "$result"
        printf '| `%s` | %s | %s | %s | %s |%s\n' "$name" "$(commas "${execs:-?}")" \
            "$(commas "${rate:-?}")" "$size" "${known:-0}" \
            "$([ "$result" = ok ] && echo ' no crash |' || echo " $result |")" >>"$md"
        total=$((total + ${execs:-0}))
        if [ "$result" != ok ]; then
            grep -h -m 3 -E 'fuzz oracle|ERROR: |runtime error|SUMMARY' "$log" | sed 's/^/    | /'
        fi
    done
    echo
    echo "machine: $(uname -n), $(grep -m1 'model name' /proc/cpuinfo 2>/dev/null |
        sed 's/.*: //'), $(nproc 2>/dev/null || echo '?') cores; $N s per target"
    if [ -n "$found" ]; then
        echo "new regression inputs (replayed by make check):$found"
    else
        echo "no crash"
    fi
    {
        echo "\`make fuzz FUZZ_TIME=$N\` ($N s per target, -jobs=1 -workers=1 under" \
            "\`${FUZZ_NICE:-no nice}\`), at commit" \
            "$(git rev-parse --short HEAD 2>/dev/null || echo '?')$(git diff --quiet HEAD -- \
                src include tests/fuzz 2>/dev/null || echo ' with local changes'), on" \
            "$(uname -m) $(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | sed 's/.*: //')," \
            "$(nproc 2>/dev/null || echo '?') CPUs, $(clang --version 2>/dev/null | head -n 1):"
        echo
        echo "| target | executions | per second | corpus | open finding tolerated | result |"
        echo "|---|---:|---:|---:|---:|---|"
        cat "$md"
        echo "| all $(wc -l <"$md" | tr -d ' ') | $(commas "$total") | | | | |"
    } >"$FZ/fuzz.md"
    rm -f "$md"
    echo "table: $FZ/fuzz.md (make doc-tables pastes it into tools/doc/pages/fuzzing-soak.md)"
    ;;
*)
    echo "run.sh: unknown mode $mode (fuzz or smoke)" >&2
    exit 2
    ;;
esac
exit "$status"
