# CMocka unit and property tests, both precisions, under valgrind.
cmocka_dir double "$BUILD/cmake-double/tests"
cmocka_dir float "$BUILD/cmake-float/tests"
# The debugging build (SE23_CFG_DEEP_CHECKS=1): every step re-proves the
# state it is handed, and the tests of those statuses run too.
for deep_t in test_gauss test_preint_unc test_kalman; do
    cmocka_test "deep-$deep_t" "$BUILD/cmake-deep/tests/$deep_t"
done
