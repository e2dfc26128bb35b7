#!/usr/bin/env python3
"""One table over the runs of tools/drive/demo-drive.sh (se23-drive's CSVs).

    summary.py [--plot PNG] [--max-pct LEN:P,...] RUN_DIR

RUN_DIR holds, per precision p in (double, float):
  aided-p.csv                      every reference epoch of the run with all fixes
  oL-nhc-p.csv, oL-none-p.csv      the runs with outages of L s, with and without
                                   the non-holonomic constraint (+ .outages.csv)
Prints the aided error and NEES, then per outage length the median end error
in % of the distance driven (and in m) and the median NEES at the ends, then
every outage of the double runs with what the car did in it (from the
reference track: "turn" if its course turned by more than 45 deg while moving,
"stop" if it stood still, "straight" otherwise).
--max-pct LEN:P  exit 1 if the double NHC run's median % for length LEN exceeds P
--max-float-ratio R  exit 1 if a float median (aided or outage) differs from the
                 double one by more than R (relative; 0.1 = 10 %)
"""
import csv
import math
import os
import sys

CHI2_3_99 = 11.345
LENGTHS = (10, 30, 60)
PRECISIONS = ("double", "float")


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def median(xs):
    xs = sorted(x for x in xs if not math.isnan(x))
    if not xs:
        return float("nan")
    n = len(xs)
    return xs[n // 2] if n % 2 else 0.5 * (xs[n // 2 - 1] + xs[n // 2])


def quantile(xs, q):
    xs = sorted(xs)
    return xs[min(len(xs) - 1, int(q * len(xs)))] if xs else float("nan")


def aided(run, p):
    rows = [r for r in read(os.path.join(run, f"aided-{p}.csv")) if int(r["outage"]) < 0]
    eh = [float(r["err_h"]) for r in rows]
    nees = [float(r["nees3"]) for r in rows]
    return {
        "h50": median(eh), "h95": quantile(eh, 0.95), "nees": sum(nees) / len(nees),
        "beyond": sum(1 for x in nees if x > CHI2_3_99) / len(nees), "n": len(rows),
    }


def kind(epochs, start, length):
    """What the car did in [start, start + length) by the reference track."""
    pts = [(float(r["t_rel_s"]), float(r["ref_n"]), float(r["ref_e"])) for r in epochs
           if start <= float(r["t_rel_s"]) < start + length]
    turn, stop, last = 0.0, False, None
    for (t0, n0, e0), (t1, n1, e1) in zip(pts, pts[1:]):
        dt = t1 - t0
        if dt <= 0:
            continue
        sp = math.hypot(n1 - n0, e1 - e0) / dt
        if sp < 0.5:
            stop = True
        if sp > 2.0:
            c = math.atan2(e1 - e0, n1 - n0)
            if last is not None:
                turn += abs(math.remainder(c - last, 2 * math.pi))
            last = c
    words = (["turn"] if turn > math.radians(45) else []) + (["stop"] if stop else [])
    return "+".join(words) or "straight"


def outages(run, length, mode, p):
    base = os.path.join(run, f"o{length}-{mode}-{p}")
    return read(base + ".outages.csv"), base + ".csv"


def main(argv):
    plot, bounds, ratio = None, {}, None
    while argv and argv[0].startswith("--"):
        if argv[0] == "--plot":
            plot = argv[1]
        elif argv[0] == "--max-pct":
            bounds = {int(k): float(v) for k, v in (x.split(":") for x in argv[1].split(","))}
        elif argv[0] == "--max-float-ratio":
            ratio = float(argv[1])
        else:
            sys.exit(f"summary.py: unknown option {argv[0]}")
        argv = argv[2:]
    run = argv[0]
    ok = True
    a = {p: aided(run, p) for p in PRECISIONS}
    print("With every fix, against the RTK truth (%d epochs):" % a["double"]["n"])
    print("  %-8s horizontal error median %.3f m, 95%% %.3f m; NEES (3 dof) mean %.2f, "
          "%.1f%% of epochs beyond %.2f (1%% for an honest covariance)"
          % ("double", a["double"]["h50"], a["double"]["h95"], a["double"]["nees"],
             100 * a["double"]["beyond"], CHI2_3_99))
    print("  %-8s horizontal error median %.3f m, 95%% %.3f m; NEES (3 dof) mean %.2f, "
          "%.1f%% beyond" % ("float", a["float"]["h50"], a["float"]["h95"], a["float"]["nees"],
                            100 * a["float"]["beyond"]))
    print()
    print("GNSS outages: median horizontal error at the end, in % of the distance driven"
          " (median m), and the median NEES at the end (3 dof; 99 % bound 11.34):")
    print("  %-6s %-7s %-34s %-34s" % ("length", "", "with NHC (the preset)", "without NHC"))
    table = {}
    for length in LENGTHS:
        for p in PRECISIONS:
            cells = []
            for mode in ("nhc", "none"):
                rows, _ = outages(run, length, mode, p)
                pct = median([float(r["err_end_pct"]) for r in rows])
                m = median([float(r["err_end_h_m"]) for r in rows])
                nees = median([float(r["nees_end"]) for r in rows])
                table[(length, mode, p)] = pct
                cells.append("%6.2f %% (%6.2f m) NEES %6.2f  n=%d" % (pct, m, nees, len(rows)))
            print("  %4d s %-7s %-34s %-34s" % (length, p, cells[0], cells[1]))
    print()
    print("Every outage (double, with NHC):")
    print("  %5s %5s %-12s %8s %9s %7s %8s" % ("start", "len", "the car", "dist m",
                                               "end err m", "%", "NEES"))
    for length in LENGTHS:
        rows, epochs_csv = outages(run, length, "nhc", "double")
        epochs = read(epochs_csv)
        for r in rows:
            s, ln = float(r["start_s"]), float(r["len_s"])
            print("  %5.0f %5.0f %-12s %8.1f %9.2f %7.2f %8.2f"
                  % (s, ln, kind(epochs, s, ln), float(r["dist_m"]), float(r["err_end_h_m"]),
                     float(r["err_end_pct"]), float(r["nees_end"])))
    for length, bound in sorted(bounds.items()):
        got = table[(length, "nhc", "double")]
        if not got <= bound:
            print(f"summary: {length} s outages: median {got:.2f} % above the bound {bound} %")
            ok = False
    if ratio is not None:
        pairs = [(a["double"]["h50"], a["float"]["h50"], "aided median")]
        pairs += [(table[(ln, md, "double")], table[(ln, md, "float")], f"{ln} s {md}")
                  for ln in LENGTHS for md in ("nhc", "none")]
        for d, f, what in pairs:
            if not abs(f - d) <= ratio * abs(d):
                print(f"summary: float differs from double by more than {ratio:.0%}: {what}"
                      f" {f:.4g} against {d:.4g}")
                ok = False
    if plot:
        draw(run, plot)
    return 0 if ok else 1


def draw(run, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    colours = {10: "tab:blue", 30: "tab:orange", 60: "tab:red"}
    for ax, mode, title in zip(axes, ("nhc", "none"), ("with the non-holonomic constraint",
                                                        "without it")):
        for length in LENGTHS:
            _, epochs_csv = outages(run, length, mode, "double")
            series = {}
            for r in read(epochs_csv):
                if int(r["outage"]) >= 0 and r["t_in_outage_s"] != "nan":
                    series.setdefault(int(r["outage"]), []).append(
                        (float(r["t_in_outage_s"]), float(r["err_h"]), float(r["sig_h"])))
            for k, pts in series.items():
                t, e, s = zip(*pts)
                ax.plot(t, e, color=colours[length], lw=1,
                        label=f"{length} s outages" if k == 0 else None)
                ax.plot(t, [3 * x for x in s], color=colours[length], lw=0.6, ls=":")
        ax.set_yscale("log")
        ax.set_xlabel("time since the outage began [s]")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("horizontal error [m] (dotted: the filter's 3 sigma)")
    axes[0].legend()
    fig.suptitle("se23 car preset, rtklibexplorer drive 0708: error growth in GNSS outages "
                 "(double)")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
