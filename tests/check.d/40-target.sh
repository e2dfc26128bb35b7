# Cortex-M4F (float, mps2-an386) and Cortex-M7 (double, mps2-an500) images
# on qemu-system-arm; port self-tests; the template port compiles.
check port-posix make -s test-port-posix BUILD="$BUILD"
check port-template cc -std=c99 -Wall -Wextra -Wpedantic -Werror -Iport \
    -fsyntax-only port/template/se23_port.c
check target-images make -s -j1 target BUILD="$BUILD"
check target-qemu make -s test-target BUILD="$BUILD"
