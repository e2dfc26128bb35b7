#!/usr/bin/python3
"""Plots of a se23 harness run, from the CSV files se23-report writes.

Run with Debian's /usr/bin/python3 (python3-matplotlib); a python3 earlier
on PATH may not see Debian's packages.

  plot.py --dir DIR [--title T]

reads DIR/errors.csv (and DIR/gnss.csv if present) and writes
  DIR/trajectory.png  truth vs estimate: north-east track and height
  DIR/errors.png      position, velocity, attitude errors (NED) with +-3 sigma
  DIR/biases.png      gyro and accelerometer bias: truth, estimate, +-3 sigma
  DIR/nees.png        NEES of the pose (9 dof) and of pose + biases (15 dof)
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

RAD2DEG = 180.0 / np.pi
AXES = ("north", "east", "down")


def load(path):
    return np.genfromtxt(path, delimiter=",", names=True)


def cols(d, prefix, names):
    return np.column_stack([d[prefix + n] for n in names])


def band_plot(ax, t, err, sig, unit, label):
    ax.fill_between(t, -3 * sig, 3 * sig, color="tab:blue", alpha=0.18, lw=0,
                    label="$\\pm 3\\sigma$")
    ax.plot(t, 3 * sig, color="tab:blue", lw=0.6)
    ax.plot(t, -3 * sig, color="tab:blue", lw=0.6)
    ax.plot(t, err, color="tab:red", lw=0.8, label="error")
    inside = np.mean(np.abs(err) <= 3 * sig) * 100.0
    # zoom on the run after the initial transient (first 5% of the time)
    late = t >= t[0] + 0.05 * (t[-1] - t[0])
    if np.any(late):
        top = 1.25 * max(np.max(3 * sig[late]), np.max(np.abs(err[late])))
        if top > 0:
            ax.set_ylim(-top, top)
    ax.set_title(f"{label}  ({inside:.0f}% within 3$\\sigma$)", fontsize=9)
    ax.set_ylabel(unit, fontsize=8)
    ax.grid(True, alpha=0.3)
    ax.tick_params(labelsize=7)


def plot_trajectory(d, gnss, out, title):
    fig = plt.figure(figsize=(11, 5))
    ax1 = fig.add_subplot(1, 2, 1)
    pt, pe = cols(d, "pt", "NED"), cols(d, "pe", "NED")
    if gnss is not None and gnss.size > 1:
        ax1.plot(gnss["pE"], gnss["pN"], ".", ms=2, color="0.6", label="GNSS fixes")
    ax1.plot(pt[:, 1], pt[:, 0], color="k", lw=1.6, label="truth")
    ax1.plot(pe[:, 1], pe[:, 0], color="tab:red", lw=0.9, ls="--", label="estimate")
    ax1.plot(pt[0, 1], pt[0, 0], "go", ms=6, label="start")
    ax1.set_xlabel("east [m]")
    ax1.set_ylabel("north [m]")
    ax1.set_aspect("equal", adjustable="datalim")
    ax1.grid(True, alpha=0.3)
    ax1.legend(fontsize=8)
    ax1.set_title("track (top view)", fontsize=10)
    ax2 = fig.add_subplot(1, 2, 2)
    ax2.plot(d["t"], -pt[:, 2], color="k", lw=1.6, label="truth")
    ax2.plot(d["t"], -pe[:, 2], color="tab:red", lw=0.9, ls="--", label="estimate")
    ax2.set_xlabel("time [s]")
    ax2.set_ylabel("height above origin [m]")
    ax2.grid(True, alpha=0.3)
    ax2.legend(fontsize=8)
    ax2.set_title("height", fontsize=10)
    fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "trajectory.png"), dpi=110)
    plt.close(fig)


def plot_errors(d, out, title):
    t = d["t"]
    groups = (("dp", "sp", 1.0, "m", "position"),
              ("dv", "sv", 1.0, "m/s", "velocity"),
              ("dth", "sth", RAD2DEG, "deg", "attitude"))
    fig, axs = plt.subplots(3, 3, figsize=(13, 8.5), sharex=True)
    for r, (e, s, k, unit, name) in enumerate(groups):
        err, sig = cols(d, e, "NED") * k, cols(d, s, "NED") * k
        for c in range(3):
            band_plot(axs[r, c], t, err[:, c], sig[:, c], unit, f"{name} error, {AXES[c]}")
    for c in range(3):
        axs[2, c].set_xlabel("time [s]")
    axs[0, 0].legend(fontsize=7, loc="upper right")
    fig.suptitle(title + "  -  errors (truth - estimate) with $\\pm 3\\sigma$ of the filter"
                 " (y zoomed past the first 5% of the run)", fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "errors.png"), dpi=100)
    plt.close(fig)


def plot_biases(d, out, title):
    t = d["t"]
    groups = (("bgt", "bge", "sbg", RAD2DEG * 3600.0, "deg/h", "gyro bias"),
              ("bat", "bae", "sba", 1000.0 / 9.80665, "mg", "accel bias"))
    fig, axs = plt.subplots(2, 3, figsize=(13, 6), sharex=True)
    for r, (bt, be, sb, k, unit, name) in enumerate(groups):
        tru, est, sig = (cols(d, p, "123") * k for p in (bt, be, sb))
        for c in range(3):
            ax = axs[r, c]
            ax.fill_between(t, est[:, c] - 3 * sig[:, c], est[:, c] + 3 * sig[:, c],
                            color="tab:blue", alpha=0.18, lw=0, label="estimate $\\pm 3\\sigma$")
            ax.plot(t, tru[:, c], color="k", lw=1.4, label="truth")
            ax.plot(t, est[:, c], color="tab:red", lw=0.9, label="estimate")
            ax.set_title(f"{name}, axis {c + 1}", fontsize=9)
            ax.set_ylabel(unit, fontsize=8)
            ax.grid(True, alpha=0.3)
            ax.tick_params(labelsize=7)
    for c in range(3):
        axs[1, c].set_xlabel("time [s]")
    axs[0, 0].legend(fontsize=7)
    fig.suptitle(title + "  -  bias estimates", fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "biases.png"), dpi=100)
    plt.close(fig)


def plot_nees(d, out, title):
    t = d["t"]
    fig, ax = plt.subplots(figsize=(10, 4))
    # two-sided 95% bounds of a single chi-square draw with 9 / 15 dof
    bounds = {9: (2.700, 19.023), 15: (6.262, 27.488)}
    for name, dof, color in (("nees9", 9, "tab:blue"), ("nees15", 15, "tab:orange")):
        v = d[name]
        if np.all(np.isnan(v)):
            continue
        ax.axhspan(*bounds[dof], color=color, alpha=0.08,
                   label=f"95% band of $\\chi^2_{{{dof}}}$")
        ax.plot(t, v, color=color, lw=0.8,
                label=f"NEES, {dof} dof (mean {np.nanmean(v):.1f}, expected {dof})")
        ax.axhline(dof, color=color, ls="--", lw=0.8)
    ax.set_yscale("log")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("NEES")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(title + "  -  normalised estimation error squared", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "nees.png"), dpi=100)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dir", required=True)
    ap.add_argument("--title", default="se23 run")
    a = ap.parse_args()
    d = load(os.path.join(a.dir, "errors.csv"))
    gpath = os.path.join(a.dir, "gnss.csv")
    gnss = load(gpath) if os.path.exists(gpath) and os.path.getsize(gpath) > 20 else None
    plot_trajectory(d, gnss, a.dir, a.title)
    plot_errors(d, a.dir, a.title)
    plot_biases(d, a.dir, a.title)
    plot_nees(d, a.dir, a.title)


if __name__ == "__main__":
    main()
