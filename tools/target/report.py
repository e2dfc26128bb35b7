"""Markdown tables of the Cortex-M figures (make report-target), written into
BUILD/target/ and pasted into the manual pages by make doc-tables
(tools/doc/tables.py); make check (tests/check.d/40-target.sh, 45-gates.sh)
verifies the pages current:

  report-VARIANT.md   per target, the library's code size and, per public
                      function, the worst-case stack (stack_gate.py) and the
                      instructions per call (BUILD/target/bench.md from make
                      bench-target), then the composite steps
                      (cortex-m-functions.md);
  report-hot-path.md  the per-sample calls against their performance targets
                      (cortex-m.md);
  report-footprint.md what a firmware links (footprint.py on the footprint
                      images' link maps, from make gates-target), written
                      only when the maps are there (cortex-m.md).

  report.py BUILD [--only functions|footprint]
"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PY = sys.executable
VARIANTS = ["m4f-float", "m7-double"]

# The per-sample path against the performance targets set for it: M4F
# instructions, M7 within 1.3x; the worst stack of a public call 1 KiB on M4F,
# 2 KiB on M7; the library 16 KiB. (label, bench.md row or stack root, M4F, M7)
HOT_STEPS = [
    ("`se23_gauss_predict`, 9 states", "STEP mean+cov n=9 (se23_gauss_predict)", 3000, 3900),
    ("`se23_gauss_predict`, 15 states", "STEP mean+cov n=15 (se23_gauss_predict)", 6000, 7800),
    ("`se23_preint_unc_add`, no classical Jacobians",
     "STEP preintegration (se23_preint_unc_add, exact B, no classical Jacobians)", 4000, 5200),
    ("GNSS position update, 15 states (`se23_meas_pos_nav` + `se23_kalman_update`)",
     "UPDATE GNSS position n=15 (se23_meas_pos_nav + se23_kalman_update)", 6000, 7800),
]
HOT_STACK = ["se23_gauss_predict", "se23_preint_unc_add", "se23_kalman_update",
             "se23_ins_imu", "se23_ins_gnss"]
STACK_TARGET = (1024, 2048)
SIZE_TARGET = 16384
FOOTPRINT_ROWS = [
    "the kernels of its own 15-state filter: `se23_gauss_predict`, `se23_meas_pos_nav`, "
    "`se23_kalman_update`",
    "the library's filter: `se23_ins_init`, `se23_ins_imu`, `se23_ins_gnss`",
]


def run(*args):
    return subprocess.run([PY, *args], capture_output=True, text=True).stdout


def verdict(m4f, m7, t4, t7):
    over = [f"{name} " + (f"+{100.0 * (v - t) / t:.1f} %" if v < 2 * t else f"{v / t:.1f}x")
            for name, v, t in (("M4F", m4f, t4), ("M7", m7, t7)) if v > t]
    return "met" if not over else "missed: " + ", ".join(over)


def write(build, name, text):
    path = os.path.join(build, "target", name)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    print(f"<!-- {path} -->\n{text}")


def measure(build, variant):
    """(size in bytes, {public function: worst stack})."""
    size = run(os.path.join(HERE, "size_gate.py"), f"{build}/lib-{variant}/libse23.a",
               "tests/target/budgets/size.txt", variant)
    m = re.search(r"^total\s+(\d+)", size, re.M)
    if not m:
        raise SystemExit(f"report.py: no size for {variant} (make cross):\n{size}")
    stack = run(os.path.join(HERE, "stack_gate.py"), f"{build}/lib-{variant}",
                f"{build}/target/{variant}/tv_test.elf,{build}/target/{variant}/ins_replay.elf",
                "tests/target/budgets/stack.txt", variant)
    worst = {}
    for line in stack.splitlines()[1:]:
        p = line.split()
        if len(p) >= 4 and p[0].startswith("se23_") and p[2].isdigit():
            worst[p[0]] = int(p[2])
    if not worst:
        raise SystemExit(f"report.py: no stack figures for {variant} (make target):\n{stack}")
    return int(m.group(1)), worst


def functions(build):
    with open(os.path.join(build, "target", "bench.md"), encoding="utf-8") as f:
        bench_rows = [line.strip().strip("|").split("|") for line in f if line.startswith("| ")]
    header = [c.strip() for c in bench_rows[0]]
    bench = {r[0].strip(): [c.strip() for c in r[1:]] for r in bench_rows[1:]}
    figures = {}
    for variant in VARIANTS:
        size, worst = measure(build, variant)
        figures[variant] = (size, worst)
        idx = header.index(f"{variant} (instructions)") - 1
        out = [f"Library code size (.text + .rodata, all modules): **{size} bytes**.", "",
               "| function | worst-case stack [bytes] | instructions per call |",
               "|---|---:|---:|"]
        for name, w in worst.items():
            out.append(f"| `{name}` | {w} | {bench.get(name, ['-'] * 2)[idx]} |")
        for name, cells in bench.items():
            if not name.startswith("se23_"):
                out.append(f"| {name} | | {cells[idx]} |")
        write(build, f"report-{variant}.md", "\n".join(out) + "\n")

    def count(row, variant):
        return int(bench[row][header.index(f"{variant} (instructions)") - 1])

    out = ["| what | M4F float | M7 double | target (M4F / M7) | |", "|---|---:|---:|---:|---|"]
    for label, row, t4, t7 in HOT_STEPS:
        a, b = count(row, "m4f-float"), count(row, "m7-double")
        out.append(f"| {label} | {a:,} | {b:,} | {t4:,} / {t7:,} | {verdict(a, b, t4, t7)} |")
    for row in bench:
        if row.startswith("FILTER "):
            out.append(f"| filter: {row[len('FILTER '):]} | {count(row, 'm4f-float'):,} | "
                       f"{count(row, 'm7-double'):,} | | |")
    for name in HOT_STACK:
        a, b = figures["m4f-float"][1][name], figures["m7-double"][1][name]
        out.append(f"| worst stack of `{name}` [B] | {a:,} | {b:,} | "
                   f"{STACK_TARGET[0]:,} / {STACK_TARGET[1]:,} | "
                   f"{verdict(a, b, *STACK_TARGET)} |")
    a, b = figures["m4f-float"][0], figures["m7-double"][0]
    out.append(f"| library `.text + .rodata` [B] | {a:,} | {b:,} | {SIZE_TARGET:,} (M4F) | "
               f"{verdict(a, 0, SIZE_TARGET, 1)} |")
    write(build, "report-hot-path.md", "\n".join(out) + "\n")


def footprint(build):
    maps = {v: [f"{build}/target/{v}/footprint_{i}.map" for i in ("kernels", "filter", "none")]
            for v in VARIANTS}
    if not all(os.path.exists(m) for v in VARIANTS for m in maps[v]):
        print("report.py: no footprint maps (make gates-target): report-footprint.md not written")
        return
    cells = {}
    for v in VARIANTS:
        text = run(os.path.join(HERE, "footprint.py"), v, *maps[v])
        found = re.findall(r"se23 +(\d+) B, \+ libm +(\d+) B, libgcc/libc +(\d+) B", text)
        if len(found) != len(FOOTPRINT_ROWS):
            raise SystemExit(f"report.py: footprint.py {v}:\n{text}")
        for i, (se23, libm, rt) in enumerate(found):
            extra = [f"{name} {int(n):,} B" for name, n in (("libm", libm), ("libgcc/libc", rt))
                     if int(n)]
            cells.setdefault(i, []).append(
                f"{int(se23):,} B" + (f" (+ {', '.join(extra)})" if extra else ""))
    out = ["| a firmware that calls | M4F float | M7 double |", "|---|---:|---:|"]
    for i, label in enumerate(FOOTPRINT_ROWS):
        out.append(f"| {label} | {' | '.join(cells[i])} |")
    write(build, "report-footprint.md", "\n".join(out) + "\n")


def main():
    args = sys.argv[1:]
    only = None
    if "--only" in args:
        i = args.index("--only")
        only = args[i + 1] if i + 1 < len(args) else None
        del args[i:i + 2]
        if only not in ("functions", "footprint"):
            raise SystemExit(__doc__)
    build = args[0] if args else "build"
    os.makedirs(os.path.join(build, "target"), exist_ok=True)
    if only in (None, "functions"):
        functions(build)
    if only in (None, "footprint"):
        footprint(build)
    return 0


if __name__ == "__main__":
    sys.exit(main())
