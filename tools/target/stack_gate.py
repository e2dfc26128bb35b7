"""Worst-case stack per public function of the se23 library on a Cortex-M
target, including every callee, checked against a budget file.

  stack_gate.py LIBDIR IMAGE[,IMAGE...] BUDGET COLUMN [--include DIR]

LIBDIR   build/lib-<variant>: the library objects with their -fstack-usage
         (.su) and -fcallgraph-info=su (.ci) files.
IMAGE    linked images of the same variant (the target test images), comma-
         separated, that together hold the newlib functions the library
         calls (sqrtf, sinf, memcpy, __aeabi_l2f, ...): the vector image
         links every routine but the navigation filter, the replay image
         (ins_replay.elf) the filter.
BUDGET   tests/target/budgets/stack.txt: "function column1 column2 ..." rows.
COLUMN   the budget column (m4f-float, m7-double).

Method. Library functions: the frame GCC reports in the .ci graph (the same
number as in the .su file); a "dynamic" frame (VLA, alloca) is an error.
Indirect calls (__indirect_call in the graph) may reach any library function
whose address is taken (an R_ARM_ABS32/MOVW/MOVT relocation against a text
symbol): the worst of those is charged. Functions outside the library (newlib)
have no .su file: their frame is read from the image's disassembly as the sum
of every stack-pointer decrement in the function body (push, stmdb sp!,
vpush, sub sp, str/strd with sp pre-decrement), which over-approximates when
different paths push separately; their callees are the bl/b targets that are
other functions (tail calls are charged at the full frame). Recursion and an
indirect call in newlib code are errors. Worst = frame + max over callees.

Exit status: 0 if every public function has a budget and stays within it.
"""
import argparse
import glob
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from se23_api import public_functions  # noqa: E402

OBJDUMP = os.environ.get("ARM_OBJDUMP", "arm-none-eabi-objdump")
NM = os.environ.get("ARM_NM", "arm-none-eabi-nm")
INDIRECT = "__indirect_call"


class Graph:
    def __init__(self):
        self.frame = {}    # title -> bytes
        self.calls = {}    # title -> set of titles
        self.where = {}    # title -> "file:line" (library functions)

    def add_call(self, a, b):
        self.calls.setdefault(a, set()).add(b)


def parse_ci(libdir, g):
    node = re.compile(r'node: \{ title: "([^"]+)" label: "([^"]*)"')
    edge = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
    for ci in sorted(glob.glob(os.path.join(libdir, "*.ci"))):
        with open(ci, encoding="utf-8") as f:
            for line in f:
                m = node.search(line)
                if m:
                    parts = m.group(2).split("\\n")
                    sz = re.match(r"(\d+) bytes \(([\w,]+)\)", parts[-1]) if len(parts) >= 3 else None
                    if sz:
                        if sz.group(2) != "static":
                            raise SystemExit(f"{m.group(1)} ({parts[1]}): {sz.group(2)} stack "
                                             "(VLA or alloca) -- not allowed in the library")
                        g.frame[m.group(1)] = int(sz.group(1))
                        g.where[m.group(1)] = parts[1]
                    continue
                m = edge.search(line)
                if m:
                    g.add_call(m.group(1), m.group(2))


def address_taken(libdir, g):
    """Library functions whose address is taken (possible indirect targets)."""
    taken = set()
    # The objects are flat (ins.o); the sources sit in layer folders
    # (src/nav/ins.c), which is how the call graph names their statics.
    sources = {os.path.basename(s): s for s in glob.glob("src/**/*.c", recursive=True)}
    for obj in sorted(glob.glob(os.path.join(libdir, "*.o"))):
        src = sources.get(os.path.basename(obj)[:-2] + ".c", "")
        text_syms = set()
        for line in subprocess.run([NM, obj], check=True, capture_output=True,
                                   text=True).stdout.splitlines():
            parts = line.split()
            if len(parts) == 3 and parts[1] in "tT":
                text_syms.add(parts[2])
        for line in subprocess.run([OBJDUMP, "-r", obj], check=True, capture_output=True,
                                   text=True).stdout.splitlines():
            parts = line.split()
            if len(parts) != 3 or parts[1] in ("R_ARM_THM_CALL", "R_ARM_THM_JUMP24",
                                                "R_ARM_THM_JUMP19", "R_ARM_CALL"):
                continue
            sym = parts[2].split("+")[0]
            if sym.startswith(".text."):
                sym = sym[len(".text."):]
            elif sym not in text_syms:
                continue
            title = f"{src}:{sym}" if f"{src}:{sym}" in g.frame else sym
            if title in g.frame:
                taken.add(title)
    return taken


_REGS = re.compile(r"\{([^}]*)\}")


def _reglist_bytes(text, vector=False):
    total = 0
    for item in _REGS.search(text).group(1).split(","):
        item = item.strip()
        size = 8 if item.startswith("d") else 4
        m = re.match(r"([a-z]+)(\d+)-[a-z]+(\d+)", item)
        total += size * (int(m.group(3)) - int(m.group(2)) + 1) if m else size
    return total


def parse_image(image):
    """frame and callees of every function of a linked image, by disassembly."""
    out = subprocess.run([OBJDUMP, "-d", "--no-show-raw-insn", image], check=True,
                         capture_output=True, text=True).stdout
    funcs = {}
    cur = None
    head = re.compile(r"^[0-9a-f]+ <([^>]+)>:$")
    for line in out.splitlines():
        m = head.match(line)
        if m:
            cur = m.group(1)
            funcs[cur] = {"frame": 0, "calls": set(), "error": None}
            continue
        if cur is None or "\t" not in line:
            continue
        ins = line.split("\t", 1)[1].strip()
        op = ins.split()[0] if ins else ""
        f = funcs[cur]
        if op in ("push", "push.w", "vpush", "vpush.64", "vpush.32") or \
                (op.startswith("stmdb") and ins.split()[1].startswith("sp!")):
            f["frame"] += _reglist_bytes(ins)
        elif re.match(r"(sub|subw|sub\.w)\s+sp,\s*(sp,\s*)?#(\d+)", ins):
            f["frame"] += int(re.match(r"(sub|subw|sub\.w)\s+sp,\s*(sp,\s*)?#(\d+)", ins).group(3))
        elif re.match(r"(sub|sub\.w)\s+sp,\s*(sp,\s*)?r", ins):
            f["error"] = f"dynamic stack: {ins}"
        elif re.match(r"str[a-z.]*\s.*\[sp,\s*#-(\d+)\]!", ins):
            f["frame"] += int(re.search(r"\[sp,\s*#-(\d+)\]!", ins).group(1))
        elif op.startswith("blx") and "<" not in ins:
            f["error"] = f"indirect call: {ins}"
        elif op.startswith("b"):
            t = re.search(r"<([^>+]+)>$", ins)
            if t and t.group(1) != cur:
                f["calls"].add(t.group(1))
    return funcs


class Worst:
    def __init__(self, g, taken, image_funcs):
        self.g, self.taken, self.img = g, taken, image_funcs
        self.memo = {}
        self.active = []

    def __call__(self, fn):
        """(worst bytes, deepest path) for fn."""
        if fn in self.memo:
            return self.memo[fn]
        if fn in self.active:
            raise SystemExit("recursion: " + " -> ".join(self.active[self.active.index(fn):] + [fn]))
        self.active.append(fn)
        if fn in self.g.frame:
            frame = self.g.frame[fn]
            callees = set(self.g.calls.get(fn, ()))
            if INDIRECT in callees:
                callees.discard(INDIRECT)
                if not self.taken:
                    raise SystemExit(f"{fn}: indirect call, but no address-taken function")
                callees |= self.taken
        else:
            name = fn.split(":")[-1]
            f = self.img.get(name)
            if f is None:
                raise SystemExit(f"{fn}: not in the library and not in the images -- "
                                 "link it into a target test image")
            if f["error"]:
                raise SystemExit(f"{name} (newlib): {f['error']}")
            frame, callees = f["frame"], f["calls"]
        best, path = 0, []
        for c in sorted(callees):
            w, p = self(c)
            if w > best:
                best, path = w, p
        self.active.pop()
        self.memo[fn] = (frame + best, [fn.split(":")[-1]] + path)
        return self.memo[fn]


def read_budget(path, column):
    rows, cols = {}, None
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if not line:
                continue
            if cols is None:
                cols = line[1:]
                if column not in cols:
                    raise SystemExit(f"{path}: no column {column}")
                continue
            rows[line[0]] = int(line[1 + cols.index(column)])
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("libdir")
    ap.add_argument("image")
    ap.add_argument("budget")
    ap.add_argument("column")
    ap.add_argument("--include", default="include/se23")
    ap.add_argument("--roots", help="comma-separated functions to analyse instead of "
                    "the public API (for the gate's own tests)")
    a = ap.parse_args()

    g = Graph()
    parse_ci(a.libdir, g)
    image_funcs = {}
    for image in a.image.split(","):
        for name, f in parse_image(image).items():
            image_funcs.setdefault(name, f)
    worst = Worst(g, address_taken(a.libdir, g), image_funcs)
    budget = read_budget(a.budget, a.column)
    fails = 0
    print(f"{'function':30} {'own':>5} {'worst':>6} {'budget':>6}  deepest path ({a.column})")
    roots = a.roots.split(",") if a.roots else [n for n, _ in public_functions(a.include)]
    for name in roots:
        if name not in g.frame:
            print(f"{name:30} not in {a.libdir} (not compiled?)")
            fails += 1
            continue
        w, path = worst(name)
        b = budget.get(name)
        verdict = "ok" if b is not None and w <= b else ("NO BUDGET" if b is None else "OVER")
        fails += verdict != "ok"
        print(f"{name:30} {g.frame[name]:5d} {w:6d} {b if b is not None else '-':>6}  "
              f"{' > '.join(path)}  {verdict if verdict != 'ok' else ''}")
    print(f"{fails} function(s) over or without budget")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
