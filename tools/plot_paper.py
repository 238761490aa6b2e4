#!/usr/bin/env python3
"""Pictures of an ergo_paper folder.

usage: plot_paper.py DIR   (reads DIR/figures.json, each run's plot_data.json, DIR/table2.csv
    and DIR/depth_sweep.csv where present; writes
    DIR/pressure_maps_<scene>.png  every design of a scene, skin pressure seen from the
                                   support, one colour scale per scene
    DIR/table2.png                 fresh reduction against the smoothing strength
    DIR/depth_sweep.png            fresh reduction against the negative-image depth)
Needs matplotlib (Debian: python3-matplotlib); exits 3 without it. Each PNG is written to a
temporary name first and renamed, so no partial picture is left behind.
"""
import csv
import json
import math
import os
import sys


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110, bbox_inches="tight")
    os.replace(tmp, path)


def number(text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def pressure_maps(plt, out_dir, scene, panels):
    skins = []
    for panel in panels:
        path = os.path.join(panel["case"], "plot_data.json")
        try:
            with open(path) as f:
                skins.append((panel, json.load(f)[panel["side"]]["skin"]))
        except (OSError, KeyError, ValueError) as error:
            print("plot_paper.py: skipping %s (%s)" % (path, error), file=sys.stderr)
    if not skins:
        return
    top = max(max(skin["pressure"] or [0]) for _, skin in skins) / 1e3
    top = max(top, 1e-9)
    columns = min(4, len(skins))
    rows = (len(skins) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(3.6 * columns, 3.4 * rows + 0.4),
                             constrained_layout=True, squeeze=False)
    mesh = None
    for k, ax in enumerate(axes.flat):
        if k >= len(skins):
            ax.axis("off")
            continue
        panel, skin = skins[k]
        u = [p[0] * 1e3 for p in skin["points2d"]]
        v = [p[1] * 1e3 for p in skin["points2d"]]
        kpa = [p / 1e3 for p in skin["pressure"]]
        if skin["triangles"]:
            mesh = ax.tripcolor(u, v, skin["triangles"], kpa, shading="gouraud", cmap="inferno",
                                vmin=0, vmax=top)
        score = number(panel.get("score"))
        ax.set_title("%s\nφ %s, skin peak %.1f kPa"
                     % (panel["label"], "%.3g" % score if score is not None else "—",
                        max(kpa or [0])), fontsize=9)
        ax.set_aspect("equal")
        ax.tick_params(labelsize=7)
    if mesh is not None:
        fig.colorbar(mesh, ax=axes, label="skin contact pressure (kPa)", shrink=0.8)
    fig.suptitle("%s: every design placed afresh (φ counts both surfaces; the map is the "
                 "skin's side), one colour scale" % scene)
    save(fig, os.path.join(out_dir, "pressure_maps_%s.png" % scene))
    plt.close(fig)


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def gamma_plot(plt, out_dir):
    rows = [r for r in read_csv(os.path.join(out_dir, "table2.csv"))
            if r["design_space"] == "raw vertices"]
    if not rows:
        return
    labels, ours, paper = [], [], []
    for r in rows:
        labels.append("0" if r["gamma_power"] in ("", "γ = 0") else "κ·1e%s" % r["gamma_power"])
        ours.append(number(r["reduction_percent"]))
        paper.append(number(r["paper_reduction_percent"]))
    fig, ax = plt.subplots(figsize=(6, 3.6), constrained_layout=True)
    xs = list(range(len(rows)))
    ax.plot([x for x, y in zip(xs, ours) if y is not None], [y for y in ours if y is not None],
            "o-", label="ergo, placed afresh")
    ax.plot([x for x, y in zip(xs, paper) if y is not None], [y for y in paper if y is not None],
            "s--", label="paper (Table 2)")
    ax.set_xticks(xs)
    ax.set_xticklabels(labels)
    ax.set_xlabel("smoothing strength γ")
    ax.set_ylabel("score reduction (%)")
    ax.axhline(0, color="grey", lw=0.5)
    ax.legend()
    ax.set_title("mouse: γ sweep in the raw-vertex design space")
    save(fig, os.path.join(out_dir, "table2.png"))
    plt.close(fig)


def depth_plot(plt, out_dir):
    rows = read_csv(os.path.join(out_dir, "depth_sweep.csv"))
    if not rows:
        return
    depth = [number(r["depth_m"]) * 100 for r in rows]
    fig, ax = plt.subplots(figsize=(6, 3.6), constrained_layout=True)
    for key, label in (("reduction_percent", "against its own start"),
                       ("reduction_vs_flat_percent", "against the flat chair")):
        pts = [(d, number(r[key])) for d, r in zip(depth, rows) if number(r[key]) is not None]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=label)
    ax.set_xlabel("negative-image depth (cm)")
    ax.set_ylabel("score reduction, placed afresh (%)")
    ax.axhline(0, color="grey", lw=0.5)
    ax.legend()
    ax.set_title("chair: negative-image start depth")
    save(fig, os.path.join(out_dir, "depth_sweep.png"))
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out_dir = sys.argv[1]
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("plot_paper.py: matplotlib is missing (apt-get install python3-matplotlib)",
              file=sys.stderr)
        return 3
    with open(os.path.join(out_dir, "figures.json")) as f:
        manifest = json.load(f)
    for scene, panels in manifest.get("scenes", {}).items():
        pressure_maps(plt, out_dir, scene, panels)
    gamma_plot(plt, out_dir)
    depth_plot(plt, out_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
