#!/usr/bin/env python3
"""The picture of an ergo_validate run: the simulated and the measured (aligned) contact
pressure side by side on one colour scale, and their difference, each with the footprint
outlines, the region boundaries along the footprint's axis and the peaks.

    python3 tools/plot_validation.py OUT_DIR     # reads OUT_DIR/maps.json, writes comparison.png
"""
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    directory = pathlib.Path(sys.argv[1])
    data = json.loads((directory / "maps.json").read_text())
    rows, columns = data["rows"], data["columns"]
    simulated = np.array(data["simulated_kpa"], dtype=float).reshape(rows, columns)
    measured = np.array(data["measured_kpa"], dtype=float).reshape(rows, columns)
    x0, z0 = data["lower_mm"]
    pitch = data["pitch_mm"]
    # Node (r, c) sits at (x0 + c h, z0 + r h); pixels centred on the nodes.
    extent = [x0 - pitch / 2, x0 + (columns - 0.5) * pitch, z0 - pitch / 2, z0 + (rows - 0.5) * pitch]
    threshold = data["footprint_threshold_kpa"]
    top = max(simulated.max(), measured.max(), 1e-9)
    difference = measured - simulated
    spread = max(np.abs(difference).max(), 1e-9)

    # The region boundaries: segments across the footprint at each fraction along the axis.
    origin = np.array(data["axis_origin_mm"])
    direction = np.array(data["axis_direction"])
    across = np.array([-direction[1], direction[0]])
    length = data["axis_length_mm"]
    half_width = 0.5 * max(extent[1] - extent[0], extent[3] - extent[2])

    figure, axes = plt.subplots(1, 3, figsize=(13, 6.5), sharex=True, sharey=True)
    panels = [
        (axes[0], simulated, "simulated", "viridis", 0, top),
        (axes[1], measured, "measured (aligned)", "viridis", 0, top),
        (axes[2], difference, "measured − simulated", "RdBu_r", -spread, spread),
    ]
    for axis, field, title, colours, low, high in panels:
        image = axis.imshow(field, origin="lower", extent=extent, cmap=colours, vmin=low, vmax=high,
                            interpolation="nearest")
        xs = x0 + pitch * np.arange(columns)
        zs = z0 + pitch * np.arange(rows)
        for outline, style in ((simulated, "-"), (measured, "--")):
            if outline.max() > threshold:
                axis.contour(xs, zs, outline, levels=[threshold], colors="white" if colours == "viridis" else "black",
                             linewidths=0.8, linestyles=style)
        for region in data["regions"][:-1]:
            centre = origin + region["end"] * length * direction
            ends = np.array([centre - half_width * across, centre + half_width * across])
            axis.plot(ends[:, 0], ends[:, 1], color="orange", linewidth=0.8)
        axis.plot(*data["simulated_peak_mm"], marker="x", color="red", markersize=8, linestyle="none")
        axis.plot(*data["measured_peak_mm"], marker="+", color="red", markersize=10, linestyle="none")
        if "sensors_mm" in data and field is measured:
            points = np.array(data["sensors_mm"])
            axis.plot(points[:, 0], points[:, 1], ".", color="white", markersize=2)
        axis.set_title(title)
        axis.set_xlabel("x, mm")
        axis.set_aspect("equal")
        figure.colorbar(image, ax=axis, shrink=0.8, label="kPa")
    axes[0].set_xlim(extent[0], extent[1])
    axes[0].set_ylim(extent[2], extent[3])
    axes[0].set_ylabel("z, mm")
    shares = ", ".join(f"{r['name']} {r['simulated_share']:.2f}/{r['measured_share']:.2f}" for r in data["regions"])
    figure.suptitle(f"{data['title']}\nPearson {data['pearson']:.3f}, Dice {data['dice']:.3f}; "
                    f"shares simulated/measured: {shares}\n"
                    "outlines: simulated (solid), measured (dashed); peaks: × simulated, + measured",
                    fontsize=9)
    figure.tight_layout()
    figure.savefig(directory / "comparison.png", dpi=110)


if __name__ == "__main__":
    main()
