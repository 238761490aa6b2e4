#!/usr/bin/python3
"""The Fig. 10 table of README "Soft supports" from run.sh's and resolution_check.sh's outputs."""
import json
import os

import meshio
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))


def rest_change(E):
    """Largest and mean (over the vertices that moved > 1 µm) support change, mm."""
    a = meshio.read(os.path.join(here, f"chair_{E}/support_initial.ply")).points
    b = meshio.read(os.path.join(here, f"chair_{E}/support_optimized.ply")).points
    d = np.linalg.norm(b - a, axis=1)
    moved = d[d > 1e-3]
    return d.max(), moved.mean() if moved.size else 0.0


for E in ["rigid", "1.25e5", "5e4", "2e4"]:
    path = os.path.join(here, f"chair_{E}/summary.json")
    if not os.path.exists(path):
        continue
    d = json.load(open(path))
    largest, mean = rest_change(E)
    checks = ", ".join(f"{p['name']} " + (f"{p['reduction_percent']:.1f}" if p["converged"] else
                                          "did not converge") for p in d["placement_checks"])
    converged = [p["reduction_percent"] for p in d["placement_checks"] if p["converged"]]
    worst = f"{min(converged):.1f} %" + ("" if len(converged) == len(d["placement_checks"])
                                         else f" of {len(converged)}")
    row = (f"| {E} | {d['initial_score']:.3g} | {d['optimized_score']:.3g} | "
           f"**{d['reduction_percent']:.1f} %** | {worst} | "
           f"{d['initial_peak_pressure_Pa'] / 1e3:.1f} → {d['fresh_peak_pressure_Pa'] / 1e3:.1f} kPa | "
           f"{largest:.1f} / {mean:.2f} mm | {d['evaluations']} | {d['wall_s']:.0f} s |")
    flat = os.path.join(here, f"res15_flat_{E}/summary.json")
    design = os.path.join(here, f"res15_design_{E}/summary.json")
    retried = os.path.join(here, f"res15_design_{E}_300/summary.json")  # 300 Newton iterations
    if not os.path.exists(design) and os.path.exists(retried):
        design = retried
    if os.path.exists(flat) and os.path.exists(design):
        f = json.load(open(flat))
        g = json.load(open(design))
        row += (f" {100 * (1 - g['initial_score'] / f['initial_score']):.1f} % "
                f"({f['initial_score']:.3g} → {g['initial_score']:.3g}) |")
    elif os.path.exists(flat):
        row += " the design did not reach equilibrium |"
    else:
        row += " – |"
    print(row)
    print("   checks:", checks)
