#!/usr/bin/env python3
"""Pictures of an ergo_optimize run (paper Figs. 6, 8, 9 style).

usage: plot_results.py DIR   (reads DIR/plot_data.json and DIR/history.csv, writes
    DIR/pressure_maps.png        initial and optimised skin pressure, one colour scale,
                                 seen from the support's side (tissue squeezed past its
                                 material law's range marked)
    DIR/pressure_histograms.png  the two pressure histograms overlaid
    DIR/displacement.png         how far each support vertex moved, mm
    DIR/phi_history.png          phi/phi0 over iterations and evaluations)
Needs matplotlib (Debian: python3-matplotlib); exits 3 without it. Writes each PNG to a
temporary name first and renames it, so no partial picture is ever left behind.
"""
import csv
import json
import os
import sys


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=120, bbox_inches="tight")
    os.replace(tmp, path)


def mark_regions(ax, regions, share_key):
    """The scenario's bands along the map's second axis (the shoe: rearfoot, midfoot,
    forefoot), dashed at their inner ends, each labelled with its share of the load."""
    if not regions:
        return
    ends = sorted({round(b[e] * 1e3, 6) for b in regions for e in ("v_from", "v_to")})
    for v in ends[1:-1]:
        ax.axhline(v, color="0.6", linestyle="--", linewidth=0.8)
    for band in regions:
        share = band.get(share_key)
        label = band["name"] + ("" if share is None else " %.0f %%" % (100 * share))
        ax.text(1.02, (band["v_from"] + band["v_to"]) / 2 * 1e3, label, rotation=90,
                va="center", ha="left", fontsize=8, transform=ax.get_yaxis_transform())


def mark_crushed(ax, points):
    """Where the tissue is squeezed past its material law's range (its pressure there is the
    law's numerical extension): small crosses, with their count in the legend."""
    if not points:
        return
    ax.plot([p[0] * 1e3 for p in points], [p[1] * 1e3 for p in points], marker="x",
            color="deepskyblue", markersize=4, linestyle="none",
            label="tissue past its law's range (%d tets)" % len(points))
    ax.legend(loc="lower left", fontsize=8)


def pressure_maps(plt, data, out_dir):
    initial, optimized = data["initial"]["skin"], data["optimized"]["skin"]
    top = max(max(initial["pressure"] or [0]), max(optimized["pressure"] or [0]), 1e-12) / 1e3
    fig, axes = plt.subplots(1, 2, figsize=(11, 5), constrained_layout=True)
    for ax, skin, title in ((axes[0], initial, "initial"), (axes[1], optimized, "optimised")):
        u = [p[0] * 1e3 for p in skin["points2d"]]
        v = [p[1] * 1e3 for p in skin["points2d"]]
        kpa = [p / 1e3 for p in skin["pressure"]]
        if skin["triangles"]:
            mesh = ax.tripcolor(u, v, skin["triangles"], kpa, shading="gouraud", cmap="inferno", vmin=0, vmax=top)
        ax.set_title("%s: peak %.2f kPa" % (title, max(kpa or [0])))
        mark_crushed(ax, data["initial" if title == "initial" else "optimized"].get("crushed_points2d"))
        mark_regions(ax, data.get("regions"), "initial_share" if title == "initial" else "optimized_share")
        ax.set_aspect("equal")
        ax.set_xlabel(data["view"]["axes"][0] + " (mm)")
        ax.set_ylabel(data["view"]["axes"][1] + " (mm)")
    fig.colorbar(mesh, ax=axes, label="contact pressure (kPa)", shrink=0.8)
    fig.suptitle("skin pressure seen from the support (%s)" % data.get("scenario", ""))
    save(fig, os.path.join(out_dir, "pressure_maps.png"))


def histograms(plt, data, out_dir):
    fig, ax = plt.subplots(figsize=(7, 4.5), constrained_layout=True)
    initial = [p / 1e3 for p in data["initial"]["skin"]["pressure"] if p > 0]
    optimized = [p / 1e3 for p in data["optimized"]["skin"]["pressure"] if p > 0]
    top = max(initial + optimized + [1e-12])
    bins = [top * i / 30 for i in range(31)]
    ax.hist(initial, bins=bins, alpha=0.55, color="tab:blue", label="initial (%d vertices)" % len(initial))
    ax.hist(optimized, bins=bins, alpha=0.55, color="tab:pink", label="optimised (%d vertices)" % len(optimized))
    ax.set_xlabel("contact pressure (kPa)")
    ax.set_ylabel("skin vertices")
    ax.legend()
    ax.set_title("pressure histograms")
    save(fig, os.path.join(out_dir, "pressure_histograms.png"))


def displacement(plt, data, out_dir):
    d = data["support_displacement"]
    fig, ax = plt.subplots(figsize=(6, 5), constrained_layout=True)
    u = [p[0] * 1e3 for p in d["points2d"]]
    v = [p[1] * 1e3 for p in d["points2d"]]
    if d["triangles"]:
        mesh = ax.tripcolor(u, v, d["triangles"], d["displacement_mm"], shading="gouraud", cmap="viridis")
        fig.colorbar(mesh, ax=ax, label="displacement (mm)")
    ax.set_aspect("equal")
    ax.set_xlabel(data["view"]["axes"][0] + " (mm)")
    ax.set_ylabel(data["view"]["axes"][1] + " (mm)")
    ax.set_title("support displacement, max %.2f mm" % max(d["displacement_mm"] or [0]))
    save(fig, os.path.join(out_dir, "displacement.png"))


def history(plt, out_dir):
    path = os.path.join(out_dir, "history.csv")
    if not os.path.exists(path):
        return
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return
    phi0 = float(rows[0]["phi"])
    fig, axes = plt.subplots(1, 2, figsize=(11, 4), constrained_layout=True)
    axes[0].plot([int(r["iteration"]) for r in rows], [float(r["phi"]) / phi0 for r in rows], "o-")
    axes[0].set_xlabel("iteration")
    axes[1].plot([int(r["evaluations"]) for r in rows], [float(r["phi"]) / phi0 for r in rows], "o-")
    axes[1].set_xlabel("evaluations (equilibrium solves)")
    for ax in axes:
        ax.set_ylabel("phi / phi0")
        ax.grid(True, alpha=0.3)
    fig.suptitle("objective over the optimisation")
    save(fig, os.path.join(out_dir, "phi_history.png"))


def import_pyplot(script):
    """matplotlib.pyplot drawing to files (Agg), or None after saying it is missing."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("%s: matplotlib is not installed (apt-get install python3-matplotlib)" % script,
              file=sys.stderr)
        return None
    return plt


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out_dir = sys.argv[1]
    plt = import_pyplot("plot_results.py")
    if plt is None:
        return 3
    with open(os.path.join(out_dir, "plot_data.json")) as f:
        data = json.load(f)
    pressure_maps(plt, data, out_dir)
    histograms(plt, data, out_dir)
    displacement(plt, data, out_dir)
    history(plt, out_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
