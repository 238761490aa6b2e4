#!/usr/bin/env python3
"""The picture of an ergo_population run: each body's fresh-score reduction on the population
design (and on the design made for the population's mean body alone, where the run made it),
and each body's peak skin pressure before and after.

    python3 tools/plot_population.py OUT_DIR     # reads OUT_DIR/summary.json
"""
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    directory = pathlib.Path(sys.argv[1])
    summary = json.loads((directory / "summary.json").read_text())
    bodies = summary["bodies"]
    names = [b["name"] for b in bodies]
    xs = range(len(bodies))
    mean = "mean_body_design" in summary
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    width = 0.38 if mean else 0.6

    def value(body, key):
        v = body.get(key)
        return float("nan") if v is None else v

    left.bar([x - (width / 2 if mean else 0) for x in xs],
             [value(b, "reduction_percent") for b in bodies], width,
             label=f"population design ({summary['objective']})")
    if mean:
        left.bar([x + width / 2 for x in xs],
                 [value(b, "mean_body_design_reduction_percent") for b in bodies], width,
                 label="mean body's design")
    left.axhline(0, color="black", linewidth=0.8)
    left.set_xticks(list(xs), names, rotation=30, ha="right")
    left.set_ylabel("fresh score reduction, %")
    left.set_title("each body placed afresh")
    left.legend(fontsize=8)
    right.bar([x - 0.2 for x in xs], [value(b, "initial_peak_pressure") / 1e3 for b in bodies],
              0.4, label="initial design", color="#bbbbbb")
    right.bar([x + 0.2 for x in xs], [value(b, "optimized_peak_pressure") / 1e3 for b in bodies],
              0.4, label="population design")
    right.set_xticks(list(xs), names, rotation=30, ha="right")
    right.set_ylabel("peak skin pressure, kPa")
    right.legend(fontsize=8)
    figure.suptitle(summary.get("description") or summary["population"], fontsize=10)
    figure.tight_layout()
    figure.savefig(directory / "population.png", dpi=110)


if __name__ == "__main__":
    main()
