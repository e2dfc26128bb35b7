# Nothing outside the build folder: after every step above, `git status`
# (ignored files included, $BUILD excepted) shows exactly what it showed
# before `make check` started (nothing, on a fresh clone). Python byte code,
# matplotlib's cache and cppcheck's addon all stay under $BUILD.
# Outside a git checkout there is nothing to compare: counted as skipped.
tree_unchanged() {
    tree_status >"$LOGDIR/tree-at-end.txt" &&
        diff "$LOGDIR/tree-at-start.txt" "$LOGDIR/tree-at-end.txt"
}
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    check tree-unchanged-outside-build tree_unchanged
else
    SKIPPED=$((SKIPPED + 1))
    SKIPPED_NAMES="$SKIPPED_NAMES tree-unchanged-outside-build(not a git checkout)"
fi
