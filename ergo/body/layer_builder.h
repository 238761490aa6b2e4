// The body builder (paper §3.1): the soft-tissue layer of a body part as a tet mesh whose
// inner-surface vertices are attached to the rigid core. Two inputs: (a) an outer shape and
// a core shape as implicit functions, (b) the user's skin surface (open scans are capped)
// pushed inward by an interpolated depth. Both are meshed by CGAL Mesh_3 with sizes from
// one target edge length. SI units (m). The format and the scheme: ergo/body/README.md.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "ergo/body/implicit_layer_mesher.h"
#include "ergo/body/sample_interpolation.h"
#include "ergo/body/surface_distance.h"
#include "ergo/body/tet_quality.h"
#include "ergo/mesh/json.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// A scalar field over space, negative inside its solid (metres for signed distances).
using ImplicitFunction = std::function<double(const Eigen::Vector3d&)>;

struct BuilderOptions {
  // Target edge length h (m, required > 0). Mesh_3 bounds: facet_size = h/√3 and
  // cell_size = h·√(3/8), the circumradii of an equilateral triangle and a regular tet of
  // edge h, so edges come out at most about h (the report gives the mean).
  double edge_length = 0;
  // Optional local target edge length h(p) ≤ edge_length, m: refines where it matters
  // (e.g. around a contact). The thickness checks still use edge_length.
  std::function<double(const Eigen::Vector3d&)> edge_length_field;
  // Surface input, optional: the core is also cut to {core_limit < 0} (a signed implicit,
  // metres): where the part has no bones (a foot's toes), a clean cut rather than a depth
  // that thins the core to nothing (thin core slivers pinch the mesh).
  ImplicitFunction core_limit;
  double facet_distance = 0;        // m; 0 = edge_length / 10
  double facet_angle_degrees = 25;  // Mesh_3 facet_angle
  double radius_edge_ratio = 2.0;   // Mesh_3 cell_radius_edge_ratio
  // Sliver removal after refinement (measurements in README.md): perturbation moves
  // vertices (surface vertices along their surface), then exudation changes weights only.
  // Both stop once every dihedral angle is above sliver_bound_degrees; 0 = as long as
  // they improve the worst tet (exudation alone then took 10x the refinement time).
  bool perturb = true;
  bool exude = true;
  double sliver_bound_degrees = 15;
  double relative_error_bound = 1e-5;  // surface bisection accuracy / bounding-sphere radius
  unsigned seed = 0;                   // Mesh_3 randomness, for reproducible meshes
  // The layer must be at least this many edge lengths thick everywhere (measured on the
  // mesh; for surface input also checked on the depth before meshing).
  double min_thickness_in_edges = 0.5;
  // Candidate initial points per surface (found on a grid); Mesh_3 starts from as few as
  // will do.
  int max_seeds_per_surface = 1024;
  // Called at the start of each stage (scan, mesh, classify, measure) with a line for
  // people; none when empty.
  std::function<void(const std::string& stage)> progress;
};

// Input (a): the layer is {f_out < 0} minus {f_core < 0}.
struct ImplicitLayer {
  ImplicitFunction outer;      // f_out, < 0 inside the body
  ImplicitFunction core;       // f_core, < 0 inside the core
  Eigen::AlignedBox3d bounds;  // contains the whole body, with some margin
  // Optional: a faster classifier that agrees with outer/core (kOutsideRegion, kLayerRegion,
  // kCoreRegion). When given, the core is trusted to lie inside the outer shape.
  RegionFunction region;
};

struct LayerBuildReport {
  int vertex_count = 0, tet_count = 0, skin_vertex_count = 0, attached_vertex_count = 0;
  int skin_components = 0, core_components = 0;
  double layer_volume = 0;         // m³, sum of tet volumes
  double min_thickness = 0;        // m, min over skin vertices of the distance to the core
  double mean_thickness = 0;       // m
  double max_attached_offset = 0;  // m, max |f_core| / |∇f_core| over attached vertices
  TetQuality quality;
  double edge_length = 0, facet_distance = 0;  // as used, m
  int initial_points = 0;
  double refine_seconds = 0, exude_seconds = 0, perturb_seconds = 0, total_seconds = 0;
  std::vector<std::string> notes;  // caps added, core pieces, ...
};

struct BuiltLayer {
  TetMesh mesh;                  // positively oriented, metres
  std::vector<bool> attached;    // per vertex: on the core surface
  Eigen::VectorXd vertex_depth;  // per vertex: layer depth below its nearest skin point, m
  // The skin used to build (the capped input surface, or the meshed skin for implicit
  // input), for projecting points onto it.
  std::shared_ptr<const SurfaceDistance> skin;
  TriMesh skin_surface;  // the same surface as a mesh
  LayerBuildReport report;
};

// Meshes an implicit layer. Throws InputError (naming `source`) for an empty layer, a core
// that is empty or not inside the outer shape, a core touching the skin, or a layer
// thinner than options.min_thickness_in_edges · edge_length.
BuiltLayer BuildLayerFromImplicit(const ImplicitLayer& layer, const BuilderOptions& options,
                                  const std::string& source = "implicit shape");

// Meshes the layer under a skin surface (metres): checks it (the mesh check; refuses
// non-manifold or self-intersecting input), caps open boundaries (a note says so), and
// takes the core as the points deeper than depth(π(p)) below the skin, π(p) the closest
// skin point. Throws InputError naming `source` for bad surfaces, a depth below
// min_thickness_in_edges · edge_length, or a core that vanishes (depth beyond half the
// body's thickness everywhere).
BuiltLayer BuildLayerFromSurface(const TriMesh& skin, const SampleInterpolant& depth,
                                 const BuilderOptions& options, const std::string& source);

// Per-tet values of `field` taken at the skin point closest to each tet's centroid: a
// measurement on the skin describes the tissue column beneath it (used for E).
Eigen::VectorXd InterpolateOntoTets(const BuiltLayer& layer, const SampleInterpolant& field);

// A multi-line human-readable summary of the report.
std::string DescribeLayerBuild(const LayerBuildReport& report);

// The report's numbers as a JSON object (keys with units: "layer_volume_m3", ...).
Json LayerBuildReportJson(const LayerBuildReport& report);

}  // namespace ergo
