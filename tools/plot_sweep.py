#!/usr/bin/env python3
"""Pictures of a sweep written by ergo_sweep: one PNG per varied flag, the fresh reduction
(left axis) and the optimised fresh score (right axis) against the flag's value, one line
per combination of the other varied flags.

    python3 tools/plot_sweep.py SWEEP_DIR     # reads SWEEP_DIR/sweep.csv
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FIXED = ["case", "status", "initial_score", "optimized_score", "reduction_percent",
         "followed_reduction_percent", "worst_placement_reduction_percent",
         "skin_zeta_reduction_percent", "initial_peak_pressure_Pa", "fresh_peak_pressure_Pa",
         "initial_plate_peak_pressure_Pa", "fresh_plate_peak_pressure_Pa",
         "evaluations", "wall_s", "message"]


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def main():
    directory = pathlib.Path(sys.argv[1])
    with open(directory / "sweep.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return
    flags = [name for name in rows[0] if name not in FIXED]
    for flag in flags:
        others = [f for f in flags if f != flag]
        groups = {}
        for row in rows:
            if row["status"] != "ok":
                continue
            key = ", ".join(f"{o}={row[o]}" for o in others)
            groups.setdefault(key, []).append(row)
        figure, left = plt.subplots(figsize=(7, 4.5))
        right = left.twinx()
        numeric = all(number(row[flag]) is not None for row in rows)
        labels = sorted({row[flag] for row in rows}, key=lambda v: number(v) if numeric else v)
        for key, members in sorted(groups.items()):
            members.sort(key=lambda r: labels.index(r[flag]))
            x = [number(r[flag]) if numeric else labels.index(r[flag]) for r in members]
            line, = left.plot(x, [number(r["reduction_percent"]) for r in members], "o-",
                              label=key or "reduction afresh")
            right.plot(x, [number(r["optimized_score"]) for r in members], "s--",
                       color=line.get_color(), alpha=0.6)
        if not numeric:
            left.set_xticks(range(len(labels)), labels)
        left.set_xlabel(flag)
        left.set_ylabel("fresh reduction (%), solid")
        right.set_ylabel("optimised fresh score φ, dashed")
        right.set_yscale("log")
        if any(groups):
            left.legend(fontsize=8, loc="best")
        left.set_title(f"sweep over {flag}")
        figure.tight_layout()
        figure.savefig(directory / f"sweep_{flag}.png", dpi=110)
        plt.close(figure)


if __name__ == "__main__":
    main()
