#!/usr/bin/env python3
"""The picture of an ergo_calibrate run: each measured point's force-indentation readings,
the fitted layered law through them and Hertz's half-space law with the same modulus (what the
layer's depth adds), one panel per point (the first 24), titled with the fitted E and depth.

    python3 tools/plot_calibration.py OUT_DIR     # reads OUT_DIR/fits.json, writes calibration.png
"""
import json
import math
import os
import pathlib
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MAX_PANELS = 24


def title(point):
    text = "%s: E = %.3g ± %.2g kPa" % (point["sample"], 1e-3 * point["youngs_modulus_pa"],
                                         1e-3 * point["youngs_modulus_stderr_pa"])
    if point["depth_m"] is None:
        return text + ", half-space"
    text += ", h = %.3g" % (1e3 * point["depth_m"])
    if point["depth_stderr_m"]:
        text += " ± %.2g" % (1e3 * point["depth_stderr_m"])
    return text + " mm"


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plot_calibration.py OUT_DIR (an ergo_calibrate output directory)")
    directory = pathlib.Path(sys.argv[1])
    source = directory / "fits.json"
    if not source.is_file():
        sys.exit("plot_calibration.py: %s has no fits.json: is it an ergo_calibrate output?" %
                 directory)
    points = json.loads(source.read_text())
    shown = points[:MAX_PANELS]
    columns = min(4, max(1, len(shown)))
    rows = max(1, math.ceil(len(shown) / columns))
    figure, axes = plt.subplots(rows, columns, figsize=(4.2 * columns, 3.3 * rows), squeeze=False)
    for index, point in enumerate(shown):
        axis = axes[index // columns][index % columns]
        axis.plot([1e3 * d for d in point["indentation_m"]], point["force_n"], "o", ms=3,
                  color="black", label="readings")
        grid = [1e3 * d for d in point["model_indentation_m"]]
        axis.plot(grid, point["model_force_n"], "-", color="tab:blue", label="layered law, fitted")
        if point["depth_m"] is not None:
            axis.plot(grid, point["hertz_force_n"], "--", color="tab:gray",
                      label="Hertz, same E")
        axis.set_title(title(point), fontsize=8)
        axis.set_xlabel("indentation (mm)", fontsize=8)
        axis.set_ylabel("force (N)", fontsize=8)
        axis.tick_params(labelsize=7)
        if point["note"]:
            axis.text(0.02, 0.97, textwrap.fill(point["note"], 60), transform=axis.transAxes,
                      fontsize=6, va="top", color="tab:red")
        if index == 0:
            axis.legend(fontsize=7, loc="lower right")
    for index in range(len(shown), rows * columns):
        axes[index // columns][index % columns].axis("off")
    heading = "Tissue calibration: %d point%s" % (len(points), "" if len(points) == 1 else "s")
    if len(points) > MAX_PANELS:
        heading += " (the first %d shown; all in calibration.md)" % MAX_PANELS
    figure.suptitle(heading, fontsize=10)
    figure.tight_layout()
    target = directory / "calibration.png"
    temporary = directory / "calibration.png.tmp.png"
    figure.savefig(temporary, dpi=110)
    os.replace(temporary, target)  # no partial picture under the final name


if __name__ == "__main__":
    main()
