#!/usr/bin/python3
"""Plots the endpoint clouds of se23-montecarlo like the paper's Figure on
Monte Carlo clouds (section 3.4): true dispersion black, the exponential
(concentrated Gaussian) model red, the standard EKF green, the nominal
trajectory blue. Left: 3D view; right: the cross-section seen along the
motion (lateral y against altitude), where the banana is plain.

Usage: plot_clouds.py CLOUDS.csv OUT.png [TITLE]
Run with Debian's /usr/bin/python3 (python3-matplotlib).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {
    "true": ("black", "true (noisy equations)"),
    "exponential": ("red", "exponential model, Sigma from eq. riccati"),
    "ekf": ("green", "standard EKF"),
}


def load(path):
    pts = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            # NED: plot altitude = -z so that up is up.
            pts.setdefault(row["kind"], []).append(
                (float(row["x"]), float(row["y"]), -float(row["z"])))
    return pts


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    pts = load(argv[1])
    fig = plt.figure(figsize=(13, 5.5))
    ax3 = fig.add_subplot(1, 2, 1, projection="3d")
    ax2 = fig.add_subplot(1, 2, 2)
    nom = pts.get("nominal", [])
    if nom:
        ax3.plot([p[0] for p in nom], [p[1] for p in nom], [p[2] for p in nom],
                 color="blue", lw=2, label="nominal trajectory")
    for kind in ("true", "exponential", "ekf"):
        p = pts.get(kind, [])
        color, label = STYLE[kind]
        ax3.scatter([q[0] for q in p], [q[1] for q in p], [q[2] for q in p],
                    s=2, color=color, alpha=0.35, label=label, depthshade=False)
        ax2.scatter([q[1] for q in p], [q[2] for q in p], s=2, color=color,
                    alpha=0.35, label=label)
    try:
        ax3.set_box_aspect((2.0, 1.0, 0.6))
    except AttributeError:  # matplotlib < 3.3
        pass
    ax3.set_xlabel("x, direction of motion [m]")
    ax3.set_ylabel("y [m]")
    ax3.set_zlabel("altitude [m]")
    ax3.view_init(elev=20, azim=-75)
    ax3.legend(loc="upper left", fontsize=8, markerscale=4)
    ax2.set_xlabel("y, lateral [m]")
    ax2.set_ylabel("altitude [m]")
    ax2.set_title("endpoint clouds seen along the motion")
    ax2.axis("equal")
    ax2.grid(True, alpha=0.3)
    if len(argv) > 3:
        fig.suptitle(argv[3], fontsize=10)
    fig.tight_layout()
    fig.savefig(argv[2], dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
