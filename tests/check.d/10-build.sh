# Library alone with the strict flags: host in both precisions, then
# Cortex-M4F (float) and Cortex-M7 (double) with arm-none-eabi-gcc.
check build-lib-host make -s lib BUILD="$BUILD"
check build-lib-cross make -s cross BUILD="$BUILD"
check build-tests-double make -s tests-double BUILD="$BUILD" JOBS="$JOBS"
check build-tests-float make -s tests-float BUILD="$BUILD" JOBS="$JOBS"
check build-tests-deep make -s tests-deep BUILD="$BUILD" JOBS="$JOBS"
check build-tests-asan-double make -s tests-asan-double BUILD="$BUILD" JOBS="$JOBS"
check build-tests-asan-float make -s tests-asan-float BUILD="$BUILD" JOBS="$JOBS"
