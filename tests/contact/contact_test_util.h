// Shared helpers of the contact tests: random triangles with query points placed on purpose
// in each of the 7 Voronoi regions, a bevelled box, and brute-force references (closest
// point over all triangles, inside test by the generalized winding number).
#pragma once

#include <array>
#include <random>

#include <Eigen/Core>

#include "ergo/contact/closest_feature.h"
#include "ergo/contact/feature.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo::contact_testing {

using Triangle = std::array<Eigen::Vector3d, 3>;

// A region of one triangle: type and local index (vertex i, or edge i = (x_i, x_{i+1})).
struct Region {
  FeatureType type;
  int index;
};

// The 7 regions: vertex 0..2, edge 0..2, face.
std::array<Region, 7> AllRegions();

// "vertex 1", "edge 2", "face".
std::string RegionName(const Region& region);

// A random triangle of size ~scale around a random centre within 10·scale of the origin,
// all angles in [20°, 120°] so that every region has a comfortable margin.
Triangle RandomTriangle(std::mt19937& rng, double scale);

// A point whose closest feature on `triangle` is `region`, at least ~0.1·scale away from
// the region's boundaries, and on the negative side of the triangle's plane (inside a
// support whose outward normal the triangle's is).
Eigen::Vector3d PointInRegion(std::mt19937& rng, const Triangle& triangle, const Region& region,
                              double scale);

// Support vertices of `region` in Feature order (edge i: x_i, x_{i+1}; face: x0, x1, x2),
// with their offsets (in 3-blocks) in the 12-vector (p, x0, x1, x2).
int RegionVertexBlocks(const Region& region, std::array<int, 3>* blocks);

// A box of half extents `half` centred at the origin with every edge and corner bevelled by
// `bevel` (26 planar faces: 6 sides, 12 edge strips, 8 corner triangles), triangulated,
// then `subdivisions` times midpoint-subdivided (coplanar neighbours everywhere). Closed,
// outward-oriented.
TriMesh MakeBevelledBox(const Eigen::Vector3d& half, double bevel, int subdivisions);

// Brute-force closest point over all triangles: the lexicographic minimum of
// (squared distance, triangle id) using ClosestPointOnTriangle.
struct BruteForceClosest {
  TriangleProjection projection;
  int triangle = -1;
};
BruteForceClosest BruteForceClosestPoint(const TriMesh& mesh, const Eigen::Vector3d& p);

// Generalized winding number of a closed mesh around p (1 inside, 0 outside).
double WindingNumber(const TriMesh& mesh, const Eigen::Vector3d& p);

}  // namespace ergo::contact_testing
