#!/usr/bin/env python3
"""How far apart two optimised designs of the same flat-topped support are, whatever their
meshes: the top face's vertical displacement (optimised minus initial) of each run is
interpolated linearly onto the other's top vertices; prints the RMS difference relative to
the RMS displacement (both ways) and the largest displacements.

With --transfer=DIR it also writes each design carried onto the other's mesh: DIR/a_on_b.ply
(run B's initial support, its top raised by A's displacement interpolated linearly) and
DIR/b_on_a.ply, to be scored like any support (ergo_optimize --support_mesh=… --support_unit=mm
--max_evals=1): two designs that differ in shape but score alike on both meshes sit in one
flat valley of φ; a design that scores worse on the other mesh depends on its own.

usage: compare_sole_surfaces.py RUN_A RUN_B [--transfer=DIR]   (ergo_optimize output dirs)
"""
import os
import sys

import matplotlib.tri as mtri
import numpy as np


def read_ply_lines(path):
    with open(path) as f:
        lines = f.read().split("\n")
    end = lines.index("end_header")
    count = next(int(l.split()[2]) for l in lines if l.startswith("element vertex"))
    return lines, end, count


def read_ply(path):
    lines, end, count = read_ply_lines(path)
    return np.array([[float(v) for v in l.split()] for l in lines[end + 1:end + 1 + count]])


def write_transferred(from_run, onto_run, path):
    """onto_run's initial support with its top raised by from_run's displacement."""
    points, displacement = top_displacement(from_run)
    lines, end, count = read_ply_lines(onto_run + "/support_initial.ply")
    vertices = read_ply(onto_run + "/support_initial.ply")
    top = vertices[:, 1] > vertices[:, 1].max() - 1e-6
    moved = interpolate(points, displacement, vertices[top][:, [0, 2]])
    vertices[np.flatnonzero(top), 1] += np.where(np.isfinite(moved), moved, 0.0)
    body = [" ".join(repr(float(c)) for c in v) for v in vertices]
    temporary = path + ".tmp"
    with open(temporary, "w") as f:
        f.write("\n".join(lines[:end + 1] + body + lines[end + 1 + count:]))
    os.replace(temporary, path)  # no partial file under the final name


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
    transfer = [a[len("--transfer="):] for a in sys.argv[1:] if a.startswith("--transfer=")]
    runs = [a for a in sys.argv[1:] if not a.startswith("--transfer=")]
    if len(runs) != 2 or len(transfer) > 1:
        sys.exit(__doc__)
    for run in runs:
        for name in ("support_initial.ply", "support_optimized.ply"):
            if not os.path.isfile(os.path.join(run, name)):
                sys.exit(f"compare_sole_surfaces.py: {run} has no {name}; give two "
                         "ergo_optimize output directories")
    a_points, a = top_displacement(runs[0])
    b_points, b = top_displacement(runs[1])
    for name, points, own, other_points, other in (("A", a_points, a, b_points, b),
                                                   ("B", b_points, b, a_points, a)):
        mapped = interpolate(other_points, other, points)
        inside = np.isfinite(mapped)
        rms_own = np.sqrt(np.mean(own[inside] ** 2))
        rms_difference = np.sqrt(np.mean((own[inside] - mapped[inside]) ** 2))
        print(f"on {name}'s {inside.sum()} top vertices: RMS displacement {rms_own:.3f} mm, "
              f"RMS difference {rms_difference:.3f} mm = {100 * rms_difference / rms_own:.1f} %, "
              f"largest |displacement| {np.abs(own).max():.2f} mm")
    if transfer:
        os.makedirs(transfer[0], exist_ok=True)
        write_transferred(runs[0], runs[1], os.path.join(transfer[0], "a_on_b.ply"))
        write_transferred(runs[1], runs[0], os.path.join(transfer[0], "b_on_a.ply"))
        print(f"wrote {transfer[0]}/a_on_b.ply and b_on_a.ply")


if __name__ == "__main__":
    main()
