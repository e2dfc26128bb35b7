#!/bin/sh
# Instruction counts per call of each kernel on the host, float and double
# builds, from valgrind --tool=callgrind (deterministic: the same binary and
# inputs give the same count on any load). Prints a markdown table.
#   tools/bench/run.sh BUILD_DIR
set -eu
build=$1
n=1000
out="$build/bench"
mkdir -p "$out"
count() { # binary kernel -> instructions per call
    valgrind --tool=callgrind --callgrind-out-file="$out/cg.$2.$$" \
        --toggle-collect=run_kernel "$1" "$2" "$n" >/dev/null 2>&1
    total=$(sed -n 's/^summary: *//p' "$out/cg.$2.$$")
    rm -f "$out/cg.$2.$$"
    echo $((total / n))
}
echo "| routine | float (instr/call) | double (instr/call) | double/float |"
echo "|---|---:|---:|---:|"
for k in $("$build/bench-double/se23-bench" --list); do
    f=$(count "$build/bench-float/se23-bench" "$k")
    d=$(count "$build/bench-double/se23-bench" "$k")
    ratio=$(awk -v a="$d" -v b="$f" 'BEGIN { printf "%.2f", a / b }')
    echo "| $k | $f | $d | $ratio |"
done
