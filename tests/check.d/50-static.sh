# Static analysis of the library (src/), float and double configurations:
#  - cppcheck --enable=warning,style,performance,portability;
#  - cppcheck with the MISRA C:2012 addon; the deviations, each justified,
#    are tools/target/misra-deviations.txt (rule numbers only: Debian ships
#    no rule texts);
#  - clang-tidy with the repository's .clang-tidy.
# Every finding fails. A fixture with a planted bug must be rejected by both
# tools (tests/target/gate_fixtures/bad_static.c).
STATIC_CPPCHECK="cppcheck --std=c99 --enable=warning,style,performance,portability
    --inline-suppr --error-exitcode=1 -q -Iinclude -Iport -USE23_CFG_OPTS_FILE"
STATIC_SRCS=$(find src -name "*.c" | sort)
for static_d in 0 1; do
    # shellcheck disable=SC2086
    check "cppcheck-double$static_d" $STATIC_CPPCHECK -DSE23_CFG_DOUBLE=$static_d $STATIC_SRCS
    # shellcheck disable=SC2086
    # The addon's dump files go to a build directory, not next to the sources;
    # emptied first: its cache does not see a header that changed alone.
    rm -rf "$BUILD/cppcheck-misra$static_d"
    mkdir -p "$BUILD/cppcheck-misra$static_d"
    # shellcheck disable=SC2086
    check "cppcheck-misra-double$static_d" $STATIC_CPPCHECK -DSE23_CFG_DOUBLE=$static_d \
        --addon=misra --suppressions-list=tools/target/misra-deviations.txt \
        --cppcheck-build-dir="$BUILD/cppcheck-misra$static_d" $STATIC_SRCS
    # shellcheck disable=SC2086
    check "clang-tidy-double$static_d" clang-tidy --quiet $STATIC_SRCS -- -std=c99 -Iinclude -Iport \
        -DSE23_CFG_DOUBLE=$static_d
done
# The port and the target test code, plain cppcheck (no MISRA).
# shellcheck disable=SC2086
check cppcheck-port-target $STATIC_CPPCHECK -Iport -Itests/target -DSE23_CFG_DOUBLE=0 \
    -D__ARM_ARCH_7EM__ port/posix/se23_port.c port/cortex-m/se23_port.c \
    port/template/se23_port.c tests/target/tv_runner.c tests/target/tv_custom.c \
    tests/target/port_selftest.c tests/target/ins_replay.c tests/target/ins_replay_drive.c \
    tests/target/walk_replay.c tests/target/walk_replay_drive.c tests/target/walk_replay_check.c \
    tests/target/drive_replay.c
# shellcheck disable=SC2086
check cppcheck-rejects-fixture sh -c '! "$@"' sh $STATIC_CPPCHECK \
    tests/target/gate_fixtures/bad_static.c
check clang-tidy-rejects-fixture sh -c '! clang-tidy --quiet "$1" -- -std=c99' sh \
    tests/target/gate_fixtures/bad_static.c
# Generated code is current: src/cov/gen/cov_step_kernel.c is what
# tools/gen/gen_cov_step.py writes (edit the generator, not the file).
check gen-cov-step-current /usr/bin/python3 tools/gen/gen_cov_step.py --check
