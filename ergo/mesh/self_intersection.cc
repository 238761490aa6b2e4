#include "ergo/mesh/self_intersection.h"

#include <array>
#include <exception>
#include <iterator>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

namespace ergo {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Face = SurfaceMesh::Face_index;

}  // namespace

SelfIntersections FindSelfIntersections(const TriMesh& mesh, int max_pairs) {
  namespace pmp = CGAL::Polygon_mesh_processing;
  SelfIntersections result;
  std::vector<Point> points;
  points.reserve(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    points.emplace_back(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));
  }
  // The soup CGAL sees: triangles without a repeated corner, with their mesh indices.
  std::vector<std::array<size_t, 3>> soup;
  std::vector<int> soup_to_mesh;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const int a = mesh.triangles(f, 0), b = mesh.triangles(f, 1), c = mesh.triangles(f, 2);
    if (a == b || b == c || a == c) continue;
    soup.push_back({static_cast<size_t>(a), static_cast<size_t>(b), static_cast<size_t>(c)});
    soup_to_mesh.push_back(static_cast<int>(f));
  }
  try {
    // Orientation does not change which triangles intersect; CGAL needs it consistent.
    if (!pmp::orient_polygon_soup(points, soup)) {
      result.skipped_because =
          "the surface is not a manifold (CGAL would have to split vertices to orient it)";
      return result;
    }
    SurfaceMesh surface;
    std::vector<SurfaceMesh::Vertex_index> vertices;
    vertices.reserve(points.size());
    for (const Point& p : points) vertices.push_back(surface.add_vertex(p));
    std::vector<SurfaceMesh::Vertex_index> corners(3);
    for (const auto& triangle : soup) {
      for (int k = 0; k < 3; ++k) corners[k] = vertices[triangle[k]];
      if (CGAL::Euler::add_face(corners, surface) == SurfaceMesh::null_face()) {
        result.skipped_because = "the surface is not a manifold (CGAL could not build it)";
        return result;
      }
    }
    std::vector<std::pair<Face, Face>> pairs;
    // One extra pair tells whether the limit was reached.
    pmp::self_intersections<CGAL::Sequential_tag>(
        faces(surface), surface, std::back_inserter(pairs),
        CGAL::parameters::maximum_number(static_cast<unsigned>(max_pairs) + 1));
    result.checked = true;
    for (const auto& [f, g] : pairs) {
      if (f == g) continue;  // a collinear triangle: reported as degenerate by the caller
      if (static_cast<int>(result.pairs.size()) == max_pairs) {
        result.stopped_at_limit = true;
        break;
      }
      int first = soup_to_mesh[static_cast<size_t>(f.idx())];
      int second = soup_to_mesh[static_cast<size_t>(g.idx())];
      if (first > second) std::swap(first, second);
      result.pairs.emplace_back(first, second);
    }
  } catch (const std::exception& error) {
    result.checked = false;
    result.skipped_because = std::string("CGAL failed: ") + error.what();
    result.pairs.clear();
  }
  return result;
}

}  // namespace ergo
