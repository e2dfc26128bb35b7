#!/usr/bin/env python3
"""Print the cross-check table of tools/doc/pages/accuracy.md (both precisions side by side).

Runs crosscheck_so3 and crosscheck_se23 of the double and float CMake trees
(make tests-double tests-float first) and joins their rows:
    python3 tools/accuracy/crosscheck_table.py build > /tmp/xc.md
"""
import os
import re
import subprocess
import sys

PROGRAMS = ("crosscheck_so3", "crosscheck_se23")
ROW = re.compile(r"^(?P<name>\S.*?)\s{2,}(?P<kind>\S+)\s+(?P<n>\d+)\s+(?P<worst>\S+)"
                 r"\s+(?P<eps>\S+)\s+(?P<bound>\S+)\s+(?P<over>\d+)\s+\S+\s+(?P<res>\S+)$")
EPS = {"double": 2.220446049250313e-16, "float": 1.1920928955078125e-07}


def run(build, precision, program):
    exe = os.path.join(build, "cmake-" + precision, "tests", "reference", program)
    out = subprocess.run([exe], check=False, capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        m = ROW.match(line)
        if m and m.group("kind") != "error":
            rows.append(m.groupdict())
    if not rows:
        sys.exit("%s: no rows (built? make tests-%s)" % (exe, precision))
    return rows


def label(name):
    """so3_log, pi-1e-3<t<pi-1e-6 -> `so3_log`, π−1e-3 < θ < π−δ"""
    head, _, rng = name.partition(", ")
    head = head.replace("(J^-1)", "(J⁻¹)")
    m = re.match(r"^(se23_\w+|so3_\w+)(.*)$", head)
    if m:
        head = "`%s`%s" % (m.group(1), m.group(2))
    if rng:
        rng = re.sub(r"pi-1e-(\d+)$", "pi-δ", rng)
        rng = rng.replace("pi", "π").replace("-", "−").replace("<t<", " < θ < ")
        rng = rng.replace("π−1e−3", "π−1e-3").replace("2π−2e−3", "2π−2e-3")
        return head + ", " + rng
    return head


def cells(row, precision):
    if row["kind"] == "decision":
        return "%d wrong" % int(row["over"]), ""
    if row["kind"] == "exact":
        return ("0" if float(row["worst"]) == 0 else row["worst"]), ""
    return "%.2e" % float(row["worst"]), "%.2f" % (float(row["worst"]) / EPS[precision])


def bound(row):
    b = float(row["bound"]) / EPS["float"]
    if row["kind"] == "decision" or b == 0:
        return "0 wrong" if row["kind"] == "decision" else "0"
    text = ("%.0f" % b) if b >= 10 else ("%.1f" % b).rstrip("0").rstrip(".")
    return text + " ε"


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    print("| routine | error | samples | double: worst | /ε | float: worst | /ε | float bound |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    for program in PROGRAMS:
        double_rows = run(build, "double", program)
        float_rows = run(build, "float", program)
        for d, f in zip(double_rows, float_rows):
            dw, de = cells(d, "double")
            fw, fe = cells(f, "float")
            print("| %s | %s | %s | %s | %s | %s | %s | %s |" % (
                label(d["name"]), d["kind"], d["n"], dw, de, fw, fe, bound(f)))


if __name__ == "__main__":
    main()
