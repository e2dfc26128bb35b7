"""Forbidden symbols in the se23 library objects (not in a linked image,
whose newlib printf legitimately pulls in doubles).

  symbol_gate.py RULE OBJECT...

RULE
  soft-double  a call into the soft-float double runtime (__aeabi_d*, f2d,
               i2d, ...) or into a double libm function (sin, sqrt, ...):
               forbidden in the float build, which must do no double op.
  heap         malloc/free/calloc/realloc/_sbrk and relatives: forbidden in
               every build (the library has no heap).
  stdio        printf/puts/fwrite/... and exit/abort: forbidden (no stdio,
               no process control in the library).
Each finding names the object and the function that references the symbol
(from the relocations of its .text.<function> section). Exit status 1 if
there is any.
"""
import os
import re
import subprocess
import sys

OBJDUMP = os.environ.get("ARM_OBJDUMP", "arm-none-eabi-objdump")
NM = os.environ.get("ARM_NM", "arm-none-eabi-nm")

LIBM_DOUBLE = ("acos asin atan atan2 cos sin tan cosh sinh tanh exp exp2 expm1 log log2 "
               "log10 log1p pow sqrt cbrt hypot fabs fmod floor ceil round trunc fma fmin "
               "fmax copysign frexp ldexp modf remainder").split()
RULES = {
    "soft-double": re.compile(r"^(__aeabi_(d[a-z0-9]+|f2d|i2d|ui2d|l2d|ul2d)|"
                              + "|".join(LIBM_DOUBLE) + r")$"),
    "heap": re.compile(r"^_*(malloc|free|calloc|realloc|reallocf|memalign|aligned_alloc|"
                       r"posix_memalign|valloc|sbrk|_sbrk|_?malloc_r|_?free_r|_?calloc_r|"
                       r"_?realloc_r)$"),
    "stdio": re.compile(r"^_*(printf|fprintf|sprintf|snprintf|vprintf|vfprintf|vsnprintf|"
                        r"puts|fputs|putchar|fputc|fwrite|fopen|fflush|perror|exit|_exit|"
                        r"abort|assert|__assert_func|iprintf|fiprintf)$"),
}


def undefined(obj):
    out = subprocess.run([NM, "-u", obj], check=True, capture_output=True, text=True).stdout
    return {line.split()[-1] for line in out.splitlines() if line.strip()}


def users(obj, sym):
    """Functions of obj whose code references sym."""
    out = subprocess.run([OBJDUMP, "-r", obj], check=True, capture_output=True,
                         text=True).stdout
    found, section = set(), None
    for line in out.splitlines():
        m = re.match(r"RELOCATION RECORDS FOR \[(\S+)\]:", line)
        if m:
            section = m.group(1)
            continue
        parts = line.split()
        if len(parts) == 3 and parts[2] == sym and section:
            found.add(section.replace(".text.", "", 1) if section.startswith(".text.")
                      else section)
    return sorted(found)


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in RULES:
        raise SystemExit(__doc__)
    rule = RULES[sys.argv[1]]
    bad = 0
    for obj in sys.argv[2:]:
        for sym in sorted(undefined(obj)):
            if rule.match(sym):
                bad += 1
                print(f"{obj}: {sym} used by {', '.join(users(obj, sym))}")
        # defined heap/stdio symbols would be as bad as calls
        out = subprocess.run([NM, "--defined-only", obj], check=True, capture_output=True,
                             text=True).stdout
        for line in out.splitlines():
            sym = line.split()[-1]
            if rule.match(sym):
                bad += 1
                print(f"{obj}: defines {sym}")
    print(f"{sys.argv[1]}: {bad} finding(s) in {len(sys.argv) - 2} object(s)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
