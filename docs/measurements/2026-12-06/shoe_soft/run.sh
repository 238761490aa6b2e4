#!/bin/bash
# The quick shoe on a soft insole (E = 500 kPa, ν = 0.3, the sole meshed at 8 → 12 mm):
# flat start, one placement optimised, the ±3 mm / ±1° placement checks on, 600 s of
# nlopt-lbfgs, one thread. Beside it the rigid sole with two-way springs at the same budget.
# Run from this directory.
B=/work/fig10bin/ergo_optimize_shoe  # build/bin/ergo_optimize with the Mesh_3 restart for thin slabs
common="--flagfile=/work/main/data/shoe.flags --robust_placements=1 --placement_checks=true --plot=true --max_seconds=600 --threads=1"
/usr/bin/time -f "%e s wall" $B $common --support_model=soft --support_youngs_modulus=5e5 --soft_support_edge_length=0.008 --soft_support_base_edge_length=0.012 --out=shoe_5e5 > log_5e5.txt 2>&1
/usr/bin/time -f "%e s wall" $B $common --support_springs --out=shoe_rigid > log_rigid.txt 2>&1
