# CMocka unit and property tests, both precisions, under valgrind.
cmocka_dir double "$BUILD/cmake-double/tests"
cmocka_dir float "$BUILD/cmake-float/tests"
