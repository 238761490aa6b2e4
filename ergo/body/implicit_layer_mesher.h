// The Mesh_3 step of the body builder (paper §3.1: the tissue layer between the skin and
// the core is tetrahedralised): Delaunay refinement of the region labelled "layer" by a
// region function, with sliver exudation. Plain Eigen in and out; CGAL Mesh_3 stays inside
// implicit_layer_mesher.cc (one slow-to-compile translation unit). Metres.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// Which part of space a point is in. Only kLayer is meshed; the skin is the interface
// kOutside|kLayer and the core surface the interface kLayer|kCore.
enum LayerRegion : int { kOutsideRegion = 0, kLayerRegion = 1, kCoreRegion = 2 };

using RegionFunction = std::function<int(const Eigen::Vector3d&)>;

// A point known to lie on the skin or on the core surface, to start the refinement on
// every part of both surfaces.
struct SurfaceSeed {
  Eigen::Vector3d point;
  bool on_core = false;
};

// Mesh_3 criteria (CGAL names; sizes in metres). See layer_builder.h for how they follow
// from one target edge length.
struct LayerMesherCriteria {
  double facet_angle_degrees = 25;    // lower bound on surface triangle angles
  double facet_size = 0;              // radius bound of surface Delaunay balls (> 0)
  double facet_distance = 0;          // bound on facet-centre-to-surface distance (> 0)
  double cell_radius_edge_ratio = 2;  // circumradius / shortest edge
  double cell_size = 0;               // circumradius bound of tets (> 0)
  // Optional space-varying scale of facet_size and cell_size (1 = as given): local mesh
  // refinement, e.g. under a contact. Must be positive wherever it is evaluated.
  std::function<double(const Eigen::Vector3d&)> size_scale;
  // Surface points are found by bisection to this fraction of the bounding sphere radius.
  double relative_error_bound = 1e-5;
  bool perturb = true;  // sliver perturbation (moves vertices, surface ones along the surface)
  bool exude = true;    // sliver exudation (changes weights only)
  // Both stop once every dihedral angle is above this (degrees); 0 = improve the worst
  // tets as long as they can.
  double sliver_bound_degrees = 0;
  double time_limit = 0;  // seconds for each of perturb and exude; 0 = none (reproducible)
  unsigned seed = 0;      // for CGAL's random choices (reproducible meshes)
};

struct LayerMesherResult {
  TetMesh mesh;  // the layer's cells, compact vertices, positively oriented
  // Per vertex: bit 1 = on a skin facet, bit 2 = on a core facet (as Mesh_3 classified the
  // restricted facets), 0 = interior.
  std::vector<uint8_t> surface_flags;
  int initial_points = 0;  // seeds used to start the refinement
  double refine_seconds = 0, perturb_seconds = 0, exude_seconds = 0;
};

// Meshes {p in bounds : region(p) == kLayerRegion}. `region` is called from one thread.
// Seeds should be listed so that every prefix of each surface's seeds is well spread
// (farthest-point order): refinement starts from the first 16 of each, or 64, 256, ...
// until one Voronoi vertex of them lies in the layer (else it cannot start); with none
// that works, CGAL's random initial points are tried.
LayerMesherResult MeshImplicitLayer(const RegionFunction& region, const Eigen::AlignedBox3d& bounds,
                                    const std::vector<SurfaceSeed>& seeds,
                                    const LayerMesherCriteria& criteria);

}  // namespace ergo
