// The mouse (paper §3.2, §5.3, Fig. 9): a relaxed right hand resting under its own weight on
// a mouse made as the paper made its neutral mouse — the CSG union (CGAL corefinement) of two
// non-concentric spheres, remeshed isotropically and smoothed by a few Taubin iterations; the
// hand only translates vertically; the mouse's upper part (what a hand resting from above can
// reach) is designed. Starts from the neutral mouse or its negative image. Presets "quick"
// and "paper" (≥ 10k body vertices). SI units; y up, fingers towards +z.
#pragma once

#include <string>
#include <vector>

#include "problems/hand_body.h"
#include "problems/negative_image.h"
#include "problems/scenario.h"
#include "problems/scenario_parts.h"

namespace ergo {

struct MouseShape {
  // Two non-concentric balls: the rear hump under the palm, the lower front under the
  // fingers (0.116 m long, 0.072 m wide and tall as given; the desk is not modelled).
  Ball rear{Eigen::Vector3d(0, 0, -0.022), 0.036};
  Ball front{Eigen::Vector3d(0, -0.004, 0.028), 0.030};
  double edge_length = 0.004;  // target edge of the remeshed union, m
  int taubin_iterations = 5;   // λ = 0.5, μ = −0.53 (paper: "a few iterations")
};

// The neutral mouse surface: union of the two balls (icospheres finer than the edge length),
// isotropic remeshing to the edge length, Taubin smoothing. Closed, outward.
TriMesh MakeTwoBallMouse(const MouseShape& shape);

struct MouseScenarioOptions {
  std::string preset = "quick";
  HandOptions hand;                 // dimensions, depths, moduli, mass, pose clearance
  double body_edge_length = 0.007;  // target tet edge of the hand, m
  double sliver_bound_degrees = 10;
  MouseShape mouse;
  // Vertices above this height are designed: the upper part, above the lower ball centre's
  // level (what the hand can reach from above), m.
  double designed_above_y = -0.004;
  double start_gap = 5e-4;  // m
  bool negative_image = false;
  NegativeImageOptions negative{0.005, 0, 3, 0.004, 10, 0.5, 5e-4};
  std::string lock = "tx,tz,rx,ry,rz";  // vertical translation only
  // Contact stiffness κ, Pa/m (mesh-independent), calibrated for 0.3 mm max penetration on
  // the quick preset.
  double contact_stiffness = 7.8e7;
  double free_fall_mass_scale = 1e4;  // paper: 1e4 mouse
  // Filtered normal displacements, filter radius from the skin; the pressure smoothing has a
  // physical radius (9 mm: √3 × the quick preset's skin edge near the design), the same at
  // every resolution so that scores compare across meshes and presets.
  DesignSpaceOptions design_space{DesignParameterization::kFiltered, 0, 0.009};
  UserBodyInput user_body;
  UserSupportInput user_support;

  // "quick" or "paper"; throws InputError for anything else.
  static MouseScenarioOptions FromPreset(const std::string& preset);
};

Scenario MakeMouseScenario(const MouseScenarioOptions& options,
                           ScenarioBuildReport* report = nullptr);

}  // namespace ergo
