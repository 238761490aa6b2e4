// A generated body part (paper §3.1, with smooth implicit shapes standing in for scans): the
// skin is a BlendedShape, the core is the skin pushed inward by a depth field
// (f_core = f_out + depth, exact because the primitives are true signed distances), the
// tissue's Young's modulus is a field over space, and the core mass makes up a stated total
// mass. Meshed by the body builder (CGAL Mesh_3). SI units: m, Pa, kg.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "ergo/body/layer_builder.h"
#include "ergo/body/layered_body.h"
#include "problems/implicit_shapes.h"

namespace ergo {

// A field over space given the point and the shape's region weights there.
using RegionField = std::function<double(const Eigen::Vector3d& p, const double* weights)>;

struct ImplicitBodySpec {
  std::string name;       // for messages, e.g. "seated body"
  BlendedShape shape;     // the skin
  RegionField depth;      // tissue depth below the skin, m (> 0)
  RegionField stiffness;  // Young's modulus, Pa, evaluated at each tet's centroid
  double poisson_ratio = 0.45;
  double tissue_density = 1050;  // kg/m³
  // Total mass of the part, kg: the core mass is this minus the tissue mass (the core's
  // centre of mass is its volume centroid). Negative: core volume × tissue_density.
  double total_mass = -1;
};

// How well the meshed layer follows the requested depth: per skin vertex the distance to the
// core surface (measured on the mesh) against depth(vertex).
// (Where the depth exceeds the local half-thickness — the foot's toes — there is no core
// beneath and the achieved depth is the distance to the nearest core elsewhere.)
struct DepthAgreement {
  double mean_requested = 0, mean_achieved = 0;  // m
  double median_relative_error = 0;              // of |achieved − requested| / requested
  double within_20_percent = 0;                  // fraction of skin vertices within 20 %
};

struct GeneratedBody {
  std::shared_ptr<LayeredBody> body;
  LayerBuildReport report;  // counts, volume, thickness, tet quality, times
  DepthAgreement depth;
  double tissue_mass = 0, core_mass = 0;  // kg
  double youngs_min = 0, youngs_max = 0;  // Pa, over tets
  double build_seconds = 0;               // wall, meshing and body creation
};

// Meshes the layer with `builder` (edge length etc.) and creates the body with the load and
// lock of `load` (its masses and densities are replaced by the spec's). Throws InputError
// naming spec.name when the layer cannot be meshed or the total mass is below the tissue's.
GeneratedBody BuildImplicitBody(const ImplicitBodySpec& spec, const BuilderOptions& builder,
                                const LayeredBodyOptions& load);

// One line: vertices, tets, mass split, thickness, depth agreement, quality, time.
std::string DescribeGeneratedBody(const GeneratedBody& generated);

}  // namespace ergo
