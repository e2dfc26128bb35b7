#!/bin/sh
# make bench: the host benchmark, float and double builds (se23-bench, one
# binary per precision, main.c). Prints markdown:
#  - the machine line;
#  - per precision, the composite steps against the dense Eigen reference:
#    wall time per call (median and p10-p90 over interleaved rounds, after a
#    cross-check of the outputs that must pass) and callgrind instructions
#    per call, each with the ratio se23 / Eigen;
#  - instructions per call of each library routine.
# Instruction counts come from valgrind --tool=callgrind, collecting only
# run_kernel (collect.c): the same binary and inputs give the same count on
# any load. The raw timings are kept in BUILD/bench/time-<precision>.tsv.
# The machine line and the two tables of the composite steps are also
# written into OUT/steps.md, which make doc-tables pastes into
# tools/doc/pages/host-speed.md (tools/doc/tables.py); make check
# (tests/check.d/80-bench.sh) runs --steps with a few rounds and verifies
# the page's instruction columns, the same on any load, not its times.
#   tools/bench/run.sh BUILD_DIR [--steps]
# --steps: the composite steps only (no per-routine table).
# Environment: CC, CXX and BENCH_FLAGS name the compilers and flags on the
# machine line; BENCH_ROUNDS sets the timed rounds (default 1000); BENCH_OUT
# the output folder OUT (default BUILD_DIR/bench).
set -eu
build=$1
steps_only=${2:-}
rounds=${BENCH_ROUNDS:-1000}
n=128 # calls per callgrind run: two passes over the input ring
out=${BENCH_OUT:-$build/bench}
mkdir -p "$out"

count() { # binary kernel -> instructions per call
    cg="$out/cg.$$"
    if ! valgrind --tool=callgrind --callgrind-out-file="$cg" \
        --toggle-collect=run_kernel "$1" count "$2" "$n" >/dev/null 2>"$cg.log"; then
        echo "run.sh: callgrind run of $1 count $2 failed (log: $cg.log)" >&2
        exit 1
    fi
    total=$(sed -n 's/^summary: *//p' "$cg")
    rm -f "$cg" "$cg.log"
    echo $((total / n))
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }

lscpu_field() { lscpu | sed -n "s/^$1: *//p" | head -n 1; }
eigen=$(dpkg-query -W -f='${Version}' libeigen3-dev 2>/dev/null || echo unknown)
{
    echo "Machine: $(uname -m), $(lscpu_field 'Model name') (family $(lscpu_field 'CPU family')," \
        "model $(lscpu_field 'Model')), $(nproc) CPUs; gcc $(${CC:-cc} -dumpfullversion)," \
        "g++ $(${CXX:-c++} -dumpfullversion), Eigen $eigen; ${BENCH_FLAGS:-}"
    for prec in double float; do
        bin="$build/bench-$prec/se23-bench"
        tsv="$out/time-$prec.tsv"
        "$bin" time "$rounds" >"$tsv"
        echo
        echo "**$(echo "$prec" | sed 's/^./\U&/') build.** ns per call and time ratio (within each" \
            "round): median (p10-p90) over $rounds rounds; instructions per call: callgrind."
        echo
        echo "| step | se23 ns | Eigen ns | time se23/Eigen | se23 instr | Eigen instr | instr se23/Eigen | max rel. diff |"
        echo "|---|---:|---:|---:|---:|---:|---:|---:|"
        while IFS='	' read -r name label diff _ s10 smed s90 _ e10 emed e90 r10 rmed r90; do
            si=$(count "$bin" "$name/se23")
            ei=$(count "$bin" "$name/eigen")
            echo "| $label | $smed ($s10-$s90) | $emed ($e10-$e90) | $rmed ($r10-$r90)" \
                "| $si | $ei | $(ratio "$si" "$ei") | $diff |"
        done <"$tsv"
    done
} >"$out/steps.md.tmp"
mv "$out/steps.md.tmp" "$out/steps.md"
cat "$out/steps.md"
echo
echo "(the steps' tables: $out/steps.md; make doc-tables pastes them into tools/doc/pages/host-speed.md)"
[ "$steps_only" = --steps ] && exit 0

echo
echo "### Instructions per routine"
echo
echo "| routine | float (instr/call) | double (instr/call) | double/float |"
echo "|---|---:|---:|---:|"
for k in $("$build/bench-double/se23-bench" routines); do
    f=$(count "$build/bench-float/se23-bench" "$k")
    d=$(count "$build/bench-double/se23-bench" "$k")
    echo "| $k | $f | $d | $(ratio "$d" "$f") |"
done
