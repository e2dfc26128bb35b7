# The host benchmark (make bench) builds, and its dense Eigen reference of
# the four composite steps (tools/bench/ref_*.cpp, written independently of
# the library) agrees with the library to rounding, in both precisions: one
# more independent check of the covariance kernels. No timing is judged.
check bench-build make -s bench-bins BUILD="$BUILD"
check bench-double-crosscheck "$BUILD/bench-double/se23-bench" check
check bench-float-crosscheck "$BUILD/bench-float/se23-bench" check
