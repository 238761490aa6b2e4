#!/usr/bin/env python3
"""Optimises the quick shoe sole with SciPy's L-BFGS-B through ergo's Python bindings and
plots the skin's pressure maps on the flat and on the optimised sole, the foot placed
afresh on each (the score a wearer gets, not the optimiser's path).

    PYTHONPATH=build/python /usr/bin/python3 examples/optimize_shoe_scipy.py \
        [--max_evals=40] [--out=example_out] [--preset=quick]

Writes OUT/pressure_maps.png and OUT/result.json (scores, evaluations, wall time).
"""
import argparse
import json
import pathlib
import time

import numpy as np
import scipy.optimize

import ergo


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--flagfile", default=str(pathlib.Path(__file__).resolve().parents[1]
                                                  / "data" / "shoe.flags"))
    parser.add_argument("--preset", default="quick")
    parser.add_argument("--max_evals", type=int, default=40)
    parser.add_argument("--out", default="example_out")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    begin = time.perf_counter()
    scene = ergo.scenario(flagfile=args.flagfile, preset=args.preset)
    print(scene)
    path = scene.problem()           # warm-started along the optimiser's path: cheap
    fresh = scene.problem("fresh")   # the foot placed afresh: the score reported
    x0 = path.initial_design()
    phi0 = path.evaluate(x0, gradient=False)["phi"]
    setup_seconds = time.perf_counter() - begin

    evaluations = 0
    best = {"phi": 1.0, "x": x0}

    class BudgetSpent(Exception):
        pass

    def objective(x):
        # L-BFGS-B checks maxfun only between iterations (its line search can overrun it):
        # the budget is enforced here, as ergo_optimize counts it, and the best design kept.
        nonlocal evaluations
        if evaluations >= args.max_evals:
            raise BudgetSpent()
        evaluations += 1
        value = path.evaluate(x, gradient=True)
        if not value["ok"]:  # a failed equilibrium: a large value sends L-BFGS-B back
            return 10.0, np.zeros_like(x)
        scaled = value["phi"] / phi0
        if scaled < best["phi"]:
            best.update(phi=scaled, x=x.copy())
        print(f"  evaluation {evaluations:3d}  phi/phi0 {scaled:.4f}", flush=True)
        return scaled, value["gradient"] / phi0

    start = time.perf_counter()
    message = "budget spent"
    try:
        # Vertex moves of at most 2 cm either way, like ergo_optimize's move limit.
        result = scipy.optimize.minimize(objective, x0, jac=True, method="L-BFGS-B",
                                         bounds=[(-0.02, 0.02)] * x0.size,
                                         options={"maxfun": args.max_evals})
        message = str(result.message)
    except BudgetSpent:
        pass
    optimise_seconds = time.perf_counter() - start

    initial = fresh.evaluate(x0, gradient=False)
    final = fresh.evaluate(best["x"], gradient=False)
    reduction = 100 * (1 - final["phi"] / initial["phi"])
    print(f"L-BFGS-B: {evaluations} evaluations in {optimise_seconds:.1f} s; placed afresh "
          f"phi {initial['phi']:.4g} -> {final['phi']:.4g} ({reduction:.1f} % lower), peak "
          f"{initial['peak_pressure'] / 1e3:.0f} -> {final['peak_pressure'] / 1e3:.0f} kPa")

    plot(scene, initial, final, out / "pressure_maps.png")
    summary = {"scenario": scene.name, "preset": args.preset, "evaluations": evaluations,
               "setup_seconds": setup_seconds, "optimise_seconds": optimise_seconds,
               "seconds_per_evaluation": optimise_seconds / max(evaluations, 1),
               "initial_fresh_phi": initial["phi"], "optimized_fresh_phi": final["phi"],
               "reduction_percent": reduction, "initial_peak_pressure_Pa": initial["peak_pressure"],
               "optimized_peak_pressure_Pa": final["peak_pressure"],
               "scipy_message": message}
    (out / "result.json").write_text(json.dumps(summary, indent=2) + "\n")
    print(f"wrote {out}/pressure_maps.png, {out}/result.json")


def plot(scene, initial, final, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    body = scene.body
    skin = body.rest_vertices[body.skin_vertices]
    # The plantar side only: skin within 3 cm of the sole's lowest point.
    plantar = skin[:, 1] < skin[:, 1].min() + 0.03
    # The sole's view: the skin seen from below, x across and z along the foot.
    top = max(initial["skin_pressure"].max(), final["skin_pressure"].max()) / 1e3
    figure, axes = plt.subplots(1, 2, figsize=(8, 6), sharey=True)
    for axis, value, title in [(axes[0], initial, "flat sole"), (axes[1], final, "optimised")]:
        pressure = value["skin_pressure"] / 1e3
        touching = pressure > 0
        quiet = plantar & ~touching
        axis.scatter(skin[quiet, 0], skin[quiet, 2], s=2, c="0.85")
        drawn = axis.scatter(skin[touching, 0], skin[touching, 2], s=8, c=pressure[touching],
                             cmap="viridis", vmin=0, vmax=top)
        axis.set_title(f"{title}: peak {pressure.max():.0f} kPa")
        axis.set_aspect("equal")
        axis.set_xlabel("x (m)")
    axes[0].set_ylabel("z (m)")
    figure.colorbar(drawn, ax=axes, label="skin pressure (kPa), foot placed afresh")
    figure.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
