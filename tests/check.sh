#!/bin/sh
# `make check`: runs every step in tests/check.d/*.sh in name order, logs each
# to $BUILD/check/<step>.log, and ends with one line
# "N passed, N failed, N skipped" counting CMocka test cases and the other
# checks (one each), after the names of the failed and the skipped ones.
# Exits non-zero if anything failed.
set -u
BUILD=${BUILD:-build}
JOBS=${JOBS:-1}
LOGDIR="$BUILD/check"
mkdir -p "$LOGDIR"
PASSED=0
FAILED=0
FAILED_NAMES=""
SKIPPED=0
SKIPPED_NAMES=""
VALGRIND="valgrind --quiet --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect"

# progress NAME [TEXT]: the step being run. On a terminal the line is
# redrawn in place and the result line overwrites it; in a log only TEXT
# (the heartbeat of a long step) is printed, as a plain line.
progress() {
    if [ -t 1 ]; then
        printf '  ..    %-44s %.40s\033[K\r' "$1" "${2:-}"
    elif [ -n "${2:-}" ]; then
        printf '  ..    %-44s %.40s\n' "$1" "$2"
    fi
}

# heartbeat NAME LOG PID START: every 20 s while PID runs, the time spent and
# the last line of LOG (for a build, the file it compiles), so that a long
# step (a first build of the tests takes minutes) is never silent.
heartbeat() {
    while sleep 20 && kill -0 "$3" 2>/dev/null; do
        progress "$1" "$(($(date +%s) - $4)) s: $(tail -n 1 "$2" | tr -d '\r' |
            sed 's|Building \([A-Z]*\) object .*/|compiling |; s|\.o$||')"
    done
}

note_fail() {
    FAILED=$((FAILED + 1))
    FAILED_NAMES="$FAILED_NAMES $1"
}

# skip NAME REASON: a check this machine cannot run; counted in the closing
# line and named above it.
skip() {
    SKIPPED=$((SKIPPED + 1))
    SKIPPED_NAMES="$SKIPPED_NAMES $1"
    printf '  skip  %-44s (%s)\n' "$1" "$2"
}

# check NAME CMD...: one pass or one fail.
check() {
    name=$1
    shift
    log="$LOGDIR/$name.log"
    start=$(date +%s)
    progress "$name"
    "$@" >"$log" 2>&1 &
    pid=$!
    heartbeat "$name" "$log" "$pid" "$start" &
    beat=$!
    wait "$pid"
    rc=$?
    kill "$beat" 2>/dev/null
    if [ "$rc" -eq 0 ]; then
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
    s=$(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p' "$log" | tail -n 1)
    p=${p:-0}
    f=${f:-0}
    s=${s:-0}
    PASSED=$((PASSED + p))
    FAILED=$((FAILED + f))
    SKIPPED=$((SKIPPED + s))
    # A skipped case shows as "[  SKIPPED ] name" when it runs and again in
    # the closing list.
    for sk in $(sed -n 's/^\[  SKIPPED \] \([A-Za-z_][A-Za-z0-9_]*\)$/\1/p' "$log" | sort -u); do
        SKIPPED_NAMES="$SKIPPED_NAMES $name:$sk"
    done
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        note_fail "$name(valgrind/crash rc=$rc)"
    elif [ "$f" -ne 0 ]; then
        FAILED_NAMES="$FAILED_NAMES $name"
    fi
    note=""
    if [ "$s" -ne 0 ]; then
        note=", $s skipped"
    fi
    if [ "$rc" -eq 0 ]; then
        printf '  ok    %-44s %3s cases%s\n' "$name" "$p" "$note"
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

# tree_status: what git sees in the working tree outside $BUILD, ignored
# files included (a file a global gitignore hides is still a file left in
# the tree). Step 90-tree compares it with the state at the start.
tree_status() {
    git status --porcelain --ignored -- . ":(exclude)${BUILD%/}" 2>/dev/null ||
        git status --porcelain --ignored 2>/dev/null
}
tree_status >"$LOGDIR/tree-at-start.txt"

for step in tests/check.d/*.sh; do
    echo "== $(basename "$step" .sh)"
    # shellcheck disable=SC1090
    . "$step"
done

echo
if [ "$SKIPPED" -ne 0 ]; then
    echo "skipped:$SKIPPED_NAMES"
fi
if [ "$FAILED" -ne 0 ]; then
    echo "failed:$FAILED_NAMES"
fi
echo "$PASSED passed, $FAILED failed, $SKIPPED skipped"
[ "$FAILED" -eq 0 ]
