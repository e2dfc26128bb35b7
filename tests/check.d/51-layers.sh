# The source tree's layers (tools/layers.py): base < lie < imu < cov <
# kalman < nav, no include of a higher layer, internal headers seen only by
# their layer unless exported, includes relative to the including file.
# Three planted violations, each in a copy of src/ and include/, must fail:
# a lower layer including a higher one, a layer including another's private
# header, and an include that needs src/ on the include path.
check layers-hold /usr/bin/python3 tools/layers.py
layers_plant() {
    dir="$BUILD/check/layers-plant" &&
        rm -rf "$dir" && mkdir -p "$dir" && cp -r src include "$dir/" &&
        printf '%s\n' "$2" >>"$dir/src/$1" &&
        ! /usr/bin/python3 tools/layers.py "$dir"
}
check layers-reject-higher layers_plant base/linalg.c '#include "../nav/ins_internal.h"'
check layers-reject-private layers_plant nav/ins.c '#include "../cov/preint_classic.h"'
check layers-reject-src-path layers_plant kalman/meas.c '#include "base/linalg.h"'
