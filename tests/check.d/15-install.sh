# CMake install + find_package(se23) + pkg-config consumer.
check install-cmake-pkgconfig sh tests/install/run.sh "$BUILD"
