#!/usr/bin/python3
"""Plots of a foot-mounted walk, from the CSV se23-walk writes.

  plot_walk.py --dir DIR

reads DIR/walk.csv and writes
  DIR/walk_path.png  top view of the path (north-east), stance points marked
  DIR/walk_time.png  height, speed with +-3 sigma, and the detector's
                     statistic with the stance flags, against time
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--dir", required=True)
    a = ap.parse_args()
    d = np.genfromtxt(os.path.join(a.dir, "walk.csv"), delimiter=",", names=True)
    t, st = d["t"], d["stance"] > 0.5
    onset = np.flatnonzero(st[1:] & ~st[:-1]) + 1

    fig, ax = plt.subplots(figsize=(7, 6))
    ax.plot(d["pE"], d["pN"], color="tab:blue", lw=0.8, label="foot path")
    ax.plot(d["pE"][onset], d["pN"][onset], "o", ms=3, color="tab:red", label="stance onsets")
    ax.plot(d["pE"][0], d["pN"][0], "k^", ms=8, label="start")
    ax.plot(d["pE"][onset[-1]] if onset.size else d["pE"][-1],
            d["pN"][onset[-1]] if onset.size else d["pN"][-1], "ks", ms=7,
            mfc="none", label="last stance")
    ax.set_xlabel("east [m]")
    ax.set_ylabel("north [m]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("foot-mounted walk: top view (start heading = north)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(a.dir, "walk_path.png"), dpi=110)
    plt.close(fig)

    fig, axs = plt.subplots(3, 1, figsize=(10, 8), sharex=True)
    axs[0].plot(t, -d["pD"], color="tab:blue", lw=0.8)
    axs[0].set_ylabel("height [m]")
    axs[0].set_title("height (up), speed and the stationary detector", fontsize=10)
    sp, ss = d["speed"], d["sspeed"]
    axs[1].fill_between(t, np.maximum(sp - 3 * ss, 0), sp + 3 * ss, color="tab:blue",
                        alpha=0.2, lw=0, label="$\\pm 3\\sigma$")
    axs[1].plot(t, sp, color="tab:blue", lw=0.7, label="speed")
    axs[1].set_ylabel("speed [m/s]")
    axs[1].legend(fontsize=8, loc="upper right")
    stat = np.maximum(d["stat"], 1e-3)
    axs[2].semilogy(t, stat, color="0.3", lw=0.6, label="detector statistic")
    axs[2].fill_between(t, 1e-3, np.where(st, stat.max(), 1e-3), color="tab:green",
                        alpha=0.25, lw=0, label="stance (ZUPT)")
    axs[2].set_ylabel("statistic")
    axs[2].set_xlabel("time [s]")
    axs[2].legend(fontsize=8, loc="upper right")
    for ax in axs:
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(a.dir, "walk_time.png"), dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
