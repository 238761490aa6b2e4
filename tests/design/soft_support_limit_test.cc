// A stiff soft support is the rigid one: a cube of soft tissue (E = 10 kPa) resting on a foam
// block of E = 10 MPa, a thousand times stiffer, has the contact area and the score ζ of the
// same cube on the rigid block of the same shape (within 2 %; the area is a sum of skin vertex
// areas, a vertex being about 1 % of it at this 1.1 cm skin), while a block as soft as the
// tissue spreads the contact. Both under two-way contact, a soft support's. The whole chain —
// SolveStaticEquilibrium with a soft support, its pressures from the equilibrium's own springs — is
// the one ergo_simulate runs.
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>

#include "ergo/body/core_lock.h"
#include "ergo/body/elastic_part.h"
#include "ergo/design/static_equilibrium.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

std::shared_ptr<const ElasticPart> FoamBlock(double modulus) {
  const Eigen::Vector3d lo(-0.1, -0.04, -0.1), hi(0.1, 0, 0.1);
  const TetMesh mesh = MakeTetGrid(lo, hi, Eigen::Vector3i(20, 4, 20));
  std::vector<bool> base(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    base[v] = mesh.vertices(v, 1) < lo.y() + 1e-9;
  return std::make_shared<const ElasticPart>(ElasticPart::Create(
      mesh, base, UniformMaterial(mesh.tets.rows(), modulus, 0.3), {}, "foam block"));
}

struct Outcome {
  double area = 0, zeta = 0, sink = 0;
};

Outcome Solve(const LayeredBody& body, std::shared_ptr<const ElasticPart> foam,
              const TriMesh& block) {
  StaticEquilibriumOptions options;
  options.contact_stiffness = 1e8;  // fixed: the same contact law on both supports
  options.two_way_contact = true;   // a soft support's contact is; the rigid reference's too
  options.soft_support = std::move(foam);
  const StaticEquilibrium solved = SolveStaticEquilibrium(body, block, "block", options);
  EXPECT_TRUE(solved.ok()) << solved.message();
  Outcome out;
  const Eigen::VectorXd& areas = body.skin().rest_areas;
  for (Eigen::Index l = 0; l < areas.size(); ++l)
    if (solved.pressures.human.pressure[l] > 0) out.area += areas[l];
  out.zeta = solved.pressures.human.cost + solved.pressures.support.cost;
  out.sink = body.core_centre().y() - solved.result.state.centre.y();
  return out;
}

TEST(SoftSupport, AThousandTimesStifferThanTheTissueItIsRigid) {
  // Three solves of a 2.2k-vertex block with a 4k-tet cube: minutes under ASan, which sees the
  // same code in soft_support_test.cc's smaller scenes.
  if (testing::SanitizedBuild()) GTEST_SKIP() << "Release-only: three soft-support solves";
  LayeredBodyOptions options;
  options.lock = ParseCoreLock("tx,tz");
  options.external_force = Eigen::Vector3d(0, -20, 0);
  const LayeredBody body =
      testing::MakeHollowCubeBody(0.1, 9, 1e4, 0.45, options, Eigen::Vector3d(0, 0.06, 0));
  const auto stiff = FoamBlock(1e7);
  const TriMesh block = stiff->boundary().surface;
  const Outcome rigid = Solve(body, nullptr, block);
  const Outcome foam = Solve(body, stiff, block);
  const Outcome soft = Solve(body, FoamBlock(1e4), block);
  std::printf(
      "[ limit    ] area rigid %.5f m², E=10 MPa %.5f, E=10 kPa %.5f; zeta %.5g, %.5g, "
      "%.5g; core sinks %.3f, %.3f, %.3f mm\n",
      rigid.area, foam.area, soft.area, rigid.zeta, foam.zeta, soft.zeta, rigid.sink * 1e3,
      foam.sink * 1e3, soft.sink * 1e3);
  ASSERT_GT(rigid.area, 0);
  EXPECT_NEAR(foam.area, rigid.area, 0.02 * rigid.area);
  EXPECT_NEAR(foam.zeta, rigid.zeta, 0.02 * rigid.zeta);
  // The soft block is felt: the cube sinks deeper (the 4 cm block under ~2.5 kPa at E = 10 kPa
  // gives way by several millimetres; 10 % of its depth is a floor), on a larger contact, at
  // lower pressures.
  EXPECT_GT(soft.sink, rigid.sink + 0.004);
  EXPECT_GT(soft.area, rigid.area);
  EXPECT_LT(soft.zeta, rigid.zeta);
}

}  // namespace
}  // namespace ergo
