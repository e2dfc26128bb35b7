"""The public functions of se23: every function declared in include/se23/*.h.

Shared by the target gates (stack budget, vector coverage).
  se23_api.py [include/se23]               print the list
  se23_api.py --coverage tests/target/tv_list.h [include/se23]
      fail unless every public function has a row in tv_list.h or is named
      in its "tested on the target without vectors" note.
  se23_api.py --contract [include/se23]
      print the contract table (tools/doc/pages/contract.md): per public function,
      what it returns and which inputs it rejects with which status, from
      the @return paragraph of its doc comment in the header.
  se23_api.py --contract-check tools/doc/pages/contract.md [include/se23]
      fail unless the page's table (between the contract markers) is the one
      --contract prints (make check: contract-page-current).
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


_DOC_DECL = re.compile(r"/\*\*((?:(?!\*/).)*?)\*/\s*\n(?!typedef|#)([A-Za-z_][\w \*]*?)\b(se23_\w+)\s*\(",
                       re.S)
BEGIN = "<!-- contract:begin (generated: python3 tools/target/se23_api.py --contract) -->"
END = "<!-- contract:end -->"


def _returns(doc):
    """The @return paragraph of a doc comment, on one line."""
    lines = [ln.strip().lstrip("*").strip() for ln in doc.splitlines()]
    text = " ".join(ln for ln in lines if ln)
    m = re.search(r"@return\s+(.*?)(?=\s@\w|$)", text)
    return m.group(1).strip() if m else ""


def contract(include_dir="include/se23"):
    """The markdown table of the contract of every public function."""
    rows = ["| function | header | returns | rejects (status: when), from the header |",
            "|---|---|---|---|"]
    for header in sorted(glob.glob(os.path.join(include_dir, "*.h"))):
        with open(header, encoding="utf-8") as f:
            text = f.read()
        seen = set()
        for m in _DOC_DECL.finditer(text):
            name, ret = m.group(3), " ".join(m.group(2).split())
            if name in seen:
                continue
            seen.add(name)
            if ret == "void":
                what = "nothing: cannot fail, does not validate"
            else:
                what = _returns(m.group(1)) or "see the header"
            what = what.replace("|", "\\|")
            rows.append(f"| `{name}` | `{os.path.basename(header)}` | `{ret}` | {what} |")
    return "\n".join(rows) + "\n"


def contract_check(page, include_dir="include/se23"):
    with open(page, encoding="utf-8") as f:
        text = f.read()
    i, j = text.find(BEGIN), text.find(END)
    if i < 0 or j < i:
        print(f"{page}: no contract markers")
        return 1
    have = text[i + len(BEGIN):j].strip("\n") + "\n"
    want = contract(include_dir)
    if have != want:
        print(f"{page}: the contract table is out of date; regenerate it with "
              "python3 tools/target/se23_api.py --contract")
        return 1
    print(f"{page}: contract table current ({want.count(chr(10)) - 2} functions)")
    return 0


def main(argv):
    if argv[:1] == ["--contract"]:
        sys.stdout.write(contract(*(argv[1:2] or ["include/se23"])))
        return 0
    if argv[:1] == ["--contract-check"]:
        return contract_check(argv[1], *(argv[2:3] or ["include/se23"]))
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
