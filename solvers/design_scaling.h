// How the scaled optimisers (Ceres, NLopt) see a design problem: parameters u with
// x = x₀ + length_scale · u and value φ(x) / value_scale, so that tolerances written for
// O(1) problems mean something here (DESIGN.md §7: Ceres' defaults are relative to the
// problem's scale).
#pragma once

namespace ergo {

struct DesignScaling {
  double value_scale = 1.0;   // φ is divided by this (φ(x₀))
  double length_scale = 1.0;  // x = x₀ + length_scale · u (Objective::LengthScale: 1 mm)
};

}  // namespace ergo
