// A scenario's support made foam (problems/soft_support_scenario.h): the designed region of a
// box's top carries over to the remeshed boundary — every designed boundary vertex on the top,
// and the top's vertices away from its rim designed — and the scenario then poses a problem
// whose design moves the foam's rest shape.
#include "problems/soft_support_scenario.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "ergo/body/support_solid.h"
#include "ergo/body/tissue_material.h"
#include "ergo/mesh/primitives.h"
#include "problems/shoe_scenario.h"

namespace ergo {
namespace {

TEST(Problems, ABoxTopsDesignedRegionCarriesOverToItsFoamBoundary) {
  const Eigen::Vector3d lo(-0.1, -0.05, -0.08), hi(0.1, 0, 0.08);
  const TriMesh box = MakeBox(lo, hi, Eigen::Vector3i(10, 3, 8));
  std::vector<bool> active(static_cast<size_t>(box.vertices.rows()));
  for (Eigen::Index v = 0; v < box.vertices.rows(); ++v)
    active[v] = box.vertices(v, 1) > -1e-9;  // the top face, rim included
  SupportSolidOptions options;
  options.top_edge_length = 0.01;
  options.base_edge_length = 0.025;
  const SupportSolid solid = MeshSupportSolid(box, options, "box");
  const ElasticPart part = ElasticPart::Create(
      solid.mesh, solid.base, UniformMaterial(solid.mesh.tets.rows(), 5e4, 0.3), {}, "box");
  const TriMesh& boundary = part.boundary().surface;
  const std::vector<bool> moved = TransferActiveVertices(box, active, boundary);
  ASSERT_EQ(moved.size(), static_cast<size_t>(boundary.vertices.rows()));
  int designed = 0, inner_top = 0, inner_top_designed = 0;
  for (Eigen::Index v = 0; v < boundary.vertices.rows(); ++v) {
    const Eigen::Vector3d p = boundary.vertices.row(v);
    if (moved[v]) {
      ++designed;
      EXPECT_GT(p.y(), -0.011) << "a designed vertex off the top's rim band at " << p.transpose();
    }
    if (p.y() > -1e-3 && std::abs(p.x()) < 0.09 && std::abs(p.z()) < 0.07) {
      ++inner_top;
      inner_top_designed += moved[v] ? 1 : 0;
    }
  }
  EXPECT_GT(designed, 50);
  EXPECT_EQ(inner_top_designed, inner_top);
  EXPECT_TRUE(TransferActiveVertices(box, {}, boundary).empty());
}

// The quick shoe's sole (a 2 cm slab whose gridded top is designed and whose base is four
// corners) becomes foam at 5 mm edges: its surface vertices, all on a few planes, once seeded
// a Mesh_3 refinement that kept no tet ("Mesh_3 produced no tets" at every edge length). The
// solid fills the sole's volume and its base is held.
TEST(Problems, TheQuickShoesSoleBecomesFoam) {
  const Scenario shoe = MakeShoeScenario(ShoeScenarioOptions::FromPreset("quick"));
  const Eigen::Vector3d lo = shoe.support.vertices.colwise().minCoeff();
  const Eigen::Vector3d hi = shoe.support.vertices.colwise().maxCoeff();
  SupportSolidOptions options;
  options.top_edge_length = 0.005;
  options.base_edge_length = 0.008;
  const SupportSolid solid = MeshSupportSolid(shoe.support, options, "shoe sole");
  ASSERT_GT(solid.mesh.tets.rows(), 0);
  double volume = 0;
  for (Eigen::Index t = 0; t < solid.mesh.tets.rows(); ++t) volume += TetVolume(solid.mesh, t);
  // Mesh_3 rounds the slab's edges at a tenth of the top's edge (ergo/body/README.md §2b).
  EXPECT_NEAR(volume, (hi - lo).prod(), 0.03 * (hi - lo).prod());
  EXPECT_GT(std::count(solid.base.begin(), solid.base.end(), true), 100);
}

}  // namespace
}  // namespace ergo
