// TriMesh ⇄ CGAL::Surface_mesh (ergo/mesh/cgal_surface_mesh.h): a round trip keeps every
// coordinate and the numbering for both kernels; a triangle that cannot be joined is an
// InputError naming the source, the mesh and the triangle.
#include "ergo/mesh/cgal_surface_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/primitives.h"

namespace ergo {
namespace {

using ExactPredicatesPoint = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using CartesianPoint = CGAL::Simple_cartesian<double>::Point_3;

// Triangle f of `b` is triangle f of `a` with its corners in the same cyclic order.
void ExpectSameTriangles(const Triangles& a, const Triangles& b) {
  ASSERT_EQ(a.rows(), b.rows());
  for (Eigen::Index f = 0; f < a.rows(); ++f) {
    bool same = false;
    for (int shift = 0; shift < 3; ++shift) {
      same = same || (b(f, 0) == a(f, shift) && b(f, 1) == a(f, (shift + 1) % 3) &&
                      b(f, 2) == a(f, (shift + 2) % 3));
    }
    EXPECT_TRUE(same) << "triangle " << f << ": " << a.row(f) << " became " << b.row(f);
  }
}

template <typename Point>
void ExpectRoundTrip(const TriMesh& mesh) {
  const CGAL::Surface_mesh<Point> surface = ToSurfaceMesh<Point>(mesh, "test");
  ASSERT_EQ(static_cast<Eigen::Index>(surface.number_of_vertices()), mesh.vertices.rows());
  ASSERT_EQ(static_cast<Eigen::Index>(surface.number_of_faces()), mesh.triangles.rows());
  // Vertex v is the Surface_mesh's vertex v.
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    const Point& p = surface.point(typename CGAL::Surface_mesh<Point>::Vertex_index(v));
    EXPECT_EQ(p.x(), mesh.vertices(v, 0));
    EXPECT_EQ(p.y(), mesh.vertices(v, 1));
    EXPECT_EQ(p.z(), mesh.vertices(v, 2));
  }
  const TriMesh back = FromSurfaceMesh(surface);
  ASSERT_EQ(back.vertices.rows(), mesh.vertices.rows());
  EXPECT_EQ(back.vertices, mesh.vertices);  // bit for bit
  ExpectSameTriangles(mesh.triangles, back.triangles);
}

TEST(Mesh, SurfaceMeshRoundTripKeepsCoordinatesAndNumbering) {
  TriMesh sphere = MakeIcosphere(0.1, 2);
  sphere.vertices *= 1.0 / 3.0;  // coordinates that need every bit
  ExpectRoundTrip<ExactPredicatesPoint>(sphere);
  ExpectRoundTrip<CartesianPoint>(sphere);
  ExpectRoundTrip<ExactPredicatesPoint>(MakeBox({0, 0, 0}, {1, 2, 3}, {2, 3, 1}));
  ExpectRoundTrip<ExactPredicatesPoint>(TriMesh{});  // empty
}

TEST(Mesh, SurfaceMeshRemovedVerticesAreSkippedAndTheRestRenumbered) {
  TriMesh mesh = MakeIcosphere(1, 0);
  const Eigen::Index n = mesh.vertices.rows();
  // An unused vertex at the start: removing it shifts every index down by one.
  Vertices vertices(n + 1, 3);
  vertices.row(0) << 5, 5, 5;
  vertices.bottomRows(n) = mesh.vertices;
  TriMesh padded{vertices, (mesh.triangles.array() + 1).matrix()};
  CGAL::Surface_mesh<ExactPredicatesPoint> surface =
      ToSurfaceMesh<ExactPredicatesPoint>(padded, "test");
  surface.remove_vertex(CGAL::Surface_mesh<ExactPredicatesPoint>::Vertex_index(0));
  const TriMesh back = FromSurfaceMesh(surface);
  ASSERT_EQ(back.vertices.rows(), mesh.vertices.rows());
  EXPECT_EQ(back.vertices, mesh.vertices);
  ExpectSameTriangles(mesh.triangles, back.triangles);
}

TEST(Mesh, SurfaceMeshNonManifoldTriangleNamesSourceMeshAndTriangle) {
  // Three triangles on one edge (0, 1): the third cannot be joined.
  TriMesh fan;
  fan.vertices.resize(5, 3);
  fan.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1;
  fan.triangles.resize(3, 3);
  fan.triangles << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  try {
    ToSurfaceMesh<ExactPredicatesPoint>(fan, "fan.obj", "second operand");
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "fan.obj");
    EXPECT_EQ(error.location(), "second operand triangle 2");
    EXPECT_NE(error.problem().find("cannot be joined"), std::string::npos) << error.what();
    EXPECT_NE(error.fix().find("ergo_mesh check"), std::string::npos) << error.what();
  }
  try {
    ToSurfaceMesh<CartesianPoint>(fan, "fan.obj");
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "triangle 2");
  }
}

TEST(Mesh, SurfaceMeshVertexIndexOutOfRangeIsAProgrammingError) {
  TriMesh mesh = MakeIcosphere(1, 0);
  mesh.triangles(3, 1) = static_cast<int>(mesh.vertices.rows());
  EXPECT_DEATH(ToSurfaceMesh<ExactPredicatesPoint>(mesh, "bad"), "out of range");
}

}  // namespace
}  // namespace ergo
