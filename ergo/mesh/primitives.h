// Closed primitive meshes used by scenarios, tests and benchmarks: an icosphere, a
// subdivided box, a torus, and a structured tetrahedral grid. All outward-oriented
// (surfaces) or positively oriented (tets), coordinates in metres.
#pragma once

#include <functional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// Icosahedron refined `subdivisions` times and projected onto the sphere:
// 10·4^s + 2 vertices, 20·4^s triangles.
TriMesh MakeIcosphere(double radius, int subdivisions,
                      const Eigen::Vector3d& centre = Eigen::Vector3d::Zero());

// Surface of the axis-aligned box [lo, hi], each face split into a grid of
// cells(axis) x cells(other axis) squares, two triangles each.
TriMesh MakeBox(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const Eigen::Vector3i& cells);

// A box [lo, hi] (cells as in MakeBox) whose top face y = hi.y is raised by
// height(x, z) (metres, may be negative but must keep the top above lo.y); the side walls
// are stretched vertically to follow. For supports: bumps, bowls, troughs.
TriMesh MakeHeightfieldBlock(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                             const Eigen::Vector3i& cells,
                             const std::function<double(double, double)>& height);

// Torus around the z axis: tube radius `minor` swept on a circle of radius `major`.
TriMesh MakeTorus(double major, double minor, int major_segments, int minor_segments);

// The box [lo, hi] split into cells(0) x cells(1) x cells(2) cubes, each cut into six
// tetrahedra along its main diagonal (Kuhn triangulation, conforming across cells).
TetMesh MakeTetGrid(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                    const Eigen::Vector3i& cells);

// The same on a rectilinear grid with the given (strictly increasing) lines per axis:
// graded meshes, fine where contact happens and coarse away from it.
TetMesh MakeRectilinearTetGrid(const std::vector<double>& xs, const std::vector<double>& ys,
                               const std::vector<double>& zs);

}  // namespace ergo
