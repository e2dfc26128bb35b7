#!/usr/bin/python3
"""Plots the UAV trajectory of se23-paper-table (the paper's Figure
"Simulated trajectory", section 4.2) from the CSV of `--traj`.

Usage: plot_traj.py TRAJ.csv OUT.png
Run with Debian's /usr/bin/python3 (python3-matplotlib).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    x, y, h = [], [], []
    with open(argv[1], newline="") as f:
        for row in csv.DictReader(f):
            x.append(float(row["x"]))
            y.append(float(row["y"]))
            h.append(-float(row["z"]))  # NED: altitude = -z
    fig = plt.figure(figsize=(7, 5))
    ax = fig.add_subplot(1, 1, 1, projection="3d")
    ax.plot(x, y, h, color="blue", lw=1)
    ax.scatter([x[0]], [y[0]], [h[0]], color="black", s=20, label="start")
    ax.set_xlabel("north [m]")
    ax.set_ylabel("east [m]")
    ax.set_zlabel("altitude [m]")
    ax.set_title("simulated UAV trajectory (100 Hz IMU)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(argv[2], dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
