# Eigen reference (tests/reference). One pass/fail per program:
#  - selftest_*: the reference against itself by independent routes (it does
#    not depend on the C precision: run from the double tree only);
#  - crosscheck_*: the C library against the reference, both precision trees.
#    Their accuracy tables are kept in $LOGDIR/accuracy-<precision>-<program>.md
#    and merged into $LOGDIR/accuracy.md (quoted by tools/doc/pages/accuracy.md).
#    Each crosscheck also runs with every C result perturbed (SE23_XC_PERTURB,
#    relative, above every bound of that precision times the largest condition
#    factor a row divides by, ~3e3): that run passes only if EVERY row then
#    fails, i.e. it proves that each comparison can fail.
for ref_bin in "$BUILD/cmake-double/tests/reference"/selftest_*; do
    [ -x "$ref_bin" ] || continue
    check "ref-$(basename "$ref_bin")" "$ref_bin"
done
for ref_prec in double float; do
    if [ "$ref_prec" = double ]; then ref_perturb=1e-8; else ref_perturb=1e-2; fi
    for ref_bin in "$BUILD/cmake-$ref_prec/tests/reference"/crosscheck_*; do
        [ -x "$ref_bin" ] || continue
        ref_name=$(basename "$ref_bin")
        check "ref-$ref_prec-$ref_name" "$ref_bin" "$LOGDIR/accuracy-$ref_prec-$ref_name.md"
        check "ref-$ref_prec-$ref_name-perturbed" env SE23_XC_PERTURB=$ref_perturb "$ref_bin"
    done
done
# The same cross-checks with the C library built with AddressSanitizer and
# UndefinedBehaviorSanitizer (-fno-sanitize-recover=all: a finding aborts),
# both precisions (the trees of 20-unit.sh).
for ref_prec in double float; do
    check "ref-asan-$ref_prec-built" test -x "$BUILD/cmake-asan-$ref_prec/tests/reference/crosscheck_nav"
    for ref_bin in "$BUILD/cmake-asan-$ref_prec/tests/reference"/crosscheck_*; do
        [ -x "$ref_bin" ] || continue
        ref_name=$(basename "$ref_bin")
        check "ref-asan-$ref_prec-$ref_name" "$ref_bin" "$LOGDIR/asan-$ref_prec-$ref_name.md"
    done
done
{
    echo "| routine | build | error | samples | worst | worst/eps | bound | over bound |"
    echo "|---|---|---|---:|---:|---:|---:|---:|"
    cat "$LOGDIR"/accuracy-double-*.md "$LOGDIR"/accuracy-float-*.md 2>/dev/null
} >"$LOGDIR/accuracy.md"
