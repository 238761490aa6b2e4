// CGAL translation unit: Polygon Mesh Processing hole filling and self-intersection test.
#include "ergo/body/hole_filling.h"

#include <cmath>
#include <iterator>
#include <sstream>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <glog/logging.h>
#include <Eigen/Dense>

#include "ergo/mesh/cgal_surface_mesh.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

Eigen::Vector3d ToEigen(const Point& p) { return {p.x(), p.y(), p.z()}; }

// Largest distance of the points from their least-squares plane, and the loop's extent.
void Planarity(const std::vector<Eigen::Vector3d>& points, double* deviation, double* extent) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : points) scatter += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  const Eigen::Vector3d normal = solver.eigenvectors().col(0);
  *deviation = 0;
  *extent = 0;
  for (const auto& p : points) {
    *deviation = std::max(*deviation, std::abs((p - mean).dot(normal)));
    *extent = std::max(*extent, (p - mean).norm());
  }
}

}  // namespace

CappedSurface CloseWithFlatCaps(const TriMesh& surface, const std::string& source) {
  Mesh mesh = ToSurfaceMesh<Point>(surface, source);

  CappedSurface result;
  std::vector<Mesh::Halfedge_index> loops;
  {
    std::vector<bool> seen(mesh.number_of_halfedges(), false);
    for (Mesh::Halfedge_index h : mesh.halfedges()) {
      if (!mesh.is_border(h) || seen[h.idx()]) continue;
      loops.push_back(h);
      for (Mesh::Halfedge_index g : CGAL::halfedges_around_face(h, mesh)) seen[g.idx()] = true;
    }
  }
  for (Mesh::Halfedge_index h : loops) {
    std::vector<Eigen::Vector3d> points;
    for (Mesh::Halfedge_index g : CGAL::halfedges_around_face(h, mesh))
      points.push_back(ToEigen(mesh.point(mesh.target(g))));
    double deviation = 0, extent = 0;
    Planarity(points, &deviation, &extent);
    std::vector<Mesh::Face_index> patch;
    PMP::triangulate_hole(mesh, h, std::back_inserter(patch),
                          CGAL::parameters::use_2d_constrained_delaunay_triangulation(true));
    if (patch.empty()) {
      std::ostringstream where;
      where << "near (" << points[0].transpose() << ") m";
      throw InputError(source, where.str(),
                       "an open boundary of " + std::to_string(points.size()) +
                           " edges could not be closed by a cap",
                       "close the scan yourself (e.g. a planar cut and fill in MeshLab)");
    }
    ++result.holes_capped;
    result.cap_triangles += static_cast<int>(patch.size());
    std::ostringstream note;
    note.precision(3);
    note << "closed an open boundary of " << points.size() << " edges (" << 2 * extent
         << " m across";
    if (deviation > 1e-3 * extent) note << ", up to " << deviation << " m off its plane";
    note << ") with a flat cap of " << patch.size() << " triangles";
    result.notes.push_back(note.str());
  }
  if (result.holes_capped > 0 && PMP::does_self_intersect(mesh)) {
    throw InputError(source, "",
                     "closing the open boundaries with caps made the surface intersect itself "
                     "(an open boundary is not a clean cut across the body)",
                     "cut the scan with a plane and fill the hole yourself, then retry");
  }
  CHECK(CGAL::is_closed(mesh));

  // Back to a TriMesh: input vertices keep their indices (caps add no vertices).
  CHECK_EQ(static_cast<Eigen::Index>(mesh.number_of_vertices()), surface.vertices.rows());
  result.surface = FromSurfaceMesh(mesh);
  // Outward orientation: the enclosed signed volume must be positive.
  if (EnclosedVolume(result.surface) < 0) {
    result.surface.triangles.col(1).swap(result.surface.triangles.col(2));
    result.notes.push_back("the surface was oriented inward; its faces were reversed");
  }
  return result;
}

}  // namespace ergo
