"""Code size of the se23 library for one Cortex-M variant: .text + .rodata of
every object in the archive (arm-none-eabi-size -A), per object and in total,
checked against the budget file.

  size_gate.py LIBRARY BUDGET COLUMN

LIBRARY  build/lib-<variant>/libse23.a
BUDGET   tests/target/budgets/size.txt: rows "variant bytes".
COLUMN   the variant (m4f-float, m7-double).
.data and .bss must be empty (the library has no globals); their size is an
error, not a budget. Exit status 0 if within budget.
"""
import re
import subprocess
import sys
import os

SIZE = os.environ.get("ARM_SIZE", "arm-none-eabi-size")


def sections(library):
    """{object: {"code": bytes, "rw": bytes}} from size -A."""
    out = subprocess.run([SIZE, "-A", library], check=True, capture_output=True,
                         text=True).stdout
    objs, cur = {}, None
    for line in out.splitlines():
        m = re.match(r"(\S+)\s+\(ex \S+\):", line)
        if m:
            cur = objs.setdefault(m.group(1), {"code": 0, "rw": 0})
            continue
        parts = line.split()
        if cur is None or len(parts) != 3 or not parts[1].isdigit():
            continue
        name, size = parts[0], int(parts[1])
        if name.startswith((".text", ".rodata")):
            cur["code"] += size
        elif name.startswith((".data", ".bss")):
            cur["rw"] += size
    return objs


def main():
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    library, budget_file, column = sys.argv[1:]
    budget = None
    with open(budget_file, encoding="utf-8") as f:
        for line in f:
            parts = line.split("#", 1)[0].split()
            if len(parts) == 2 and parts[0] == column:
                budget = int(parts[1])
    objs = sections(library)
    total = sum(o["code"] for o in objs.values())
    rw = sum(o["rw"] for o in objs.values())
    for name in sorted(objs):
        print(f"{name:20} {objs[name]['code']:7d}")
    print(f"{'total':20} {total:7d}  (.text + .rodata, {column}; budget {budget})")
    ok = budget is not None and total <= budget and rw == 0
    if rw:
        print(f"error: {rw} bytes of .data/.bss in the library (globals are not allowed)")
    if budget is None:
        print(f"error: no budget for {column} in {budget_file}")
    elif total > budget:
        print(f"error: {total} bytes > budget {budget}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
