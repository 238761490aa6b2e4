#!/bin/bash
# Fig. 10-lite: the quick chair, flat start, one placement, 150 s of optimisation per support.
B=/work/main/build/bin/ergo_optimize
common="--flagfile=/work/main/data/chair.flags --robust_placements=1 --placement_checks=false --plot=true --max_seconds=150"
for E in rigid 2e4 5e4 1.25e5; do
  if [ $E = rigid ]; then extra="--support_springs"; else extra="--support_model=soft --support_youngs_modulus=$E --soft_support_edge_length=0.04 --soft_support_base_edge_length=0.1"; fi
  /usr/bin/time -f "%e s wall" $B $common $extra --out=chair_$E > log_$E.txt 2>&1
done
