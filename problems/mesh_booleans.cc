#include "problems/mesh_booleans.h"

#include <exception>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <glog/logging.h>

#include "ergo/mesh/cgal_surface_mesh.h"
#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using FaceIndex = SurfaceMesh::Face_index;
using EdgeIndex = SurfaceMesh::Edge_index;
namespace pmp = CGAL::Polygon_mesh_processing;

void RequireVolume(const SurfaceMesh& surface, const std::string& source, const char* which) {
  if (!CGAL::is_closed(surface)) {
    throw InputError(source, which, "the surface is open, so it bounds no volume",
                     "close the surface (it must be watertight)");
  }
  if (pmp::does_self_intersect(surface)) {
    throw InputError(source, which, "the surface intersects itself",
                     "repair the self-intersections first");
  }
  if (!pmp::does_bound_a_volume(surface)) {
    throw InputError(source, which, "the surface does not bound a volume (orientation or nesting)",
                     "orient the surface outward");
  }
}

enum class Operation { kUnion, kDifference };

BooleanResult Boolean(const TriMesh& a, const TriMesh& b, Operation operation,
                      const std::string& source) {
  SurfaceMesh first = ToSurfaceMesh<Point>(a, source, "first operand");
  SurfaceMesh second = ToSurfaceMesh<Point>(b, source, "second operand");
  RequireVolume(first, source, "first operand");
  RequireVolume(second, source, "second operand");
  SurfaceMesh out;
  auto constrained = out.add_property_map<EdgeIndex, bool>("e:cut", false).first;
  bool manifold = false;
  try {
    const auto np_out = CGAL::parameters::edge_is_constrained_map(constrained);
    manifold = operation == Operation::kUnion
                   ? pmp::corefine_and_compute_union(first, second, out,
                                                     CGAL::parameters::default_values(),
                                                     CGAL::parameters::default_values(), np_out)
                   : pmp::corefine_and_compute_difference(
                         first, second, out, CGAL::parameters::default_values(),
                         CGAL::parameters::default_values(), np_out);
  } catch (const std::exception& error) {
    throw InputError(source, "", std::string("CGAL corefinement failed: ") + error.what(),
                     "move one operand slightly (coincident features) and retry");
  }
  if (!manifold) {
    throw InputError(source, "",
                     "the Boolean result is not a manifold surface (the operands touch along an "
                     "edge or at a point)",
                     "move one operand slightly so the surfaces cross cleanly");
  }
  BooleanResult result;
  for (EdgeIndex e : out.edges()) {
    if (!constrained[e]) continue;
    const Point& p = out.point(out.vertex(e, 0));
    const Point& q = out.point(out.vertex(e, 1));
    result.cut.emplace_back(Eigen::Vector3d(p.x(), p.y(), p.z()),
                            Eigen::Vector3d(q.x(), q.y(), q.z()));
  }
  result.mesh = FromSurfaceMesh(out);
  return result;
}

}  // namespace

BooleanResult MeshUnion(const TriMesh& a, const TriMesh& b, const std::string& source) {
  return Boolean(a, b, Operation::kUnion, source);
}

BooleanResult MeshDifference(const TriMesh& a, const TriMesh& b, const std::string& source) {
  return Boolean(a, b, Operation::kDifference, source);
}

TriMesh RemeshIsotropic(const TriMesh& mesh, const std::vector<bool>& faces,
                        double target_edge_length, int iterations) {
  CHECK_GT(target_edge_length, 0.0);
  CHECK_GE(iterations, 1);
  CHECK(faces.empty() || faces.size() == static_cast<size_t>(mesh.triangles.rows()));
  SurfaceMesh surface = ToSurfaceMesh<Point>(mesh, "remeshing", "input");
  std::vector<FaceIndex> selected;
  for (FaceIndex f : surface.faces())
    if (faces.empty() || faces[f.idx()]) selected.push_back(f);
  pmp::isotropic_remeshing(selected, target_edge_length, surface,
                           CGAL::parameters::number_of_iterations(iterations));
  surface.collect_garbage();
  return FromSurfaceMesh(surface);
}

}  // namespace ergo
