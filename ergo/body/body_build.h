// Building a body part (paper §3.1) from a user's skin surface or an implicit test shape:
// the whole job of `ergo_body build` as a library call, so the tool and the Python
// bindings take the same options (named as the tool's flags) and give the same messages.
// The layer's depth and Young's modulus are constants or interpolated from x,y,z,value
// samples (CSV); the result is the body directory's content (ergo/body/README.md).
//
//   BodyBuildOptions options;
//   options.shape = "sphere_shell";
//   options.outer_radius = 0.05;
//   options.core_radius = 0.03;
//   options.youngs_modulus = 1e4;
//   options.edge_length = 0.01;
//   const BuiltBody built = BuildBody(options);
//   SaveBodyDirectory("ball", built.record);
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "ergo/body/anatomical_priors.h"
#include "ergo/body/body_directory.h"
#include "ergo/mesh/length_unit.h"

namespace ergo {

struct BodyBuildOptions {
  // Exactly one of: a skin surface file (.obj .off .ply .stl .msh; closed, or open where
  // the body is cut flat), or an implicit shape ("sphere_shell", "ellipsoid_shell").
  std::string surface;
  LengthUnit unit = LengthUnit::kMetre;  // of `surface` and of the CSVs' x,y,z and depth
  std::string shape;
  double outer_radius = 0, core_radius = 0;             // sphere_shell, m
  Eigen::Vector3d semi_axes = Eigen::Vector3d::Zero();  // ellipsoid_shell a,b,c, m
  // The layer depth: a constant (m, not scaled by `unit`) or samples x,y,z,depth (CSV).
  std::optional<double> depth;
  std::string depth_samples;
  // Young's modulus: a constant (Pa) or samples x,y,z,E (CSV).
  std::optional<double> youngs_modulus;
  std::string stiffness_samples;
  // Surface input only: anatomical priors for depth and E (anatomical_priors.h; the samples
  // above then replace the priors near them), and the rotation from the scan's axes to
  // ergo's (axis_map.h: "y,z,x" for a scan with z up and its length along x).
  AnatomyOptions anatomy;
  std::string axes = "x,y,z";
  double poisson_ratio = 0.45;
  double density = 1050;                // tissue, kg/m³
  double core_mass = -1;                // kg; negative = core volume × core_density
  double core_density = 1050;           // kg/m³
  double compression_resistance = 1.0;  // dimensionless volume-term weight c (DESIGN §3)
  double inversion_threshold = 0.1;     // principal-stretch clamp of the material
  double edge_length = 0;               // target tet edge, m (required)
  double facet_distance = 0;            // surface approximation bound, m; 0 = edge/10
  int seed = 0;                         // the mesher's random seed (same seed, same mesh)
  // One line per stage (reading, meshing, measuring, ...), elapsed time first.
  std::function<void(const std::string& line)> progress;
};

struct BuiltBody {
  BodyRecord record;   // what SaveBodyDirectory writes
  std::string report;  // the build report for people: counts, quality, mass, modulus
};

// Builds the body. Throws InputError naming the option as the tool's flag ("--depth"),
// or the file and line, with the fix, for anything that cannot make a body.
BuiltBody BuildBody(const BodyBuildOptions& options);

}  // namespace ergo
