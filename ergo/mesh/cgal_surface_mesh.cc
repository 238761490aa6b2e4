// CGAL translation unit: the TriMesh ⇄ Surface_mesh conversions, instantiated for the
// kernels ergo's CGAL code uses.
#include "ergo/mesh/cgal_surface_mesh.h"

#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <glog/logging.h>

#include "ergo/mesh/input_error.h"

namespace ergo {

template <typename Point>
CGAL::Surface_mesh<Point> ToSurfaceMesh(const TriMesh& mesh, const std::string& source,
                                        const std::string& which) {
  using Mesh = CGAL::Surface_mesh<Point>;
  if (mesh.triangles.size() > 0) {
    CHECK_GE(mesh.triangles.minCoeff(), 0) << source << ": negative vertex index";
    CHECK_LT(mesh.triangles.maxCoeff(), mesh.vertices.rows())
        << source << ": vertex index out of range";
  }
  Mesh surface;
  std::vector<typename Mesh::Vertex_index> vertices;
  vertices.reserve(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    vertices.push_back(
        surface.add_vertex(Point(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2))));
  }
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const typename Mesh::Face_index face =
        surface.add_face(vertices[mesh.triangles(f, 0)], vertices[mesh.triangles(f, 1)],
                         vertices[mesh.triangles(f, 2)]);
    if (face == Mesh::null_face()) {
      throw InputError(source, (which.empty() ? "" : which + " ") + "triangle " + std::to_string(f),
                       "the triangle cannot be joined to its neighbours (non-manifold edge or "
                       "vertex, or orientation opposite to a neighbour)",
                       "run `ergo_mesh check` on the file and repair what it reports");
    }
    CHECK_EQ(static_cast<Eigen::Index>(face.idx()), f);
  }
  return surface;
}

template <typename Point>
TriMesh FromSurfaceMesh(const CGAL::Surface_mesh<Point>& surface) {
  using Mesh = CGAL::Surface_mesh<Point>;
  TriMesh mesh;
  std::vector<int> index(surface.number_of_vertices() + surface.number_of_removed_vertices(), -1);
  mesh.vertices.resize(static_cast<Eigen::Index>(surface.number_of_vertices()), 3);
  int next = 0;
  for (typename Mesh::Vertex_index v : surface.vertices()) {
    const Point& p = surface.point(v);
    mesh.vertices.row(next) << p.x(), p.y(), p.z();
    index[v.idx()] = next++;
  }
  mesh.triangles.resize(static_cast<Eigen::Index>(surface.number_of_faces()), 3);
  int row = 0;
  for (typename Mesh::Face_index f : surface.faces()) {
    int k = 0;
    for (typename Mesh::Vertex_index v : CGAL::vertices_around_face(surface.halfedge(f), surface)) {
      CHECK_LT(k, 3) << "non-triangular face";
      mesh.triangles(row, k++) = index[v.idx()];
    }
    CHECK_EQ(k, 3) << "non-triangular face";
    ++row;
  }
  return mesh;
}

using ExactPredicatesPoint = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using CartesianPoint = CGAL::Simple_cartesian<double>::Point_3;

template CGAL::Surface_mesh<ExactPredicatesPoint> ToSurfaceMesh<ExactPredicatesPoint>(
    const TriMesh&, const std::string&, const std::string&);
template TriMesh FromSurfaceMesh<ExactPredicatesPoint>(
    const CGAL::Surface_mesh<ExactPredicatesPoint>&);
template CGAL::Surface_mesh<CartesianPoint> ToSurfaceMesh<CartesianPoint>(const TriMesh&,
                                                                          const std::string&,
                                                                          const std::string&);
template TriMesh FromSurfaceMesh<CartesianPoint>(const CGAL::Surface_mesh<CartesianPoint>&);

}  // namespace ergo
