# The host benchmark (make bench) builds, and its dense Eigen reference of
# the four composite steps (tools/bench/ref_*.cpp, written independently of
# the library) agrees with the library to rounding, in both precisions: one
# more independent check of the covariance kernels. No timing is judged.
check bench-build make -s bench-bins BUILD="$BUILD"
check bench-double-crosscheck "$BUILD/bench-double/se23-bench" check
check bench-float-crosscheck "$BUILD/bench-float/se23-bench" check
# The instruction columns of tools/doc/pages/host-speed.md (callgrind:
# the same on every run and load) are the ones measured now: make bench's
# steps with a few timed rounds, into $BUILD/check/bench; the page's times
# (one run of make bench on one machine) are not judged.
check bench-table-current sh -c 'BENCH_ROUNDS=3 BENCH_OUT="$1/check/bench" \
    sh tools/bench/run.sh "$1" --steps && /usr/bin/python3 tools/doc/tables.py --check \
    --build "$1/check" --columns 0,4,5,6,7 host-bench' sh "$BUILD"
