#!/usr/bin/env python3
"""The library's layers, checked over its #include lines (make check, step
51-layers).

  python3 tools/layers.py [ROOT]      ROOT holds src/ and include/ (default .)

src/ has one folder per layer, lowest first:

  base    scalar math wrappers, small linear algebra, trigonometry,
          argument checks, status names
  lie     SO(3) and SE_2(3): exp, log, Jacobians and their series
  imu     exact IMU increments and propagation, the Earth model, geodetic
          fixes, the preintegrated factor
  cov     covariance checks and kernels (gen/: generated code),
          concentrated Gaussians, the preintegrated factor's uncertainty
  kalman  the Kalman update and its structured forms, measurement models
  nav     the navigation filter, its detector, alignment and presets

Rules, each a failure naming the file and the line:
  - an include names a file relative to the including file (the library
    builds with include/ and port/ on the path, never src/), or a public
    header "se23/x.h";
  - no file includes one of a higher layer, public headers included: each
    public header belongs to the layer that implements it (PUBLIC below),
    and public headers follow the same order among themselves;
  - a layer's internal headers are its own unless EXPORTED to the layers
    above (for example nav/ins_internal.h, through which the filter's files
    call each other, is seen by nav alone).
"""
import os
import re
import sys

LAYERS = ["base", "lie", "imu", "cov", "kalman", "nav"]

# The layer each public header belongs to (the one that implements it).
PUBLIC = {
    "config.h": "base", "types.h": "base",
    "so3.h": "lie", "se23.h": "lie",
    "earth.h": "imu", "imu.h": "imu", "geodetic.h": "imu", "preint.h": "imu",
    "gauss.h": "cov", "preint_unc.h": "cov", "work.h": "cov",
    "kalman.h": "kalman",
    "ins.h": "nav", "align.h": "nav", "stationary.h": "nav",
}

# Internal headers a layer offers to the layers above it; every other
# internal header is seen by its own layer only.
EXPORTED = {
    "base/argcheck.h", "base/linalg.h", "base/se23_math.h", "base/trig.h",
    "lie/so3_series.h",
    "imu/imu_step.h",
    "cov/cov_check.h", "cov/cov_chol.h",
    # the filter's structured rest and NHC updates and the halves of the
    # general update they share
    "kalman/kalman_halves.h", "kalman/kalman_nhc.h", "kalman/kalman_rest.h",
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def rank(layer):
    return LAYERS.index(layer)


def check_file(root, path, layer, errors):
    """Check the quoted includes of one file of layer `layer`."""
    rel = os.path.relpath(path, root)
    with open(path, encoding="utf-8") as f:
        for num, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            name = m.group(1)
            where = f"{rel}:{num}: #include \"{name}\""
            if name.startswith("se23/"):
                target = PUBLIC.get(name[len("se23/"):])
                if target is None:
                    errors.append(f"{where}: no such public header (tools/layers.py PUBLIC)")
                elif rank(target) > rank(layer):
                    errors.append(f"{where}: {layer} includes the {target} layer's header")
                continue
            dest = os.path.normpath(os.path.join(os.path.dirname(path), name))
            src = os.path.join(root, "src")
            if not os.path.isfile(dest) or not dest.startswith(src + os.sep):
                errors.append(f"{where}: not a file under src/ relative to the including file")
                continue
            inner = os.path.relpath(dest, src).split(os.sep)
            target = inner[0]
            if target not in LAYERS:
                errors.append(f"{where}: src/{target} is not a layer (tools/layers.py LAYERS)")
            elif rank(target) > rank(layer):
                errors.append(f"{where}: {layer} includes the {target} layer's header")
            elif target != layer and "/".join(inner) not in EXPORTED:
                errors.append(f"{where}: internal to the {target} layer (not in EXPORTED)")


def main(argv):
    root = os.path.abspath(argv[1] if len(argv) > 1 else ".")
    errors, files = [], 0
    for entry in sorted(os.listdir(os.path.join(root, "src"))):
        top = os.path.join(root, "src", entry)
        if not os.path.isdir(top):
            errors.append(f"src/{entry}: a file outside the layer folders")
            continue
        if entry not in LAYERS:
            errors.append(f"src/{entry}: not a layer (tools/layers.py LAYERS)")
            continue
        for folder, _, names in sorted(os.walk(top)):
            for name in sorted(names):
                if name.endswith((".c", ".h")):
                    check_file(root, os.path.join(folder, name), entry, errors)
                    files += 1
    public = os.path.join(root, "include", "se23")
    for name in sorted(os.listdir(public)):
        if name not in PUBLIC:
            errors.append(f"include/se23/{name}: no layer (tools/layers.py PUBLIC)")
        else:
            check_file(root, os.path.join(public, name), PUBLIC[name], errors)
            files += 1
    for e in errors:
        print(e)
    print(f"layers: {files} files, {len(errors)} violations "
          f"({' < '.join(LAYERS)})")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
