"""The public functions of se23: every function declared in include/se23/*.h.

Shared by the target gates (stack budget, vector coverage).
  se23_api.py [include/se23]               print the list
  se23_api.py --coverage tests/target/tv_list.h [include/se23]
      fail unless every public function has a row in tv_list.h or is named
      in its "tested on the target without vectors" note.
"""
import glob
import os
import re
import sys

# A declaration at the start of a line: return type, then se23_name(.
# Function-pointer typedefs, macros and comments do not match.
_DECL = re.compile(r"^(?!typedef|#|\s)[A-Za-z_][\w \*]*?\b(se23_\w+)\s*\(", re.M)


def _strip_comments(text):
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def public_functions(include_dir="include/se23"):
    """Sorted list of (name, header) for every public function."""
    found = {}
    for header in sorted(glob.glob(os.path.join(include_dir, "*.h"))):
        with open(header, encoding="utf-8") as f:
            text = _strip_comments(f.read())
        for m in _DECL.finditer(text):
            found.setdefault(m.group(1), header)
    return sorted(found.items())


def covered(tv_list):
    """Functions with a row in tv_list.h, plus those its note names."""
    with open(tv_list, encoding="utf-8") as f:
        text = f.read()
    rows = set(re.findall(r"^TV_\w+\(\s*(se23_\w+)", text, re.M))
    note = re.search(r"without vectors[^:]*:([^.]*)\.", text)
    return rows | (set(re.findall(r"se23_\w+", note.group(1))) if note else set())


def main(argv):
    if argv[:1] == ["--coverage"]:
        have = covered(argv[1])
        missing = [(n, h) for n, h in public_functions(*(argv[2:3] or ["include/se23"]))
                   if n not in have]
        for n, h in missing:
            print(f"{n} ({h}): no reference vectors in {argv[1]}")
        print(f"{len(have)} covered, {len(missing)} missing")
        return 1 if missing else 0
    for name, header in public_functions(*(argv[:1] or ["include/se23"])):
        print(f"{name}\t{header}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
