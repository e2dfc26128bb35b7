"""The measured tables of the manual pages (make doc-tables), as the
contract table is (tools/target/se23_api.py --contract): each command that
measures writes its table as a file into BUILD, and this script pastes the
file between the page's markers

    <!-- table:NAME begin (generated: COMMAND) -->
    ...
    <!-- table:NAME end -->

so that no measured figure is edited by hand.

  tables.py [--build BUILD] [--pages DIR] [NAME...]
      pastes every table (or the NAMEs) whose file exists in BUILD; names
      the ones whose file is missing, with the command that writes it.
  tables.py --check [--build BUILD] [--pages DIR] [--columns I,J] NAME...
      fails when a page's table differs from its file in BUILD (only the
      columns I, J, ... of each row with --columns, counted from 0: the
      instruction counts of a table whose times vary from run to run).
  tables.py --rows [--pages DIR] NAME ROW...
      fails unless the first column of the page's table, row by row, is
      ROW... (back-quotes dropped): a table that make check cannot measure
      in its time still names what is there now (every fuzz target).
  tables.py --list
      the tables: name, page, file, command.
"""
import difflib
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

# name: (page under --pages, file under --build, the command that writes it)
TABLES = {
    "target-bench": ("cortex-m-functions.md", "target/bench.md", "make bench-target"),
    "target-m4f-float": ("cortex-m-functions.md", "target/report-m4f-float.md",
                         "make report-target"),
    "target-m7-double": ("cortex-m-functions.md", "target/report-m7-double.md",
                         "make report-target"),
    "target-hot-path": ("cortex-m.md", "target/report-hot-path.md", "make report-target"),
    "target-footprint": ("cortex-m.md", "target/report-footprint.md",
                         "make gates-target report-target"),
    "host-bench": ("host-speed.md", "bench/steps.md", "make bench"),
    "fuzz": ("fuzzing-soak.md", "fuzz/fuzz.md", "make fuzz"),
    "soak": ("fuzzing-soak.md", "soak/soak.md", "make soak"),
    "soak-check": ("fuzzing-soak.md", "check/soak/soak.md", "make check, step 85-soak"),
}


def block_re(name):
    return re.compile(r"^<!-- table:" + re.escape(name) + r" begin \(generated: [^)]*\) -->\n"
                      r"(.*?)^<!-- table:" + re.escape(name) + r" end -->\n", re.M | re.S)


def page_block(pages, name):
    """(page path, page text, match of the table's block)."""
    path = os.path.join(pages, TABLES[name][0])
    with open(path, encoding="utf-8") as f:
        text = f.read()
    m = block_re(name).search(text)
    if not m:
        raise SystemExit(f"{path}: no <!-- table:{name} begin (generated: ...) --> ... "
                         f"<!-- table:{name} end --> block")
    return path, text, m


def built(build, name):
    """The file's text, ending in one newline, or None if it is missing."""
    path = os.path.join(build, TABLES[name][1])
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as f:
        return f.read().strip("\n") + "\n"


def cells(line, columns):
    parts = [c.strip() for c in line.strip().strip("|").split("|")]
    return [parts[i] if i < len(parts) else "" for i in columns]


def same(page, build, columns):
    if columns is None:
        return page == build
    a = [cells(x, columns) for x in page.splitlines() if x.startswith("|")]
    b = [cells(x, columns) for x in build.splitlines() if x.startswith("|")]
    return a == b


def paste(args, build, pages):
    names = args or list(TABLES)
    missing = 0
    for name in names:
        text = built(build, name)
        page, _, cmd = TABLES[name]
        if text is None:
            missing += 1
            print(f"  kept    {name:18} {page}: no {build}/{TABLES[name][1]} (run {cmd})")
            continue
        path, old, m = page_block(pages, name)
        new = (old[:m.start()] + f"<!-- table:{name} begin (generated: {cmd}) -->\n" + text +
               f"<!-- table:{name} end -->\n" + old[m.end():])
        if new != old:
            with open(path, "w", encoding="utf-8") as f:
                f.write(new)
        print(f"  {'pasted' if new != old else 'current':7} {name:18} {page} "
              f"from {build}/{TABLES[name][1]}")
    return 0


def check(names, build, pages, columns):
    bad = 0
    for name in names:
        text = built(build, name)
        page, rel, cmd = TABLES[name]
        if text is None:
            print(f"{name}: no {build}/{rel} (run {cmd})")
            bad += 1
            continue
        path, _, m = page_block(pages, name)
        if same(m.group(1), text, columns):
            print(f"{name}: {path} is current with {build}/{rel}")
            continue
        bad += 1
        print(f"{name}: {path} is not what {cmd} measures now ({build}/{rel}); "
              f"run {cmd}, then make doc-tables")
        sys.stdout.writelines(difflib.unified_diff(
            m.group(1).splitlines(True), text.splitlines(True), path, f"{build}/{rel}"))
    return 1 if bad else 0


def rows(name, want, pages):
    path, _, m = page_block(pages, name)
    got = [cells(x, [0])[0].replace("`", "")
           for x in m.group(1).splitlines() if x.startswith("|")][2:]
    if got == want:
        print(f"{name}: {path} has one row per target now ({len(want)} rows)")
        return 0
    print(f"{name}: {path}'s rows are not the current ones")
    sys.stdout.writelines(difflib.unified_diff([g + "\n" for g in got], [w + "\n" for w in want],
                                               path, "now"))
    return 1


def main(argv):
    build, pages, columns, mode = "build", os.path.relpath(os.path.join(HERE, "pages")), None, "paste"
    rest = []
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("--build", "--pages", "--columns"):
            if i + 1 >= len(argv):
                raise SystemExit(__doc__)
            v = argv[i + 1]
            if a == "--build":
                build = v
            elif a == "--pages":
                pages = v
            else:
                columns = [int(c) for c in v.split(",")]
            i += 2
            continue
        if a in ("--check", "--rows", "--list"):
            mode = a[2:]
        elif a.startswith("--"):
            raise SystemExit(__doc__)
        else:
            rest.append(a)
        i += 1
    if mode == "list":
        for name, (page, rel, cmd) in TABLES.items():
            print(f"{name:18} {page:24} BUILD/{rel:28} {cmd}")
        return 0
    if mode == "rows":
        if not rest or rest[0] not in TABLES:
            raise SystemExit(__doc__)
        return rows(rest[0], rest[1:], pages)
    unknown = [n for n in rest if n not in TABLES]
    if unknown:
        raise SystemExit(f"unknown table(s) {', '.join(unknown)}; tables.py --list")
    if mode == "check":
        if not rest:
            raise SystemExit(__doc__)
        return check(rest, build, pages, columns)
    return paste(rest, build, pages)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
