#!/usr/bin/env python3
"""Pictures of an ergo_simulate run: one equilibrium's skin pressure seen from the support.

usage: plot_simulation.py DIR   (reads DIR/plot_data.json, writes
    DIR/pressure_map.png        the skin's contact pressure seen from the support, its peak,
                                the centre of pressure and any tissue squeezed past its
                                material law marked, and for a foot the rearfoot / midfoot /
                                forefoot bands with their shares
    DIR/pressure_histogram.png  the pressures of the skin vertices in contact)
Needs matplotlib (Debian: python3-matplotlib); exits 3 without it, 2 on a missing or unusable
plot_data.json (with a message naming it). Writes each PNG to a temporary name first and
renames it, so no partial picture is ever left behind.
"""
import json
import os
import sys

from plot_results import import_pyplot, mark_crushed, mark_regions, save


def load(out_dir):
    path = os.path.join(out_dir, "plot_data.json")
    try:
        with open(path) as f:
            data = json.load(f)
        skin = data["skin"]
        points, pressure = skin["points2d"], skin["pressure"]
        if len(points) != len(pressure):
            raise ValueError("%d points but %d pressures" % (len(points), len(pressure)))
        axes = data["view"]["axes"]
    except (OSError, ValueError, KeyError, TypeError) as error:
        raise SystemExit("plot_simulation.py: %s: %s (write it with ergo_simulate)" % (path, error))
    return data, skin, axes


def pressure_map(plt, data, skin, axes, out_dir):
    u = [p[0] * 1e3 for p in skin["points2d"]]
    v = [p[1] * 1e3 for p in skin["points2d"]]
    kpa = [p / 1e3 for p in skin["pressure"]]
    peak = max(kpa or [0])
    fig, ax = plt.subplots(figsize=(6, 7), constrained_layout=True)
    if skin["triangles"]:
        mesh = ax.tripcolor(u, v, skin["triangles"], kpa, shading="gouraud", cmap="inferno",
                            vmin=0, vmax=max(peak, 1e-12))
        fig.colorbar(mesh, ax=ax, label="contact pressure (kPa)", shrink=0.8)
    if peak > 0:
        i = kpa.index(peak)
        ax.plot(u[i], v[i], marker="^", color="tab:cyan", markersize=9, linestyle="none",
                label="peak %.1f kPa" % peak)
    crushed = data.get("crushed_points2d") or []
    mark_crushed(ax, crushed)
    cop = data.get("centre_of_pressure2d")
    if cop:
        ax.plot(cop[0] * 1e3, cop[1] * 1e3, marker="+", color="tab:green", markersize=14,
                markeredgewidth=2, linestyle="none", label="centre of pressure")
    mark_regions(ax, data.get("regions"), "share")
    if peak > 0 or cop or crushed:
        ax.legend(loc="lower left", fontsize=8)
    ax.set_aspect("equal")
    ax.set_xlabel(axes[0] + " (mm)")
    ax.set_ylabel(axes[1] + " (mm)")
    ax.set_title("skin pressure seen from the support\n%s" % data.get("title", ""))
    save(fig, os.path.join(out_dir, "pressure_map.png"))


def histogram(plt, data, skin, out_dir):
    kpa = [p / 1e3 for p in skin["pressure"] if p > 0]
    fig, ax = plt.subplots(figsize=(7, 4.5), constrained_layout=True)
    top = max(kpa + [1e-12])
    ax.hist(kpa, bins=[top * i / 30 for i in range(31)], color="tab:blue",
            label="%d skin vertices in contact" % len(kpa))
    ax.set_xlabel("contact pressure (kPa)")
    ax.set_ylabel("skin vertices")
    ax.legend()
    ax.set_title("pressure histogram (%s)" % data.get("title", ""))
    save(fig, os.path.join(out_dir, "pressure_histogram.png"))


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out_dir = sys.argv[1]
    plt = import_pyplot("plot_simulation.py")
    if plt is None:
        return 3
    try:
        data, skin, axes = load(out_dir)
    except SystemExit as refusal:
        print(refusal, file=sys.stderr)
        return 2
    pressure_map(plt, data, skin, axes, out_dir)
    histogram(plt, data, skin, out_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
