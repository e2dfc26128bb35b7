"""The public functions of se23: every function declared in include/se23/*.h.

Shared by the target gates (stack budget, vector coverage). Run as a script
to print the list: /usr/bin/python3 tools/target/se23_api.py [include/se23]
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


if __name__ == "__main__":
    for name, header in public_functions(*(sys.argv[1:2] or ["include/se23"])):
        print(f"{name}\t{header}")
