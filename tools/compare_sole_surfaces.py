#!/usr/bin/env python3
"""How far apart two optimised designs of the same flat-topped support are, whatever their
meshes: the top face's vertical displacement (optimised minus initial) of each run is
interpolated linearly onto the other's top vertices; prints the RMS difference relative to
the RMS displacement (both ways) and the largest displacements.

usage: compare_sole_surfaces.py RUN_A RUN_B   (ergo_optimize output directories)
"""
import sys

import matplotlib.tri as mtri
import numpy as np


def read_ply(path):
    with open(path) as f:
        lines = f.read().split("\n")
    end = lines.index("end_header")
    count = next(int(l.split()[2]) for l in lines if l.startswith("element vertex"))
    return np.array([[float(v) for v in l.split()] for l in lines[end + 1:end + 1 + count]])


def top_displacement(run):
    initial = read_ply(run + "/support_initial.ply")
    optimised = read_ply(run + "/support_optimized.ply")
    top = initial[:, 1] > initial[:, 1].max() - 1e-6  # the flat top at its initial height
    return initial[top][:, [0, 2]], (optimised - initial)[top][:, 1]


def interpolate(points, values, at):
    triangulation = mtri.Triangulation(points[:, 0], points[:, 1])
    result = mtri.LinearTriInterpolator(triangulation, values)(at[:, 0], at[:, 1])
    return np.ma.filled(result, np.nan)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a_points, a = top_displacement(sys.argv[1])
    b_points, b = top_displacement(sys.argv[2])
    for name, points, own, other_points, other in (("A", a_points, a, b_points, b),
                                                   ("B", b_points, b, a_points, a)):
        mapped = interpolate(other_points, other, points)
        inside = np.isfinite(mapped)
        rms_own = np.sqrt(np.mean(own[inside] ** 2))
        rms_difference = np.sqrt(np.mean((own[inside] - mapped[inside]) ** 2))
        print(f"on {name}'s {inside.sum()} top vertices: RMS displacement {rms_own:.3f} mm, "
              f"RMS difference {rms_difference:.3f} mm = {100 * rms_difference / rms_own:.1f} %, "
              f"largest |displacement| {np.abs(own).max():.2f} mm")


if __name__ == "__main__":
    main()
