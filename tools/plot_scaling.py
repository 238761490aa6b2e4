#!/usr/bin/env python3
"""The scaling of a warm design evaluation with the body's and the support's size, from
build/bin/scaling_benchmark's JSON: prints a Markdown table and the fitted exponents
(least squares on log time against log vertices), writes a log-log PNG of both series.

usage: plot_scaling.py SCALING.json OUT.png
Needs matplotlib for the PNG (Debian: python3-matplotlib); without it, only the table (exit 3).
"""
import json
import math
import re
import sys


UNIT_SECONDS = {"s": 1.0, "ms": 1e-3, "us": 1e-6, "ns": 1e-9}


def read_rows(path):
    with open(path) as f:
        runs = json.load(f)["benchmarks"]
    rows = []
    for run in runs:
        match = re.search(r"body=(\d+)k/support=(\d+)k", run["name"])
        if not match or run.get("error_occurred"):
            continue
        rows.append({"body_k": int(match.group(1)), "support_k": int(match.group(2)),
                     "seconds": run["real_time"] * UNIT_SECONDS[run.get("time_unit", "s")], **{k: v for k, v in run.items()
                                                      if isinstance(v, (int, float))}})
    return rows


def fitted_exponent(xs, ys):
    """Slope of log y against log x (least squares); None with fewer than two points."""
    if len(xs) < 2:
        return None
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def series(rows, vary, fixed_key, fixed_value):
    chosen = sorted((r for r in rows if r[fixed_key] == fixed_value), key=lambda r: r[vary])
    return chosen


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    rows = read_rows(sys.argv[1])
    if not rows:
        print(f"plot_scaling.py: no scaling rows in {sys.argv[1]}", file=sys.stderr)
        return 1
    print("| body vertices | support vertices | warm evaluation s | Newton its | factorisations "
          "| assembly s | contact s | support s | adjoint s | one factorisation s (cold) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(rows, key=lambda r: (r["body_vertices"], r["support_vertices"])):
        print(f"| {r['body_vertices']:,.0f} | {r['support_vertices']:,.0f} | {r['seconds']:.2f} "
              f"| {r['newton_iterations']:.0f} | {r['factorizations']:.0f} "
              f"| {r['assembly_s']:.2f} | {r['contact_s']:.2f} | {r['support_s']:.2f} "
              f"| {r['adjoint_s']:.2f} | {r['one_factorization_s']:.2f} |")
    by_body = series(rows, "body_k", "support_k", 40)
    by_support = series(rows, "support_k", "body_k", 10)
    fits = {}
    for name, chosen, size in (("body", by_body, "body_vertices"),
                               ("support", by_support, "support_vertices")):
        xs = [r[size] for r in chosen]
        fits[name] = (xs, [r["seconds"] for r in chosen], fitted_exponent(xs, [r["seconds"] for r in chosen]))
        if fits[name][2] is not None:
            print(f"\nwarm evaluation ∝ ({size})^{fits[name][2]:.2f}")
    factor_xs = [r["body_vertices"] for r in by_body if r["one_factorization_s"] > 0]
    factor_ys = [r["one_factorization_s"] for r in by_body if r["one_factorization_s"] > 0]
    factor_exponent = fitted_exponent(factor_xs, factor_ys)
    if factor_exponent is not None:
        print(f"one factorisation ∝ (body_vertices)^{factor_exponent:.2f}")
    try:
        import matplotlib
        matplotlib.use("Agg")  # no display needed
        import matplotlib.pyplot as plt
    except ImportError:
        print("plot_scaling.py: matplotlib is not installed; no PNG", file=sys.stderr)
        return 3
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, name, label in ((axes[0], "body", "body vertices (support ≈ 40k)"),
                            (axes[1], "support", "support vertices (body ≈ 10k)")):
        xs, ys, exponent = fits[name]
        if not xs:
            continue
        title = f"warm φ + ∇φ, exponent {exponent:.2f}" if exponent is not None else "warm φ + ∇φ"
        ax.loglog(xs, ys, "o-", label=title)
        if name == "body" and factor_xs:
            ax.loglog(factor_xs, factor_ys, "s--",
                      label=f"one factorisation (cold), exponent {factor_exponent:.2f}")
        ax.set_xlabel(label)
        ax.set_ylabel("seconds")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.suptitle("Paper chair: one warm design evaluation after a 0.2 mm step")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)
    print(f"\nwrote {sys.argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
