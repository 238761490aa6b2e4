// The soft support's tet mesh from its surface (ergo/body/support_solid.h): a box meshed by
// Mesh_3 fills the box (volume within 3 %: the edges are rounded at a tenth of the edge
// length), its boundary stays within that distance of the input surface, its base is the
// bottom face, it grades from the top's edge length to the base's, and it makes a part.
#include "ergo/body/support_solid.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "ergo/body/elastic_part.h"
#include "ergo/body/surface_distance.h"
#include "ergo/body/tissue_material.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/primitives.h"
#include "ergo/mesh/tet_boundary.h"

namespace ergo {
namespace {

TEST(SupportSolid, ABoxBecomesAFilledTetMeshHeldAtItsBottom) {
  const Eigen::Vector3d lo(-0.1, -0.05, -0.08), hi(0.1, 0, 0.08);
  const TriMesh box = MakeBox(lo, hi, Eigen::Vector3i(10, 3, 8));
  SupportSolidOptions options;
  options.top_edge_length = 0.01;
  options.base_edge_length = 0.025;
  const SupportSolid solid = MeshSupportSolid(box, options, "box.stl");
  double volume = 0;
  for (Eigen::Index t = 0; t < solid.mesh.tets.rows(); ++t) {
    const double v = TetVolume(solid.mesh, t);
    ASSERT_GT(v, 0) << "tet " << t;
    volume += v;
  }
  const double box_volume = (hi - lo).prod();
  EXPECT_NEAR(volume, box_volume, 0.03 * box_volume);
  // Every boundary vertex is on the box's surface to Mesh_3's facet distance (1 mm here).
  const TetBoundary boundary = ExtractBoundary(solid.mesh);
  const SurfaceDistance distance(box);
  double farthest = 0;
  for (Eigen::Index v = 0; v < boundary.surface.vertices.rows(); ++v)
    farthest =
        std::max(farthest, distance.Nearest(boundary.surface.vertices.row(v).transpose()).distance);
  EXPECT_LT(farthest, 1e-3);
  // The base: bottom vertices only, and enough of them to cover the bottom face.
  int held = 0;
  for (Eigen::Index v = 0; v < solid.mesh.vertices.rows(); ++v) {
    if (!solid.base[v]) continue;
    ++held;
    EXPECT_NEAR(solid.mesh.vertices(v, 1), lo.y(), 1e-5);
  }
  EXPECT_GE(held, 20);
  // Graded: the boundary's edges are shorter at the top than at the bottom.
  double top_sum = 0, bottom_sum = 0;
  int top_count = 0, bottom_count = 0;
  for (Eigen::Index f = 0; f < boundary.surface.triangles.rows(); ++f) {
    const Eigen::Vector3d a = boundary.surface.vertices.row(boundary.surface.triangles(f, 0));
    const Eigen::Vector3d b = boundary.surface.vertices.row(boundary.surface.triangles(f, 1));
    const double y = 0.5 * (a.y() + b.y());
    if (y > hi.y() - 1e-4) top_sum += (a - b).norm(), ++top_count;
    if (y < lo.y() + 1e-4) bottom_sum += (a - b).norm(), ++bottom_count;
  }
  ASSERT_GT(top_count, 0);
  ASSERT_GT(bottom_count, 0);
  EXPECT_LT(top_sum / top_count, 0.75 * bottom_sum / bottom_count);
  // It makes a soft part.
  const ElasticPart part = ElasticPart::Create(
      solid.mesh, solid.base, UniformMaterial(solid.mesh.tets.rows(), 5e4, 0.3), {}, "box.stl");
  EXPECT_GT(part.free_vertices().size(), 0);
}

TEST(SupportSolid, RefusesEdgeLengthsThatCannotWork) {
  const TriMesh box = MakeBox({0, 0, 0}, {0.1, 0.1, 0.1}, {2, 2, 2});
  SupportSolidOptions options;
  options.top_edge_length = 0.02;
  options.base_edge_length = 0.01;  // finer at the base than at the top
  EXPECT_THROW(MeshSupportSolid(box, options, "box.stl"), InputError);
  options.top_edge_length = 1e-4;
  options.base_edge_length = 1e-4;
  try {
    MeshSupportSolid(box, options, "box.stl");
    FAIL() << "accepted a mesh of billions of tets";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "box.stl");
    EXPECT_NE(std::string(error.what()).find("million tets"), std::string::npos);
  }
  // A 2 mm sheet meshed with 5–10 cm edges: no tet fits; refused before Mesh_3, saying how
  // tall it is (Mesh_3 left a few flat tets on a base it could not hold).
  const TriMesh sheet = MakeBox({0, 0, 0}, {0.2, 0.002, 0.2}, {4, 1, 4});
  options.top_edge_length = 0.05;
  options.base_edge_length = 0.1;
  try {
    const SupportSolid solid = MeshSupportSolid(sheet, options, "sheet.stl");
    FAIL() << "meshed a 2 mm sheet with 5 cm edges into " << solid.mesh.tets.rows() << " tets";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("2 mm tall"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace ergo
