#!/bin/sh
# `make check`: runs every step in tests/check.d/*.sh in name order, logs each
# to $BUILD/check/<step>.log, and ends with one line "N passed, N failed"
# counting CMocka test cases and the other checks (one each). Exits non-zero
# if anything failed.
set -u
BUILD=${BUILD:-build}
JOBS=${JOBS:-2}
LOGDIR="$BUILD/check"
mkdir -p "$LOGDIR"
PASSED=0
FAILED=0
FAILED_NAMES=""
VALGRIND="valgrind --quiet --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect"

# progress NAME: shows the step being run on a terminal; the result line
# then overwrites it. In a log (no terminal) nothing is printed.
progress() {
    [ -t 1 ] && printf '  ..    %-44s\r' "$1"
    return 0
}

note_fail() {
    FAILED=$((FAILED + 1))
    FAILED_NAMES="$FAILED_NAMES $1"
}

# check NAME CMD...: one pass or one fail.
check() {
    name=$1
    shift
    log="$LOGDIR/$name.log"
    start=$(date +%s)
    progress "$name"
    if "$@" >"$log" 2>&1; then
        PASSED=$((PASSED + 1))
        printf '  ok    %-44s %3ss\n' "$name" $(($(date +%s) - start))
    else
        note_fail "$name"
        printf '  FAIL  %-44s (log: %s)\n' "$name" "$log"
        tail -n 15 "$log" | sed 's/^/        | /'
    fi
}

# cmocka_test NAME BINARY: runs a CMocka executable under valgrind; counts its
# test cases. A valgrind error or a crash counts as one more failure.
cmocka_test() {
    name=$1
    bin=$2
    log="$LOGDIR/$name.log"
    progress "$name"
    $VALGRIND "$bin" >"$log" 2>&1
    rc=$?
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -n 1)
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -n 1)
    p=${p:-0}
    f=${f:-0}
    PASSED=$((PASSED + p))
    FAILED=$((FAILED + f))
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        note_fail "$name(valgrind/crash rc=$rc)"
    elif [ "$f" -ne 0 ]; then
        FAILED_NAMES="$FAILED_NAMES $name"
    fi
    if [ "$rc" -eq 0 ]; then
        printf '  ok    %-44s %3s cases\n' "$name" "$p"
    else
        printf '  FAIL  %-44s (log: %s)\n' "$name" "$log"
        grep -E '^\[  (FAILED|ERROR)|^==|error' "$log" | head -n 15 | sed 's/^/        | /'
    fi
}

# cmocka_dir NAME_PREFIX DIR: every test_* executable in DIR.
cmocka_dir() {
    for bin in "$2"/test_*; do
        [ -x "$bin" ] || continue
        cmocka_test "$1-$(basename "$bin")" "$bin"
    done
}

for step in tests/check.d/*.sh; do
    echo "== $(basename "$step" .sh)"
    # shellcheck disable=SC1090
    . "$step"
done

echo
if [ "$FAILED" -ne 0 ]; then
    echo "failed:$FAILED_NAMES"
fi
echo "$PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]
