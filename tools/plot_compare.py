#!/usr/bin/env python3
"""Plots an ergo_compare run: the kept design's phi/phi0 afresh against wall seconds, and
the optimiser's own phi/phi0 against evaluations.

usage: plot_compare.py DIR   (reads DIR/compare.csv and DIR/<optimizer>_history.csv,
                              writes DIR/compare.png)
Needs matplotlib (Debian: python3-matplotlib); exits 3 without it.
"""
import csv
import os
import re
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
    fig, (by_time, by_evals) = plt.subplots(1, 2, figsize=(12, 4.5))
    for index, run in enumerate(runs):
        name = run["optimizer"]
        color = "C%d" % (index % 10)
        path = os.path.join(out_dir, name + "_history.csv")
        if not os.path.exists(path):
            continue
        rows = read_csv(path)
        if not rows:
            continue
        phi0 = float(run["initial_phi"]) if run.get("initial_phi") else float(rows[0]["phi"])
        if phi0 == 0:
            continue
        # Left: what a person gets — the kept design placed afresh, a step at every round's
        # check, ending at the run's kept design (compare.csv; its check follows the last row).
        kept = [(float(r["wall_s"]), float(r["kept_fresh_phi"]) / phi0)
                for r in rows if r.get("kept_fresh_phi")]
        if kept:
            kept.insert(0, (0.0, kept[0][1]))
        if kept and run.get("final_phi") and run.get("wall_s"):
            kept.append((float(run["wall_s"]), float(run["final_phi"]) / phi0))
        if kept:
            by_time.step([t for t, _ in kept], [v for _, v in kept], where="post",
                         color=color, label=name)
        # Beside it, faint: the optimiser's own value against the same clock (a run in one
        # round is placed afresh only at its end).
        by_time.plot([float(r["wall_s"]) for r in rows], [float(r["phi"]) / phi0 for r in rows],
                     color=color, linestyle="--", linewidth=0.8, alpha=0.5)
        # Right: the optimiser's own path (its equilibria followed from one design to the next).
        by_evals.plot([int(r["evaluations"]) for r in rows],
                      [float(r["phi"]) / phi0 for r in rows], marker=".", color=color,
                      label=name)
    by_time.set_title("kept design placed afresh (dashed: the optimiser's own value)")
    by_evals.set_title("the optimiser's own path (followed equilibria)")
    for axes, label in ((by_time, "wall clock, s"),
                        (by_evals, "phi evaluations (equilibrium solves)")):
        axes.set_xlabel(label)
        axes.set_ylabel("phi / phi0")
        axes.set_yscale("log")
        axes.axhline(0.3, color="grey", linestyle=":", linewidth=1)  # 70 % reduction
        axes.grid(True, which="both", alpha=0.3)
    by_time.legend(fontsize="small")
    # ergo_compare plots into its temporary folder (DIR.tmp-PID) before it renames it to DIR.
    name = re.sub(r"\.tmp-\d+$", "", os.path.basename(os.path.abspath(out_dir)))
    fig.suptitle("ergo_compare: " + name)
    fig.tight_layout()
    target = os.path.join(out_dir, "compare.png")
    temporary = target + ".tmp.%d.png" % os.getpid()
    fig.savefig(temporary, dpi=110)
    os.replace(temporary, target)  # atomic, like every ergo output
    return 0


if __name__ == "__main__":
    sys.exit(main())
