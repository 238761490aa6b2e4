#!/usr/bin/env python3
"""A foot scan posed before meshing, for the standing-pose experiments of README "Scans": how
much of issue 14's split a scan taken at rest would gain from the pose a standing foot takes.
An experiment's tool, not a model of the joints: vertices are turned, the faces kept.

Two turns, in ergo's frame (y up, the length along z from the heel at the smallest z; the
scan's own axes are mapped by --axes as ergo_body's --axes does, and mapped back on writing):
  --forefoot_eversion=DEG  the forefoot turned about an axis along z through the foot's
      mid-width (x) and --forefoot_axis_height mm above its lowest skin (roughly Manter's
      longitudinal midtarsal axis), by 0 behind 35 % of the length, DEG from 65 %, and a
      smoothstep between; > 0 lowers the -x side, as --shoe_roll > 0 does (for the FIND foot,
      -x is medial: eversion);
  --toe_flexion=DEG  the toes turned down about a transverse axis (along x) at 72 % of the
      length and --toe_axis_height mm up, by 0 behind it, DEG from 80 %, smoothstep between.
The eversion is applied first. The scan must be an OBJ in metres (v and f lines; other lines
are kept).
  --measure_forefoot=LO,HI  instead of posing, print how far the forefoot stands medial side
      up: the lowest skin (within 3 cm of the floor) in nine bins across the footprint of the
      band LO..HI of the length (fractions from the heel), fitted by a line across the foot;
      --medial=-x|+x says which side is medial (-x for the FIND foot, a left foot).

usage: pose_foot_scan.py IN.obj OUT.obj [--axes=y,z,x] [--forefoot_eversion=DEG]
           [--toe_flexion=DEG] [--forefoot_axis_height=25] [--toe_axis_height=15]
       pose_foot_scan.py IN.obj --measure_forefoot=0.63,0.77 [--axes=y,z,x] [--medial=-x]
"""
import math
import os
import sys

import numpy as np

FOREFOOT_RAMP = (0.35, 0.65)
TOE_RAMP = (0.72, 0.80)


def smoothstep(s, begin, end):
    t = np.clip((s - begin) / (end - begin), 0.0, 1.0)
    return t * t * (3 - 2 * t)


def axis_permutation(text):
    """ergo's x, y, z as indices of the scan's axes ("y,z,x": ergo x = scan y, ...)."""
    names = text.split(",")
    if sorted(names) != ["x", "y", "z"]:
        raise ValueError(f"--axes={text}: give a permutation of x,y,z, e.g. y,z,x")
    return ["xyz".index(n) for n in names]


def pose(points, forefoot_eversion_deg=0.0, toe_flexion_deg=0.0, forefoot_axis_height=0.025,
         toe_axis_height=0.015):
    """The posed copy of `points` (N x 3, ergo's frame, metres)."""
    p = np.array(points, dtype=float)
    lo, hi = p.min(axis=0), p.max(axis=0)
    length = hi[2] - lo[2]
    s = (p[:, 2] - lo[2]) / length
    # The forefoot: a turn about z through (mid-width, lowest skin + height).
    phi = np.radians(forefoot_eversion_deg) * smoothstep(s, *FOREFOOT_RAMP)
    ax, ay = 0.5 * (lo[0] + hi[0]), lo[1] + forefoot_axis_height
    dx, dy = p[:, 0] - ax, p[:, 1] - ay
    turned = phi != 0  # the rest keep their coordinates bit for bit
    p[:, 0] = np.where(turned, ax + dx * np.cos(phi) - dy * np.sin(phi), p[:, 0])
    p[:, 1] = np.where(turned, ay + dx * np.sin(phi) + dy * np.cos(phi), p[:, 1])
    # The toes: a turn about x through (y = lowest skin + height, z at the toes' root); a
    # positive angle takes the points ahead of the axis down.
    a = np.radians(toe_flexion_deg) * smoothstep(s, *TOE_RAMP)
    az, ay = lo[2] + TOE_RAMP[0] * length, lo[1] + toe_axis_height
    dz, dy = p[:, 2] - az, p[:, 1] - ay
    turned = a != 0
    p[:, 1] = np.where(turned, ay + dy * np.cos(a) - dz * np.sin(a), p[:, 1])
    p[:, 2] = np.where(turned, az + dy * np.sin(a) + dz * np.cos(a), p[:, 2])
    return p


def forefoot_angle(points, band, medial_sign):
    """Degrees the forefoot's lowest skin rises towards the medial side across the foot, over
    the band (lo, hi) of the length from the heel at the smallest z (ergo's frame, metres)."""
    p = np.asarray(points, dtype=float)
    lo, hi = p.min(axis=0), p.max(axis=0)
    s = (p[:, 2] - lo[2]) / (hi[2] - lo[2])
    sole = p[(s >= band[0]) & (s <= band[1]) & (p[:, 1] < lo[1] + 0.03)]
    if len(sole) < 3:
        raise ValueError(f"--measure_forefoot={band[0]},{band[1]}: no skin within 3 cm of the "
                         "floor in that band")
    left, right = sole[:, 0].min(), sole[:, 0].max()
    centre, half = 0.5 * (left + right), 0.5 * (right - left)
    lowest = []
    for a in np.linspace(-0.8, 0.8, 9):
        near = np.abs((sole[:, 0] - centre) / half - a) < 0.1
        if near.any():
            k = np.argmin(sole[near, 1])
            lowest.append(sole[near][k, :2])
    if len(lowest) < 2:
        raise ValueError("--measure_forefoot: fewer than two bins across the foot hold skin")
    lowest = np.array(lowest)
    slope = np.polyfit(medial_sign * lowest[:, 0], lowest[:, 1], 1)[0]
    return math.degrees(math.atan(slope))


def main(argv):
    options = {"axes": "x,y,z", "forefoot_eversion": "0", "toe_flexion": "0",
               "forefoot_axis_height": "25", "toe_axis_height": "15", "measure_forefoot": "",
               "medial": "-x"}
    paths = []
    for arg in argv[1:]:
        if arg.startswith("--") and "=" in arg and arg[2:].split("=", 1)[0] in options:
            key, value = arg[2:].split("=", 1)
            options[key] = value
        elif arg.startswith("--"):
            sys.exit(f"pose_foot_scan.py: unknown option {arg}\n{__doc__}")
        else:
            paths.append(arg)
    measure = options["measure_forefoot"] != ""
    if len(paths) != (1 if measure else 2):
        sys.exit(__doc__)
    try:
        order = axis_permutation(options["axes"])
        if options["medial"] not in ("-x", "+x"):
            raise ValueError(f"--medial={options['medial']}: give -x or +x")
        band = None
        if measure:
            try:
                band = [float(t) for t in options["measure_forefoot"].split(",")]
            except ValueError:
                band = []
            if len(band) != 2 or not 0 <= band[0] < band[1] <= 1:
                raise ValueError(f"--measure_forefoot={options['measure_forefoot']}: give two "
                                 "fractions of the length, LO < HI, e.g. 0.63,0.77")
        values = {}
        for key, text in options.items():
            if key in ("axes", "measure_forefoot", "medial"):
                continue
            try:
                value = float(text)
            except ValueError:
                value = math.nan
            if not math.isfinite(value):
                raise ValueError(f"--{key}={text}: give a finite number")
            values[key] = value
    except ValueError as error:
        sys.exit(f"pose_foot_scan.py: {error}")
    try:
        with open(paths[0]) as f:
            lines = f.read().split("\n")
    except (OSError, UnicodeDecodeError) as error:
        sys.exit(f"pose_foot_scan.py: cannot read {paths[0]}: {error}")
    rows = [i for i, line in enumerate(lines) if line.startswith("v ")]
    if not rows:
        sys.exit(f"pose_foot_scan.py: {paths[0]}: no vertex (v) lines")
    scan = np.empty((len(rows), 3))
    for k, i in enumerate(rows):
        try:
            scan[k] = [float(t) for t in lines[i].split()[1:4]]
        except ValueError:
            sys.exit(f"pose_foot_scan.py: {paths[0]}:{i + 1}: a vertex needs three numbers: "
                     f"'{lines[i]}'")
        if not np.isfinite(scan[k]).all():
            sys.exit(f"pose_foot_scan.py: {paths[0]}:{i + 1}: a vertex coordinate is not finite")
    ergo = scan[:, order]
    if measure:
        try:
            angle = forefoot_angle(ergo, band, -1.0 if options["medial"] == "-x" else 1.0)
        except ValueError as error:
            sys.exit(f"pose_foot_scan.py: {paths[0]}: {error}")
        print(f"forefoot over {band[0]}-{band[1]} of the length: {angle:.2f} deg, medial side up")
        return
    posed = pose(ergo, values["forefoot_eversion"], values["toe_flexion"],
                 1e-3 * values["forefoot_axis_height"], 1e-3 * values["toe_axis_height"])
    back = np.empty_like(posed)
    back[:, order] = posed
    for i, (x, y, z) in zip(rows, back):
        lines[i] = f"v {float(x)!r} {float(y)!r} {float(z)!r}"
    # Written beside the target, then renamed: a failed write leaves no partial file.
    temporary = paths[1] + ".partial"
    try:
        with open(temporary, "w") as f:
            f.write("\n".join(lines))
        os.replace(temporary, paths[1])
    except OSError as error:
        if os.path.exists(temporary):
            os.remove(temporary)
        sys.exit(f"pose_foot_scan.py: cannot write {paths[1]}: {error}")
    print(f"posed {len(rows)} vertices: forefoot everted {values['forefoot_eversion']} deg, "
          f"toes flexed {values['toe_flexion']} deg -> {paths[1]}")


if __name__ == "__main__":
    main(sys.argv)
