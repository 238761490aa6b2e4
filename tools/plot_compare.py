#!/usr/bin/env python3
"""Plots an ergo_compare run: phi/phi0 against evaluations and against wall seconds.

usage: plot_compare.py DIR   (reads DIR/compare.csv and DIR/<optimizer>_history.csv,
                              writes DIR/compare.png)
Needs matplotlib (Debian: python3-matplotlib); exits 3 without it.
"""
import csv
import os
import sys


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out_dir = sys.argv[1]
    try:
        import matplotlib
        matplotlib.use("Agg")  # no display needed
        import matplotlib.pyplot as plt
    except ImportError:
        print("plot_compare.py: matplotlib is not installed", file=sys.stderr)
        return 3

    runs = read_csv(os.path.join(out_dir, "compare.csv"))
    fig, (by_evals, by_time) = plt.subplots(1, 2, figsize=(12, 4.5))
    for run in runs:
        name = run["optimizer"]
        path = os.path.join(out_dir, name + "_history.csv")
        if not os.path.exists(path):
            continue
        rows = read_csv(path)
        if not rows:
            continue
        phi0 = float(rows[0]["phi"])
        if phi0 == 0:
            continue
        ratio = [float(r["phi"]) / phi0 for r in rows]
        evals = [int(r["evaluations"]) for r in rows]
        seconds = [float(r["wall_s"]) for r in rows]
        by_evals.plot(evals, ratio, marker=".", label=name)
        by_time.plot(seconds, ratio, marker=".", label=name)
    for axes, label in ((by_evals, "phi evaluations (equilibrium solves)"),
                        (by_time, "wall clock, s")):
        axes.set_xlabel(label)
        axes.set_ylabel("phi / phi0")
        axes.set_yscale("log")
        axes.axhline(0.3, color="grey", linestyle=":", linewidth=1)  # 70 % reduction
        axes.grid(True, which="both", alpha=0.3)
    by_evals.legend(fontsize="small")
    fig.suptitle("ergo_compare: " + os.path.basename(os.path.abspath(out_dir)))
    fig.tight_layout()
    target = os.path.join(out_dir, "compare.png")
    temporary = target + ".tmp.%d.png" % os.getpid()
    fig.savefig(temporary, dpi=110)
    os.replace(temporary, target)  # atomic, like every ergo output
    return 0


if __name__ == "__main__":
    sys.exit(main())
