#!/usr/bin/python3
"""Plots of se23-drive (tools/drive/report.c) from DIR/drive.csv and
DIR/drive.outages.csv:

  drive_track.png   top view: the reference and the filter's antenna track,
                    the outages marked (the reference's stretch in each, the
                    filter's end point)
  drive_error.png   north, east error and the horizontal error over time
                    with +-3 sigma (the filter's covariance), outages shaded
  drive_outages.png horizontal error against the time since each outage's
                    start, one line per outage

usage: plot_drive.py DIR [LABEL]
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    out = {}
    for k in rows[0].keys() if rows else []:
        out[k] = [float(r[k]) for r in rows]
    return out, len(rows)


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    d = sys.argv[1]
    label = sys.argv[2] if len(sys.argv) > 2 and sys.argv[2] else "drive"
    ep, n = read_csv(os.path.join(d, "drive.csv"))
    oc, n_out = read_csv(os.path.join(d, "drive.outages.csv"))
    if n == 0:
        print("plot_drive.py: no epochs", file=sys.stderr)
        return 1
    t = ep["t_rel_s"]
    outage = [int(x) for x in ep["outage"]]

    # top view
    fig, ax = plt.subplots(figsize=(8, 8))
    ax.plot(ep["ref_e"], ep["ref_n"], "-", color="0.6", lw=2.5, label="reference")
    ax.plot(ep["est_e"], ep["est_n"], "-", color="C0", lw=0.9, label="filter (antenna)")
    for k in range(n_out):
        idx = [i for i in range(n) if outage[i] == k]
        if not idx:
            continue
        ax.plot([ep["ref_e"][i] for i in idx], [ep["ref_n"][i] for i in idx], "-", color="C3",
                lw=2.5, label="reference in outages" if k == 0 else None)
        ax.plot([ep["est_e"][i] for i in idx], [ep["est_n"][i] for i in idx], "-", color="C1",
                lw=1.2, label="filter in outages" if k == 0 else None)
        j = idx[-1]
        ax.plot(ep["est_e"][j], ep["est_n"][j], "x", color="C1", ms=7)
        ax.annotate("%d: %.0f s" % (k, oc["len_s"][k]), (ep["ref_e"][idx[0]], ep["ref_n"][idx[0]]),
                    fontsize=7, color="C3")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("east [m]")
    ax.set_ylabel("north [m]")
    ax.set_title("%s: top view, outages marked" % label)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "drive_track.png"), dpi=120)
    plt.close(fig)

    # error and +-3 sigma over time
    fig, axs = plt.subplots(3, 1, figsize=(10, 8), sharex=True)
    series = [("err_n", "sig_n", "north error [m]"), ("err_e", "sig_e", "east error [m]"),
              ("err_h", "sig_h", "horizontal error [m]")]
    for ax, (e, s, name) in zip(axs, series):
        three = [3 * x for x in ep[s]]
        ax.plot(t, ep[e], "-", color="C0", lw=0.8, label="error")
        ax.plot(t, three, "--", color="C3", lw=0.7, label="3 sigma")
        if e != "err_h":
            ax.plot(t, [-x for x in three], "--", color="C3", lw=0.7)
        for k in range(n_out):
            ax.axvspan(oc["start_s"][k], oc["start_s"][k] + oc["len_s"][k], color="0.85",
                       zorder=0)
        ax.set_ylabel(name)
        ax.grid(True, alpha=0.3)
        if e == "err_h":
            finite = sorted(x for x in ep[e] if math.isfinite(x))
            if finite:
                ax.set_ylim(0, max(1e-3, 1.2 * finite[int(0.995 * (len(finite) - 1))]))
        else:
            finite = sorted(abs(x) for x in ep[e] if math.isfinite(x))
            if finite:
                lim = max(1e-3, 1.2 * finite[int(0.995 * (len(finite) - 1))])
                ax.set_ylim(-lim, lim)
    axs[0].legend(loc="upper right", fontsize=8)
    axs[0].set_title("%s: antenna error against the reference, +-3 sigma; outages shaded" % label)
    axs[-1].set_xlabel("time since the first fix [s]")
    fig.tight_layout()
    fig.savefig(os.path.join(d, "drive_error.png"), dpi=120)
    plt.close(fig)

    # error growth in the outages
    fig, ax = plt.subplots(figsize=(8, 5))
    for k in range(n_out):
        idx = [i for i in range(n) if outage[i] == k]
        if not idx:
            continue
        ax.plot([ep["t_in_outage_s"][i] for i in idx], [ep["err_h"][i] for i in idx], "-",
                lw=1.0, label="#%d at %.0f s, %.0f m" % (k, oc["start_s"][k], oc["dist_m"][k]))
    ax.set_xlabel("time since the outage's start [s]")
    ax.set_ylabel("horizontal error [m]")
    ax.set_title("%s: error growth in the GNSS outages" % label)
    ax.grid(True, alpha=0.3)
    if n_out <= 16:
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "drive_outages.png"), dpi=120)
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
