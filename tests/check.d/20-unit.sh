# CMocka unit and property tests, both precisions, under valgrind.
cmocka_dir double "$BUILD/cmake-double/tests"
cmocka_dir float "$BUILD/cmake-float/tests"
# The debugging build (SE23_CFG_DEEP_CHECKS=1): every step re-proves the
# state it is handed, and the tests of those statuses run too.
for deep_t in test_gauss test_preint_unc test_kalman; do
    cmocka_test "deep-$deep_t" "$BUILD/cmake-deep/tests/$deep_t"
done
# The same unit tests of both precisions built with AddressSanitizer and
# UndefinedBehaviorSanitizer (-fno-sanitize-recover=all: a finding aborts
# the binary and fails the step); run without valgrind, which cannot host
# ASan.
unit_valgrind=$VALGRIND
VALGRIND=""
cmocka_dir asan-double "$BUILD/cmake-asan-double/tests"
cmocka_dir asan-float "$BUILD/cmake-asan-float/tests"
VALGRIND=$unit_valgrind
asan_fixture_fails() {
    cc -std=c99 -fsanitize=address,undefined -fno-sanitize-recover=all \
        tests/support/asan_fixture.c -o "$BUILD/asan_fixture" && ! "$BUILD/asan_fixture"
}
check asan-rejects-fixture asan_fixture_fails
