#!/usr/bin/python3
"""The height of each stance of walks, from the CSVs se23-walk writes: the
real walk beside its simulated twin (tools/walk/sim-walk.sh).

  plot_twin.py --out PNG LABEL=CSV [LABEL=CSV ...]

A stance starts where the stationary flag rises more than 0.1 s after the
previous stance ended (se23-walk's merge); its height is the filter's
height there less the first state's, against the stance's number.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

MERGE_S = 0.1


def stance_heights(path):
    d = np.genfromtxt(path, delimiter=",", names=True)
    t, st = d["t"], d["stance"] > 0.5
    heights, last_end = [0.0], None
    for k in range(1, len(t)):
        if st[k] and not st[k - 1] and (last_end is None or t[k] - last_end > MERGE_S):
            heights.append(d["pD"][0] - d["pD"][k])
        if st[k]:
            last_end = t[k]
    return np.array(heights)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("runs", nargs="+", help="LABEL=CSV")
    a = ap.parse_args()
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for run in a.runs:
        label, path = run.split("=", 1)
        h = stance_heights(path)
        ax.plot(np.arange(h.size), 100.0 * h, "o-", ms=3, lw=1, label=label)
    ax.axhline(0.0, color="k", lw=0.6)
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax.set_xlabel("stance number (0: the start)")
    ax.set_ylabel("height at the stance's start [cm]")
    ax.set_title("the foot's height at each stance (the truth: 0 throughout)", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
