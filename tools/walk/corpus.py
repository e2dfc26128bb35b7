#!/usr/bin/python3
"""The pedestrian filter on a folder of real foot-mounted recordings.

  corpus.py --bin BIN --run RUNDIR [--precision double|float|both] DIR...

finds the recordings under each DIR by their layout (the formats of
../shared/data/foot and the x-io walk, tools/doc/pages/walks.md), and for each:
imports it (se23-import, the column mapping of its format and nothing
else), runs the pedestrian preset (se23-ins --preset foot, the rate the
import measured), reads the per-state CSV se23-walk writes and scores it
against the recording's truth. Prints one table; exits 1 if a recording
could not be run.

Scores (tools/doc/pages/walks.md):
  dist      the distance walked: the truth's path where there is one, else
            the estimate's through its stance positions
  closure   the position at the start of the last stance, and at the end,
            minus the start, against the truth's displacement over the same
            span (0 for a closed loop); horizontal, after the heading
            alignment below where the truth has a frame of its own
  rmse      horizontal RMS error against per-sample truth or footprints
  nees      e^T C^-1 e of the horizontal error (2 dof) with C the filter's
            position covariance, averaged over the truth samples, and the
            closure's at the end; for a closed loop without other truth
            the closure's normalised error (3 dof)
The heading and the start are the filter's own (no magnetometer): truth is
moved to start at the filter's start and turned about the vertical by the
PyShoe rule (Wagstaff et al. 2020, the estimate's direction when it first
lies 0.8 m from the start, horizontally, is the truth's at that sample), or
for footprints the direction from footprint 0 to footprint 3, as their
authors score them. The first 0.8 m are then error-free by construction, so
the time-averaged NEES leans low; the closure's is not affected.
"""
import argparse
import csv
import glob
import math
import os
import re
import subprocess
import sys

import numpy as np

G0 = 9.80665
# chi^2 99 % quantiles
CHI2_99 = {2: 9.21, 3: 11.34}
PRECISIONS = {"double": "se23-ins", "float": "se23-ins-float"}
# a right-handed z-up frame to one with z down (north-east-down up to a turn
# about the vertical, which the heading alignment takes)
Z_UP = np.array([1.0, -1.0, -1.0])


class Recording:
    """One recording: its CSV, the import's column mapping, its truth."""

    def __init__(self, name, csv_path, import_opts, lat, truth, kind):
        self.name = name
        self.csv = csv_path
        self.import_opts = import_opts
        self.lat = lat
        self.truth = truth  # callable(rec, nav) -> dict of scores
        self.kind = kind


# ---------------------------------------------------------------- readers


def find_recordings(top):
    """Recordings under top, by the layout of each corpus format."""
    recs = []
    for root, _dirs, files in sorted(os.walk(top)):
        fs = set(files)
        if "short_walk.csv" in fs:
            recs.append(Recording("xio-short-walk", os.path.join(root, "short_walk.csv"),
                                  [], 51.45, score_closed_loop, "closed loop"))
        if {"imu_sample_not_rotated.csv", "mocap_sample.csv"} <= fs:
            recs += gaitmap(root)
        if {"imuMeasLeft.csv", "positionGt.csv"} <= fs:
            recs += fgo(root)
        for f in sorted(fs):
            m = re.fullmatch(r"SensorConnectData_(\d+)\.csv", f)
            if m and f"SensorConnectData_{m.group(1)}_gcp.csv" in fs:
                recs.append(gdin(root, m.group(1)))
            elif f.endswith(".csv") and first_line(os.path.join(root, f)).startswith(
                    "t_s,gyro_x_rad_s"):
                recs.append(pyshoe(root, f))
    return recs


def first_line(path):
    with open(path, encoding="utf-8", errors="replace") as fh:
        return fh.readline()


def gaitmap(root):
    """NilsPod, 204.8 Hz, no time column; the raw sensor axes (the range is
    the sensor's per axis), left then right foot."""
    out = []
    mocap = np.genfromtxt(os.path.join(root, "mocap_sample.csv"), delimiter=",", skip_header=2)
    for side, first, heel in (("left", 2, 7), ("right", 8, 10)):
        acc = ",".join(str(first + i) for i in range(3))
        gyr = ",".join(str(first + 3 + i) for i in range(3))
        truth_p = mocap[:, heel:heel + 3] * 1e-3 * Z_UP
        truth_t = mocap[:, 0] / 100.0
        opts = ["--header", "2", "--time-col", "0", "--rate", "204.8", "--accel-cols", acc,
                "--gyro-cols", gyr, "--accel-unit", "m/s2", "--gyro-unit", "deg/s"]
        out.append(Recording(f"gaitmap-{side}",
                             os.path.join(root, "imu_sample_not_rotated.csv"), opts, 49.6,
                             per_sample_truth(truth_t, truth_p), "mocap, heel marker"))
    return out


def fgo(root):
    """Two feet at 60 Hz, time_index column, per-sample truth (z down)."""
    out = []
    gt = np.genfromtxt(os.path.join(root, "positionGt.csv"), delimiter=",", skip_header=1)
    for side, f, cols in (("left", "imuMeasLeft.csv", slice(1, 4)),
                          ("right", "imuMeasRight.csv", slice(4, 7))):
        opts = ["--time-col", "0", "--rate", "60", "--accel-cols", "2,3,4",
                "--gyro-cols", "5,6,7", "--accel-unit", "m/s2", "--gyro-unit", "rad/s"]
        # its README: the truth's z points down (a right-handed frame, checked:
        # its turns have the gyroscope's sense)
        out.append(Recording(f"fgo-{side}", os.path.join(root, f), opts, 44.99,
                             per_sample_truth(gt[:, 0] / 60.0, gt[:, cols]),
                             "per-sample position"))
    return out


def gdin(root, nn):
    """LORD 3DM-GX5-25 at 200 Hz, g and rad/s; surveyed footprints."""
    base = os.path.join(root, f"SensorConnectData_{nn}")
    gcp = np.genfromtxt(base + "_gcp.csv", delimiter=",", skip_header=1)
    strides = np.genfromtxt(base + "_strideIndex_timestamp_gcpX_gcpY.csv", delimiter=",",
                            skip_header=1)
    # gdin's README: recording 40's Time column is irregular; its rows are 200 Hz
    time = ["--time-col", "0", "--rate", "200"] if nn == "40" else []
    opts = time + ["--accel-cols", "2,3,4", "--gyro-cols", "5,6,7", "--accel-unit", "g",
                   "--gyro-unit", "rad/s"]
    row_t = strides[:, 0] / 200.0 if nn == "40" else strides[:, 1]
    n = min(len(gcp), len(row_t))
    # the survey's 2-D frame is mirrored against the walk; its author flips y
    # before plotting, and so does this
    return Recording(f"gdin-{nn}", base + ".csv", opts, 39.9,
                     footprint_truth(row_t[:n], gcp[:n, 1:3] * np.array([1.0, -1.0])),
                     "surveyed footprints")


def pyshoe(root, f):
    """PyShoe Vicon trial: 200 Hz, rad/s, m/s^2, per-sample Vicon."""
    d = np.genfromtxt(os.path.join(root, f), delimiter=",", skip_header=1, usecols=(0, 7, 8, 9))
    opts = ["--gyro-cols", "2,3,4", "--accel-cols", "5,6,7", "--accel-unit", "m/s2",
            "--gyro-unit", "rad/s"]
    # Vicon's (x, y) is mirrored against the walk: on every trial with turns,
    # the path's sense is the opposite of the gyroscope's about the vertical
    # in the right-handed reading; so (x, y, z up) maps to (x, y, -z)
    return Recording("pyshoe-" + f[:-4], os.path.join(root, f), opts, 43.66,
                     per_sample_truth(d[:, 0], d[:, 1:4] * np.array([1.0, 1.0, -1.0])),
                     "Vicon")


# ---------------------------------------------------------------- scoring


def rotation(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s], [s, c]])


def heading_fit(est_h, tru_h, k):
    """Rotation about the vertical (2x2) taking the truth's direction from
    the start at sample k onto the estimate's (both relative to the start)."""
    return rotation(math.atan2(est_h[k, 1], est_h[k, 0]) - math.atan2(tru_h[k, 1], tru_h[k, 0]))


def first_beyond(est_h, r=0.8):
    k = np.flatnonzero(np.hypot(est_h[:, 0], est_h[:, 1]) > r)
    return k[0] if len(k) else len(est_h) - 1


def hcov(nav, idx):
    return np.stack([np.stack([nav["cNN"][idx], nav["cNE"][idx]], -1),
                     np.stack([nav["cNE"][idx], nav["cEE"][idx]], -1)], -2)


def with_alignment(C, est_h, k):
    """The comparison's covariance: the filter's, plus what the heading
    alignment at sample k adds. The fitted angle's error is the estimate's
    error across its direction there over its distance, variance
    s2 = u^T C_k u / |r_k|^2 (u the unit normal of r_k), and turns every
    later point r by it: + s2 (J r)(J r)^T, J the quarter turn."""
    r_k = est_h[k]
    d2 = float(r_k @ r_k)
    if d2 <= 0.0:
        return C
    u = np.array([-r_k[1], r_k[0]]) / math.sqrt(d2)
    s2 = float(u @ C[k] @ u) / d2
    jr = np.column_stack([-est_h[:, 1], est_h[:, 0]])
    return C + s2 * jr[:, :, None] * jr[:, None, :]


def nees2(e, C):
    return np.einsum("ni,nij,nj->n", e, np.linalg.inv(C), e)


def per_sample_truth(t_truth, p_truth):
    def score(nav):
        t = nav["t_ns"] * 1e-9
        keep = np.flatnonzero((t >= t_truth[0]) & (t <= t_truth[-1]))
        tp = np.column_stack([np.interp(t[keep], t_truth, p_truth[:, i]) for i in range(3)])
        est = np.column_stack([nav["pN"], nav["pE"], nav["pD"]])[keep]
        est_h = est[:, :2] - est[0, :2]
        tp = tp - tp[0]
        k = first_beyond(est_h)
        rot = heading_fit(est_h, tp[:, :2], k)
        tp[:, :2] = tp[:, :2] @ rot.T
        e = est_h - tp[:, :2]
        n2 = nees2(e, with_alignment(hcov(nav, keep), est_h, k))
        eh = np.hypot(e[:, 0], e[:, 1])
        return {"rmse": float(np.sqrt(np.mean(eh ** 2))),
                "armse": float(np.mean(eh / math.sqrt(2))),
                "dist": float(np.sum(np.hypot(*np.diff(tp[:, :2], axis=0).T))),
                "nees": float(np.mean(n2[1:])), "nees_end": float(n2[-1]), "dof": 2,
                "truth_disp": tp[-1], "rot": rot, "path": (est_h, tp[:, :2])}
    return score


def footprint_truth(t_rows, gcp):
    def score(nav):
        t = nav["t_ns"] * 1e-9
        idx = np.searchsorted(t, t_rows).clip(0, len(t) - 1)
        full = np.column_stack([nav["pN"], nav["pE"]])
        est_h = full[idx] - full[idx[0]]
        k = min(3, len(gcp) - 1)
        tp = (gcp - gcp[0]) @ heading_fit(est_h, gcp - gcp[0], k).T
        e = est_h - tp
        n2 = nees2(e, with_alignment(hcov(nav, idx), est_h, k))
        eh = np.hypot(e[:, 0], e[:, 1])
        disp = np.zeros(3)
        disp[:2] = tp[-1]
        return {"rmse": float(np.sqrt(np.mean(eh[1:] ** 2))), "nees": float(np.mean(n2[1:])),
                "dist": float(np.sum(np.hypot(*np.diff(tp, axis=0).T))),
                "nees_end": float(n2[-1]), "dof": 2, "truth_disp_h": disp,
                "path": (full - full[idx[0]], tp)}
    return score


def score_closed_loop(nav):
    return {"truth_disp": np.zeros(3)}  # nav unused: the loop is closed


# ---------------------------------------------------------------- running


def run(cmd, log):
    with open(log, "w") as fh:
        r = subprocess.run(cmd, stdout=fh, stderr=subprocess.STDOUT)
    return r.returncode


def read_nav(path):
    d = np.genfromtxt(path, delimiter=",", names=True)
    return d


def counters(path):
    c = {}
    with open(path) as fh:
        for line in fh:
            f = line.split()
            if len(f) == 2:
                c[f[0]] = f[1]
    return c


def stance_starts(nav, merge=0.1):
    st = nav["stance"] > 0.5
    t = nav["t"]
    starts, last = [], -1e9
    for k in np.flatnonzero(st & ~np.r_[False, st[:-1]]):
        if t[k] - last > merge:
            starts.append(k)
        j = k
        while j + 1 < len(st) and st[j + 1]:
            j += 1
        last = t[j]
    return starts


def evaluate(rec, nav, summ):
    p = np.column_stack([nav["pN"], nav["pE"], nav["pD"]])
    starts = stance_starts(nav)
    last = starts[-1] if starts else len(p) - 1
    dist = float(np.sum(np.linalg.norm(np.diff(p[[0] + starts], axis=0), axis=1))) \
        if starts else 0.0
    sc = rec.truth(nav)
    # the distance walked: the truth's where there is one (the estimate's
    # stance positions miss a stride the detector missed)
    out = {"dist": sc.get("dist", dist), "stances": len(starts), "p": p[:, :2] - p[0, :2],
           "floor": summ.get("floor_levels", "?"), "range": summ.get("imu_range", "?"), "sc": sc,
           "noise": (summ.get("gyro_noise_dps_rthz", "nan"), summ.get("accel_noise_ug_rthz", "nan"))}
    for tag, k in (("last", last), ("end", len(p) - 1)):
        e = p[k] - p[0]
        if "truth_disp" in sc:
            td = sc["truth_disp"]
            e = e - td
        elif "truth_disp_h" in sc:
            e = e - sc["truth_disp_h"]
            e[2] = 0.0
        out["c3_" + tag] = float(np.linalg.norm(e))
        out["ch_" + tag] = float(np.hypot(e[0], e[1]))
        c = np.array([[nav["cNN"][k], nav["cNE"][k], nav["cND"][k]],
                      [nav["cNE"][k], nav["cEE"][k], nav["cED"][k]],
                      [nav["cND"][k], nav["cED"][k], nav["cDD"][k]]])
        if "truth_disp_h" in sc:
            out["nc_" + tag] = float(e[:2] @ np.linalg.solve(c[:2, :2], e[:2]))
        else:
            out["nc_" + tag] = float(e @ np.linalg.solve(c, e))
    return out


# The runs of each recording: name -> (program, extra se23-ins options).
# "floor": the double filter with the floor assumption (ins.h, "Floor"),
# off in the preset and reported apart: does it invent a level?
RUNS = {"double": ("se23-ins", []), "float": ("se23-ins-float", []),
        "floor": ("se23-ins", ["--floor-sigma", "0.01"])}


def run_filter(a, rec, w, name):
    """One se23-ins run of the imported log and its se23-walk CSV; the
    evaluation, or None if a program failed."""
    prog, opts = RUNS[name]
    # the rate is the log's (se23-import measured it); a state per sample
    ins = [os.path.join(a.bin, prog), "--preset", "foot", "--nav-rate", "100000",
           "--lat", str(rec.lat), "--in", f"file://{w}/imu.log?speed=0",
           "--out", f"file://{w}/ins-{name}.log?mode=w"] + opts + a.ins_opts.split()
    wk = [os.path.join(a.bin, "se23-walk"), "--csv", f"{w}/walk-{name}.csv",
          f"{w}/ins-{name}.log"]
    if run(ins, f"{w}/ins-{name}.txt") != 0 or run(wk, f"{w}/walk-{name}.txt") != 0:
        print(f"corpus: {rec.name}: the {name} run failed, see {w}", file=sys.stderr)
        return None
    summ = counters(f"{w}/ins-{name}.txt")
    r = evaluate(rec, read_nav(f"{w}/walk-{name}.csv"), summ)
    r["rate"] = float(summ.get("imu_rate_hz", "nan"))
    return r


def plot_paths(path, rows, run):
    """Top views, one per recording: the estimate and its aligned truth."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = len(rows)
    cols = 6
    fig, axes = plt.subplots((n + cols - 1) // cols, cols, figsize=(3 * cols, 3 * ((n + cols - 1) // cols)))
    for ax in np.ravel(axes)[n:]:
        ax.axis("off")
    for ax, (rec, res) in zip(np.ravel(axes), rows):
        r = res.get(run)
        if r is None or "path" not in r["sc"]:
            est = r["p"] if r is not None else None
            if est is not None:
                ax.plot(est[:, 1], est[:, 0], lw=0.7, color="tab:blue")
                ax.plot([0], [0], "k^", ms=4)
        else:
            est, tru = r["sc"]["path"]
            marker = "o" if len(tru) < 200 else None
            ax.plot(tru[:, 1], tru[:, 0], lw=0.7, color="tab:gray", marker=marker, ms=2)
            ax.plot(est[:, 1], est[:, 0], lw=0.7, color="tab:blue")
        ax.set_title(f"{rec.name}\nH end {r['ch_end']:.2f} m" if r else rec.name, fontsize=8)
        ax.set_aspect("equal", "datalim")
        ax.tick_params(labelsize=6)
    fig.suptitle(f"se23 pedestrian preset ({run}): estimate (blue) and truth (grey), "
                 "north up, metres", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    fig.savefig(path, dpi=60)


def write_summary(path, rows):
    """One line per recording and run: the table's figures, for scripts."""
    with open(path, "w", newline="") as fh:
        out = csv.writer(fh)
        out.writerow(["recording", "run", "rate_hz", "dist_m", "stances", "c3_last", "ch_last",
                      "c3_end", "ch_end", "nc_end", "rmse_h", "armse", "nees_avg", "nees_end",
                      "floor_levels", "imu_range", "gyro_noise_dps_rthz", "accel_noise_ug_rthz"])
        for rec, res in rows:
            for name, r in res.items():
                sc = r["sc"]
                out.writerow([rec.name, name, f"{r['rate']:.3f}", f"{r['dist']:.3f}",
                              r["stances"], f"{r['c3_last']:.4f}", f"{r['ch_last']:.4f}",
                              f"{r['c3_end']:.4f}", f"{r['ch_end']:.4f}", f"{r['nc_end']:.3f}",
                              f"{sc.get('rmse', float('nan')):.4f}",
                              f"{sc.get('armse', float('nan')):.4f}",
                              f"{sc.get('nees', float('nan')):.3f}",
                              f"{sc.get('nees_end', float('nan')):.3f}", r["floor"],
                              r["range"], r["noise"][0], r["noise"][1]])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", required=True)
    ap.add_argument("--run", required=True)
    ap.add_argument("--runs", default="double,float,floor",
                    help="which runs, of " + ",".join(RUNS) + " (the first is tabled)")
    ap.add_argument("--summary", help="write every run's figures to this CSV")
    ap.add_argument("--plot", help="top views of every recording into this PNG")
    ap.add_argument("--ins-opts", default="", help="extra se23-ins options (experiments)")
    ap.add_argument("dirs", nargs="+")
    a = ap.parse_args()
    runs = a.runs.split(",")
    if not runs or any(r not in RUNS for r in runs):
        print(f"corpus: --runs takes {','.join(RUNS)}", file=sys.stderr)
        return 2
    recs = []
    for d in a.dirs:
        recs += find_recordings(d)
    if not recs:
        print("corpus: no recording found under " + " ".join(a.dirs), file=sys.stderr)
        return 1
    os.makedirs(a.run, exist_ok=True)
    rows, failed = [], 0
    for i, rec in enumerate(recs):
        print(f"corpus: [{i + 1}/{len(recs)}] {rec.name}", file=sys.stderr)
        w = os.path.join(a.run, rec.name)
        os.makedirs(w, exist_ok=True)
        imp = [os.path.join(a.bin, "se23-import"), "--out", f"file://{w}/imu.log?mode=w"] + \
            rec.import_opts + [rec.csv]
        if run(imp, f"{w}/import.txt") != 0:
            print(f"corpus: {rec.name}: import failed, see {w}/import.txt", file=sys.stderr)
            failed += 1
            continue
        res = {}
        for name in runs:
            r = run_filter(a, rec, w, name)
            if r is None:
                failed += 1
            else:
                res[name] = r
        if res:
            rows.append((rec, res))
    print_table(rows, runs)
    if a.summary:
        write_summary(a.summary, rows)
    if a.plot:
        plot_paths(a.plot, rows, runs[0])
    return 1 if failed else 0


# PyShoe's published per-trial error of its SHOE detector, each threshold
# tuned on that trial against Vicon (../shared/data/foot/pyshoe-vicon/
# README.md): the median over the 17 trials there, metres of ARMSE.
PYSHOE_SHOE_MEDIAN = 0.050


def print_table(rows, runs):
    p0 = runs[0]
    hdr = ("recording", "Hz", "noise", "dist m", "stances", "closure 3D/H last",
           "closure 3D/H end", "H % dist", "rmse H", "ARMSE", "NEES avg/end", "bound", "range")
    fmt = "{:<28} {:>6} {:>10} {:>7} {:>7} {:>17} {:>17} {:>8} {:>7} {:>6} {:>13} {:>6} {:>5}"
    extra = ("  float H end" if "float" in runs[1:] else "") + \
        ("  floor: levels, H end" if "floor" in runs[1:] else "")
    print(f"run: {p0}; noise: the white noise the filter took from the first rest, gyro "
          f"deg/s/sqrt(Hz) and accelerometer ug/sqrt(Hz) (floors 0.007 and 180); float: the "
          f"float build's horizontal closure at the end; floor: the levels the floor "
          f"assumption counts (one floor: 1) and its closure")
    print(fmt.format(*hdr) + extra)
    armse, in_avg, in_end, n_truth, pct_ok = [], 0, 0, 0, 0
    for rec, res in rows:
        r = res.get(p0)
        if r is None:
            continue
        sc = r["sc"]
        if "nees" in sc:
            nees = f"{sc['nees']:.1f}/{sc['nees_end']:.1f}"
            bound = CHI2_99[sc["dof"]]
            n_truth += 1
            in_avg += sc["nees"] <= bound
            in_end += sc["nees_end"] <= bound
        else:
            nees = f"-/{r['nc_end']:.1f}"
            bound = CHI2_99[3]
            n_truth += 1
            in_avg += 1
            in_end += r["nc_end"] <= bound
        pct = 100 * r["ch_end"] / max(r["dist"], 1e-9)
        pct_ok += pct <= 0.3
        if rec.name.startswith("pyshoe-"):
            armse.append(sc["armse"])
        line = fmt.format(
            rec.name, f"{r['rate']:.1f}",
            f"{float(r['noise'][0]):.3f}/{float(r['noise'][1]):.0f}", f"{r['dist']:.1f}",
            r["stances"],
            f"{r['c3_last']:.3f}/{r['ch_last']:.3f}", f"{r['c3_end']:.3f}/{r['ch_end']:.3f}",
            f"{pct:.2f}", f"{sc['rmse']:.3f}" if "rmse" in sc else "-",
            f"{sc['armse']:.3f}" if "armse" in sc else "-", nees, f"{bound:.2f}", r["range"])
        if "float" in runs[1:]:
            line += f"  {res['float']['ch_end']:11.3f}" if "float" in res else "  " + "-" * 11
        if "floor" in runs[1:] and "floor" in res:
            line += f"  {res['floor']['floor']:>6} {res['floor']['ch_end']:.3f}"
        print(line)
    print(f"\n{len(rows)} recordings ({p0}): NEES or normalised closure error within its "
          f"99 % bound at the end in {in_end}, time-averaged in {in_avg} of {n_truth}; "
          f"horizontal closure at most 0.3 % of the distance in {pct_ok}")
    if armse:
        print(f"PyShoe trials: median ARMSE {np.median(armse):.3f} m over {len(armse)} "
              f"(PyShoe's SHOE detector tuned per trial: median {PYSHOE_SHOE_MEDIAN:.3f} m)")


if __name__ == "__main__":
    sys.exit(main())
