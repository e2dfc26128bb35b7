"""Markdown tables of the Cortex-M figures (make report-target), the tables of
tools/doc/pages/cortex-m-functions.md:
per target, the library's code size and, per public function, the
worst-case stack (tools/target/stack_gate.py) and the instructions per call
(build/target/bench.md from make bench-target), then the composite steps.

  report.py BUILD
"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PY = sys.executable
TARGETS = [("m4f-float", "Cortex-M4F, float build (QEMU mps2-an386)"),
           ("m7-double", "Cortex-M7 with double-precision FPU, double build (QEMU mps2-an500)")]


def run(*args):
    return subprocess.run([PY, *args], capture_output=True, text=True).stdout


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    with open(os.path.join(build, "target", "bench.md"), encoding="utf-8") as f:
        bench_rows = [line.strip().strip("|").split("|") for line in f if line.startswith("| ")]
    header = [c.strip() for c in bench_rows[0]]
    bench = {r[0].strip(): [c.strip() for c in r[1:]] for r in bench_rows[1:]}
    for col, (variant, title) in enumerate(TARGETS):
        size = run(os.path.join(HERE, "size_gate.py"), f"{build}/lib-{variant}/libse23.a",
                   "tests/target/budgets/size.txt", variant)
        total = re.search(r"^total\s+(\d+)", size, re.M).group(1)
        stack = run(os.path.join(HERE, "stack_gate.py"), f"{build}/lib-{variant}",
                    f"{build}/target/{variant}/tv_test.elf,{build}/target/{variant}/ins_replay.elf",
                    "tests/target/budgets/stack.txt",
                    variant)
        idx = header.index(f"{variant} (instructions)") - 1
        print(f"#### {title}\n")
        print(f"Library code size (.text + .rodata, all modules): **{total} bytes**.\n")
        print("| function | worst-case stack [bytes] | instructions per call |")
        print("|---|---:|---:|")
        for line in stack.splitlines()[1:]:
            p = line.split()
            if len(p) >= 4 and p[0].startswith("se23_"):
                print(f"| `{p[0]}` | {p[2]} | {bench.get(p[0], ['-'] * 2)[idx]} |")
        for name, cells in bench.items():
            if not name.startswith("se23_"):
                print(f"| {name} | | {cells[idx]} |")
        print()
    return 0


if __name__ == "__main__":
    sys.exit(main())
