#!/bin/sh
# `make demo-walk`: a real foot-mounted walk (x-io NGIMU, ~400 Hz, 41.6 s, a
# closed loop of ~23 m; tools/data/xio-gait-tracking) through the library's
# pedestrian filter: tools/walk/walk.sh on its CSV (x-io's columns are
# se23-import's defaults), at Bristol's latitude.
#
#   sh tools/walk/demo-walk.sh HARNESS_BUILD_DIR [MAX_CLOSURE_M]
set -eu
H=${1:-build/harness}
LAT=51.45 IMPORT="" sh tools/walk/walk.sh "$H" "$H/walk" \
    tools/data/xio-gait-tracking/short_walk.csv ${2:+"$2"}
