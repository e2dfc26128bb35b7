"""What a firmware links of se23: .text + .rodata of the input sections
that the link map of a footprint image (tools/target/footprint_main.c,
linked with --gc-sections) takes from libse23.a, and from newlib's libm
and libc and from libgcc on the library's behalf (the sections that the
same image without se23 calls does not take; the startup's and the C
library's own code is left out). On M4F the filter's libgcc part is its
64-bit time arithmetic (int64_t nanoseconds: division, conversion to
float).

  footprint.py VARIANT KERNELS.map FILTER.map EMPTY.map

Prints one row per image. Exit status 1 if a map holds no se23 code, or if
the filter image links less than the kernels image (the map was not read).
"""
import re
import sys

SECTION = re.compile(r"^ (\.text|\.rodata)(\.\S*)?(\s+0x[0-9a-f]+\s+0x([0-9a-f]+)\s+(\S+))?$")
CONTINUED = re.compile(r"^\s+0x[0-9a-f]+\s+0x([0-9a-f]+)\s+(\S+)$")


def sections(path):
    """{(origin, input section): bytes} of the code and read-only data linked."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    lines = text.split("Linker script and memory map", 1)[-1].splitlines()
    found = {}
    for i, line in enumerate(lines):
        m = SECTION.match(line)
        if not m:
            continue
        if m.group(3):
            size, origin = int(m.group(4), 16), m.group(5)
        else:  # a long section name: address, size and origin on the next line
            n = CONTINUED.match(lines[i + 1]) if i + 1 < len(lines) else None
            if not n:
                continue
            size, origin = int(n.group(1), 16), n.group(2)
        key = (origin, m.group(1) + (m.group(2) or ""))
        found[key] = found.get(key, 0) + size
    return found


def group(origin):
    if "libse23.a" in origin:
        return "se23"
    if re.search(r"libm\.a|libm_nano\.a", origin):
        return "libm"
    if re.search(r"libc\.a|libc_nano\.a|libg_nano\.a|libgcc\.a", origin):
        return "rt"
    return None


def footprint(path, baseline):
    sums = {"se23": 0, "libm": 0, "rt": 0}
    for key, size in sections(path).items():
        g = group(key[0])
        if g is not None and (g == "se23" or key not in baseline):
            sums[g] += size
    return sums


def main():
    if len(sys.argv) != 5:
        raise SystemExit(__doc__)
    variant, kernels, filt, empty = sys.argv[1:]
    baseline = sections(empty)
    rows = [("kernels (gauss_predict, meas_pos_nav, kalman_update)", footprint(kernels, baseline)),
            ("navigation filter (ins_init, ins_imu, ins_gnss)", footprint(filt, baseline))]
    print(f"linked footprint, {variant} (.text + .rodata, --gc-sections):")
    for name, s in rows:
        print(f"  {name:54} se23 {s['se23']:6d} B, + libm {s['libm']:5d} B, libgcc/libc {s['rt']:5d} B")
    if rows[0][1]["se23"] == 0 or rows[1][1]["se23"] < rows[0][1]["se23"]:
        print("error: no se23 code in a footprint map, or the filter links less than the kernels")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
