// The small test scene of paper Fig. 5 and of the optimiser tests: a soft ball (a layer of
// tissue around a rigid spherical core, meshed by the body builder) resting on a plate
// with one Gaussian bump. Only the plate's top face is designed. The ball's core only
// translates vertically (a sphere's rotations would be unconstrained).
#pragma once

#include <Eigen/Core>

#include "problems/scenario.h"

namespace ergo {

struct BumpScenarioOptions {
  double ball_radius = 0.05;    // m
  double core_radius = 0.03;    // m
  double youngs_modulus = 1e4;  // Pa
  double poisson_ratio = 0.45;
  double edge_length = 0.012;      // body mesh target edge, m
  double plate_half_width = 0.08;  // m, square plate
  int plate_cells = 16;            // per side of the top face
  double plate_thickness = 0.02;   // m
  double bump_height = 0.004;      // m
  double bump_width = 0.015;       // Gaussian σ, m (spatial frequency ~ 1/width)
  Eigen::Vector2d bump_centre = Eigen::Vector2d(0.012, 0.004);  // (x, z), m
  double contact_stiffness = 3e7;  // κ, Pa/m (≈ 0.3 mm penetration for this ball)
  double drop_height = 0.002;      // gap between ball and bump top at the start, m
};

// Builds the scene; throws InputError for options that cannot make one.
Scenario MakeBumpScenario(const BumpScenarioOptions& options = BumpScenarioOptions());

// A soft ball body of the above kind, centred at `centre` (used by several scenes).
LayeredBody MakeSoftBall(double radius, double core_radius, double youngs_modulus,
                         double poisson_ratio, double edge_length, const Eigen::Vector3d& centre,
                         const LayeredBodyOptions& options);

}  // namespace ergo
