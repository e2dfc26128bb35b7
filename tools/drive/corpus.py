#!/usr/bin/env python3
"""make drive-corpus DIR=...: the outage test on every car drive of a folder.

    corpus.py [--bin DIR] [--work DIR] [--summary CSV] [--float] DIR

A drive is a folder holding either an rtklibexplorer drive (imu_*.csv,
imu_*.csv.tag, *.pos; its installation from tools/drive/<name>.conf, else
none) or a ublox-drives folder (imu.csv[.gz], gnss.csv[.gz],
reference_position.csv[.gz], reference_mount.csv[.gz]). DIR may be one drive
or a folder of them, searched two levels deep. Every drive goes through
se23-drive-import, se23-ins --preset car (with and without the
non-holonomic constraint) and se23-drive, with GNSS outages of 10, 30 and 60
s, one every length + 40 s from 60 s after the first fix to 30 s before the
last. The same settings for every drive: what differs is the installation
(mounting, lever arm, axes), which comes with the drive, and the rate,
measured from the time stamps.

ublox-drives: the IMU's mounting is the receiver's own estimate at the end of
the drive (reference_mount.csv, x_b = C_bv x_v, its roll/pitch/yaw those of
C_bv^T: the vehicle's attitude in the sensor frame); the antenna's lever arm
is unknown (0). Their reference is the receiver's own GNSS/IMU solution, a
metre-level peer, not truth.
"""
import csv
import gzip
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from summary import median  # noqa: E402  (tools/drive/summary.py, next to this script)

LENGTHS = (10, 30, 60)


def open_text(path):
    return gzip.open(path, "rt") if path.endswith(".gz") else open(path)


def find(folder, name):
    for suffix in ("", ".gz"):
        p = os.path.join(folder, name + suffix)
        if os.path.exists(p):
            return p
    return None


def drives(root):
    """(name, kind, folder) of every drive under root (itself included)."""
    out = []
    for d, dirs, files in os.walk(root):
        if d[len(root):].count(os.sep) > 2:
            continue
        if find(d, "imu.csv") and find(d, "gnss.csv"):
            out.append((os.path.basename(d), "ublox", d))
        elif any(f.endswith(".csv.tag") for f in files) and any(f.endswith(".pos") for f in files):
            out.append((os.path.basename(d), "rtklib", d))
        dirs.sort()
    return sorted(out)


def rpy_of(C):
    """(roll, pitch, yaw) [deg] with C = Rz(yaw) Ry(pitch) Rx(roll)."""
    return (math.degrees(math.atan2(C[2][1], C[2][2])), math.degrees(-math.asin(C[2][0])),
            math.degrees(math.atan2(C[1][0], C[0][0])))


def rot(roll, pitch, yaw):
    cr, sr = math.cos(math.radians(roll)), math.sin(math.radians(roll))
    cp, sp = math.cos(math.radians(pitch)), math.sin(math.radians(pitch))
    cy, sy = math.cos(math.radians(yaw)), math.sin(math.radians(yaw))
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def ublox_mount(folder):
    """se23-ins --mount for a ublox drive: the last row of reference_mount."""
    with open_text(find(folder, "reference_mount.csv")) as f:
        rows = [r for r in csv.reader(f)][1:]
    roll, pitch, yaw = (float(x) for x in rows[-1][1:4])
    C = rot(roll, pitch, yaw)
    Ct = [[C[j][i] for j in range(3)] for i in range(3)]
    return "%.4f,%.4f,%.4f" % rpy_of(Ct)


def conf(name):
    """The installation of an rtklib drive (tools/drive/<name>.conf)."""
    values = {"AXES": "x,y,z", "MOUNT": "0,0,0", "LEVER": "0,0,0", "IMU_TIME_OFFSET": "0"}
    short = name.replace("-drive-", "-")
    for cand in (name, short):
        p = os.path.join("tools", "drive", cand + ".conf")
        if os.path.exists(p):
            for line in open(p):
                if "=" in line and not line.startswith("#"):
                    k, v = line.strip().split("=", 1)
                    values[k] = v
    return values


def run(cmd, log):
    with open(log, "w") as f:
        return subprocess.call(cmd, stdout=f, stderr=subprocess.STDOUT)


def import_drive(b, kind, folder, name, log, outages):
    if kind == "ublox":
        cmd = [b + "/se23-drive-import", "--ublox", folder]
        inst = {"MOUNT": ublox_mount(folder), "LEVER": "0,0,0"}
    else:
        files = sorted(os.listdir(folder))
        imu = next(f for f in files if f.endswith(".csv") and f.startswith("imu"))
        tag = next(f for f in files if f.endswith(".csv.tag"))
        pos = next(f for f in files if f.endswith(".pos"))
        inst = conf(name)
        cmd = [b + "/se23-drive-import", "--rtklib"] + [os.path.join(folder, f)
                                                          for f in (imu, tag, pos)]
        cmd += ["--axes=" + inst["AXES"], "--imu-time-offset", inst["IMU_TIME_OFFSET"]]
    for s, ln in outages:
        cmd += ["--outage", "%g,%g" % (s, ln)]
    cmd += ["--out", "file://%s?mode=w" % log]
    if run(cmd, log + ".txt") != 0:
        return None
    lat = height = None
    for line in open(log + ".txt"):
        if "origin lat" in line:
            lat = float(line.split("origin lat")[1].split()[0])
            height = float(line.split(" h ")[1].split()[0])
    return inst, lat, height


def schedule(span, length):
    out, s = [], 60.0
    while s + length <= span - 30.0:
        out.append((s, float(length)))
        s += length + 40.0
    return out


def score(b, imp_log, nav_log, lever, out_csv):
    rep = nav_log + ".report.txt"
    run([b + "/se23-drive", "--lever", lever, "--csv", out_csv, imp_log, nav_log], rep)
    rows = list(csv.DictReader(open(out_csv))) if os.path.exists(out_csv) else []
    outs = list(csv.DictReader(open(out_csv.replace(".csv", ".outages.csv")))) \
        if os.path.exists(out_csv.replace(".csv", ".outages.csv")) else []
    return rows, outs


def main(argv):
    b, work, summary, precisions = "build/harness/bin", "build/harness/drive-corpus", None, ["double"]
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv else 2
    while argv and argv[0].startswith("--"):
        if argv[0] == "--float":
            precisions.append("float")
            argv = argv[1:]
            continue
        if len(argv) < 2:
            sys.exit("corpus.py: %s needs a value" % argv[0])
        key, val = argv[0], argv[1]
        argv = argv[2:]
        if key == "--bin":
            b = val
        elif key == "--work":
            work = val
        elif key == "--summary":
            summary = val
        else:
            sys.exit("corpus.py: unknown option " + key)
    if len(argv) != 1:
        sys.exit(__doc__)
    os.makedirs(work, exist_ok=True)
    found = drives(argv[0].rstrip("/"))
    if not found:
        sys.exit("drive-corpus: no drive under " + argv[0])
    table = []
    for i, (name, kind, folder) in enumerate(found):
        print("drive-corpus: [%d/%d] %s" % (i + 1, len(found), name), file=sys.stderr)
        base = os.path.join(work, name)
        got = import_drive(b, kind, folder, name, base + "-aided.log", [])
        if got is None:
            print("drive-corpus: %s: the import refused it (%s)" % (name, base + "-aided.log.txt"))
            continue
        inst, lat, height = got
        span = None
        row = {"drive": name, "kind": kind, "mount": inst["MOUNT"]}
        for p in precisions:
            ins = "se23-ins" if p == "double" else "se23-ins-float"
            nav = base + "-aided-%s.nav.log" % p
            run([b + "/" + ins, "--preset", "car", "--lat", "%.7f" % lat, "--height", "%.3f" % height,
                 "--mount", inst["MOUNT"], "--lever", inst["LEVER"], "--nav-rate", "100", "--in",
                 "file://%s?speed=0" % (base + "-aided.log"), "--out", "file://%s?mode=w" % nav],
                nav + ".txt")
            rows, _ = score(b, base + "-aided.log", nav, inst["LEVER"], base + "-aided-%s.csv" % p)
            eh = [float(r["err_h"]) for r in rows if int(r["outage"]) < 0]
            nees = [float(r["nees3"]) for r in rows if int(r["outage"]) < 0]
            row["aided_h50_" + p] = median(eh)
            row["aided_nees_" + p] = sum(nees) / len(nees) if nees else float("nan")
            if rows and span is None:
                t = [float(r["t_rel_s"]) for r in rows]
                span = max(t)
                row["dist_km"] = sum(math.hypot(float(a["ref_n"]) - float(c["ref_n"]),
                                                float(a["ref_e"]) - float(c["ref_e"]))
                                     for a, c in zip(rows[1:], rows)) / 1000.0
                row["min"] = span / 60.0
            for length in LENGTHS:
                outs = schedule(span or 0.0, length)
                if not outs:
                    continue
                log = base + "-o%d.log" % length
                if not os.path.exists(log):
                    import_drive(b, kind, folder, name, log, outs)
                for mode, extra in (("nhc", []), ("none", ["--nhc-sigma", "0"])):
                    nav = base + "-o%d-%s-%s.nav.log" % (length, mode, p)
                    run([b + "/" + ins, "--preset", "car", "--lat", "%.7f" % lat, "--height",
                         "%.3f" % height, "--mount",
                         inst["MOUNT"], "--lever", inst["LEVER"], "--nav-rate", "100"] + extra +
                        ["--in", "file://%s?speed=0" % log, "--out", "file://%s?mode=w" % nav],
                        nav + ".txt")
                    _, o = score(b, log, nav, inst["LEVER"],
                                 base + "-o%d-%s-%s.csv" % (length, mode, p))
                    row["o%d_%s_%s" % (length, mode, p)] = median(
                        [float(r["err_end_pct"]) for r in o])
                    row["o%d_%s_%s_nees" % (length, mode, p)] = median(
                        [float(r["nees_end"]) for r in o])
                    row["o%d_n" % length] = len(o)
        table.append(row)
    print_table(table, precisions)
    if summary:
        keys = sorted({k for r in table for k in r})
        with open(summary, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            w.writerows(table)
    return 0


def print_table(table, precisions):
    print("Car drives, se23-ins --preset car: horizontal error against each drive's reference"
          " with every fix (median) and its mean NEES (3 dof, ideal 3), then the median error at"
          " the end of GNSS outages in % of the distance driven in them, with NHC / without"
          " (n outages) and the median NEES at their ends with NHC (3 dof, ideal 3), double:")
    head = "%-40s %6s %5s %9s %6s" % ("drive", "km", "min", "aided m", "NEES")
    for length in LENGTHS:
        head += "  %-29s" % ("%d s: NHC / none (n) NEES" % length)
    print(head)
    for r in table:
        line = "%-40s %6.2f %5.1f %9.3f %6.2f" % (r["drive"], r.get("dist_km", float("nan")),
                                                  r.get("min", float("nan")),
                                                  r["aided_h50_double"], r["aided_nees_double"])
        for length in LENGTHS:
            k = "o%d_nhc_double" % length
            if k in r:
                line += "  %6.2f / %6.2f (%2d) %6.2f" % (r[k], r["o%d_none_double" % length],
                                                         r["o%d_n" % length], r[k + "_nees"])
            else:
                line += "  %-29s" % "-"
        print(line)
    for length in LENGTHS:
        vals = [r["o%d_nhc_double" % length] for r in table if "o%d_nhc_double" % length in r]
        none = [r["o%d_none_double" % length] for r in table if "o%d_none_double" % length in r]
        nees = [r["o%d_nhc_double_nees" % length] for r in table
                if "o%d_nhc_double" % length in r]
        print("median over the drives, %2d s outages: %.2f %% with NHC, %.2f %% without;"
              " NEES at the ends %.2f" % (length, median(vals), median(none), median(nees)))
    if "float" in precisions:
        for length in LENGTHS:
            d = [r.get("o%d_nhc_double" % length) for r in table]
            f = [r.get("o%d_nhc_float" % length) for r in table]
            pairs = [(x, y) for x, y in zip(d, f) if x is not None and y is not None]
            if pairs:
                worst = max(abs(y - x) / abs(x) for x, y in pairs if x)
                print("float against double, %2d s outages with NHC: worst relative difference"
                      " of a drive's median %.1f %%" % (length, 100 * worst))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
