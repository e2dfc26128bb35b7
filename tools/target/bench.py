"""Instruction counts per call on the Cortex-M targets (make bench-target).

  bench.py PLUGIN VARIANT=BOARD=IMAGE [VARIANT=BOARD=IMAGE ...] [--out FILE]

Runs each benchmark image (tools/target/bench_main.c) in qemu-system-arm
with the instruction-counting plugin (tools/target/insn_count.c) attached
between the image's markers se23_bench_begin/se23_bench_end, pairs the
plugin's regions with the names the image prints, subtracts the first
region (an empty call), and prints one markdown table with a column per
variant. Counts are guest instructions (not cycles) and identical run to
run. Exit status 1 if an operation returned a non-zero status or a run
failed.
"""
import os
import re
import subprocess
import sys
import tempfile

NM = os.environ.get("ARM_NM", "arm-none-eabi-nm")
QEMU = os.environ.get("QEMU_ARM", "qemu-system-arm")


def symbol(image, name):
    for line in subprocess.run([NM, image], check=True, capture_output=True,
                               text=True).stdout.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[2] == name:
            return int(parts[0], 16) & ~1
    raise SystemExit(f"{image}: no symbol {name}")


def run(plugin, board, image):
    """[(name, status, instructions)] of one image, calibrated."""
    begin, end = symbol(image, "se23_bench_begin"), symbol(image, "se23_bench_end")
    with tempfile.NamedTemporaryFile("r", suffix=".log") as log:
        proc = subprocess.run(
            ["timeout", "300", QEMU, "-M", board, "-nographic", "-monitor", "none",
             "-serial", "none", "-semihosting-config", "enable=on,target=native",
             "-plugin", f"{plugin},begin={begin:#x},end={end:#x}", "-d", "plugin",
             "-D", log.name, "-kernel", image],
            capture_output=True, text=True)
        counts = [int(m.group(1)) for m in re.finditer(r"^region \d+ (\d+)$", log.read(), re.M)]
    if proc.returncode != 0:
        raise SystemExit(f"{image} on {board}: exit {proc.returncode}\n{proc.stdout}{proc.stderr}")
    names = []
    for line in proc.stdout.splitlines():
        if line.startswith("bench "):
            name, status = line[len("bench "):].rsplit(" ", 1)
            names.append((name, int(status)))
    if len(names) != len(counts) or not names:
        raise SystemExit(f"{image}: {len(names)} names but {len(counts)} regions")
    base = counts[0]
    return [(n, s, c - base) for (n, s), c in zip(names[1:], counts[1:])]


def main():
    args = sys.argv[1:]
    out = None
    if "--out" in args:
        i = args.index("--out")
        out = args[i + 1]
        del args[i:i + 2]
    if len(args) < 2:
        raise SystemExit(__doc__)
    plugin, specs = args[0], [a.split("=", 2) for a in args[1:]]
    results = {v: run(plugin, b, img) for v, b, img in specs}
    variants = [v for v, _, _ in specs]
    order = [n for n, _, _ in results[variants[0]]]
    table = {v: {n: (s, c) for n, s, c in results[v]} for v in variants}
    bad = 0
    lines = ["| operation | " + " | ".join(f"{v} (instructions)" for v in variants) + " |",
             "|---|" + "---:|" * len(variants)]
    for n in order:
        cells = []
        for v in variants:
            s, c = table[v].get(n, (None, None))
            if s:
                bad += 1
            cells.append("-" if c is None else (f"{c}" if not s else f"{c} (status {s}!)"))
        lines.append(f"| {n} | " + " | ".join(cells) + " |")
    text = "\n".join(lines) + "\n"
    sys.stdout.write(text)
    if out:
        with open(out, "w", encoding="utf-8") as f:
            f.write(text)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
