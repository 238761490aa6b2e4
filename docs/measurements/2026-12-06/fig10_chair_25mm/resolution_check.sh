#!/bin/bash
# The designs of run.sh judged on another foam resolution: each optimised rest shape
# (chair_E/support_optimized.stl) meshed again by Mesh_3 at 15 mm top / 45 mm base (run.sh:
# 25 / 75 mm) and placed afresh (centred), against the flat block
# meshed the same way. One evaluation each (--max_evals=1 scores the start design). Run from
# this directory after run.sh.
B=/work/fig10bin/ergo_optimize
common="--flagfile=/work/main/data/chair.flags --robust_placements=1 --placement_checks=false --plot=false --max_evals=1 --threads=1 --support_model=soft --soft_support_edge_length=0.015 --soft_support_base_edge_length=0.045"
for E in 1.25e5 5e4 2e4; do
  /usr/bin/time -f "%e s wall" $B $common --support_youngs_modulus=$E --out=res15_flat_$E > log_res15_flat_$E.txt 2>&1
  /usr/bin/time -f "%e s wall" $B $common --support_youngs_modulus=$E --support_mesh=chair_$E/support_optimized.stl --support_unit=mm --out=res15_design_$E > log_res15_design_$E.txt 2>&1
done
# The 20 kPa design on the 15 mm foam did not reach equilibrium in 100 Newton iterations
# (90 projected steps); again with 300.
/usr/bin/time -f "%e s wall" $B $common --support_youngs_modulus=2e4 --threads=2 --max_newton_iterations=300 --support_mesh=chair_2e4/support_optimized.stl --support_unit=mm --out=res15_design_2e4_300 > log_res15_design_2e4_300.txt 2>&1
