#!/bin/bash
# Fig. 10 (paper §5.4) on the quick chair, flat start: rigid (two-way springs) and foam at
# E = 125, 50, 20 kPa, the foam's top meshed at the rigid block's 25 mm (75 mm at the base),
# one placement optimised, the ±3 mm / ±1° placement checks on, 900 s of nlopt-lbfgs per row,
# one thread (the machine's other core was building). Run from this directory.
B=/work/fig10bin/ergo_optimize  # a copy of build/bin/ergo_optimize at 66db805, so rebuilds do not change the run
common="--flagfile=/work/main/data/chair.flags --robust_placements=1 --placement_checks=true --plot=true --max_seconds=900 --threads=1"
for E in rigid 1.25e5 5e4 2e4; do
  if [ $E = rigid ]; then extra="--support_springs"; else extra="--support_model=soft --support_youngs_modulus=$E --soft_support_edge_length=0.025 --soft_support_base_edge_length=0.075"; fi
  /usr/bin/time -f "%e s wall" $B $common $extra --out=chair_$E > log_$E.txt 2>&1
done
