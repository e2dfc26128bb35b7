#!/bin/sh
# Installs se23 (float build, to show the precision travels with the
# package) into a scratch prefix, then builds and runs a consumer through
# the CMake package and through pkg-config.
set -eu
work="$(cd "$1" && pwd)/install-test"
rm -rf "$work"
cmake -S . -B "$work/build" -DSE23_DOUBLE=OFF -DCMAKE_INSTALL_PREFIX="$work/prefix"
cmake --build "$work/build" -j "${JOBS:-2}"
cmake --install "$work/build"
cmake -S tests/install -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix"
cmake --build "$work/consumer"
"$work/consumer/consumer" | grep 'sizeof(se23_real_t) = 4'
pcdir=$(dirname "$(find "$work/prefix" -name se23.pc)")
cc -std=c99 -Wall -Werror tests/install/consumer.c -o "$work/consumer-pc" \
    $(PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs se23)
"$work/consumer-pc" | grep 'sizeof(se23_real_t) = 4'
