#include "ergo/body/tissue_compression.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "tests/support/body/body_fixtures.h"

namespace ergo {
namespace {

// The body at rest and turned and moved rigidly is not compressed at all: every tet's volume
// ratio and principal stretches are 1 (to rounding: 1e-12).
TEST(Body, TissueCompressionOfARigidMotionIsNone) {
  const LayeredBody body = testing::MakeHollowCubeBody(0.3, 3, 1e4, 0.45, {});
  for (const BodyState& state :
       {RestState(body), MovedRigidly(body, RestState(body), Eigen::Vector3d(0.1, -0.2, 0.05),
                                      Eigen::Vector3d(0.3, -0.2, 0.4))}) {
    const TissueCompression c = MeasureTissueCompression(body, state);
    EXPECT_NEAR(c.min_volume_ratio, 1, 1e-12);
    EXPECT_NEAR(c.min_principal_stretch, 1, 1e-12);
    EXPECT_EQ(c.tets_beyond_threshold, 0);
    EXPECT_EQ(c.inverted_tets, 0);
    EXPECT_TRUE(c.beyond_threshold_points.empty());
    EXPECT_EQ(c.threshold, body.material().inversion_threshold);
    EXPECT_GE(c.worst_tet, 0);
  }
}

// One free vertex moved towards the opposite face of one of its tets, along that face's
// normal, to s of its height: that tet's deformation gradient is F = I − (1 − s) n nᵀ, so its
// stretches are (1, 1, s) and det F = s, exactly. At s = 0.05 (95 % compression) it is beyond
// the threshold 0.1; at s = −0.5 (pushed through the face) it is inverted with stretch −0.5. The
// vertex's other tets only add to the counts, so the extremes are at most s and the worst tet
// touches the moved vertex.
TEST(Body, TissueCompressionFindsATetSqueezedToAKnownStretch) {
  const LayeredBody body = testing::MakeHollowCubeBody(0.3, 3, 1e4, 0.45, {});
  const Tetrahedra& tets = body.rest().tets;
  const Vertices& rest = body.rest().vertices;
  Eigen::Index tet = -1;
  int corner = -1;
  for (Eigen::Index t = 0; t < tets.rows() && tet < 0; ++t)
    for (int k = 0; k < 4 && tet < 0; ++k)
      if (body.free_index()[tets(t, k)] >= 0) tet = t, corner = k;
  ASSERT_GE(tet, 0);
  const int vertex = tets(tet, corner);
  const Eigen::Vector3d p = rest.row(vertex).transpose();
  const Eigen::Vector3d a = rest.row(tets(tet, (corner + 1) % 4)).transpose();
  const Eigen::Vector3d b = rest.row(tets(tet, (corner + 2) % 4)).transpose();
  const Eigen::Vector3d c = rest.row(tets(tet, (corner + 3) % 4)).transpose();
  Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
  if (normal.dot(p - a) < 0) normal = -normal;  // from the face towards the vertex
  const double height = normal.dot(p - a);
  for (const double s : {0.05, -0.5}) {
    BodyState state = RestState(body);
    state.free_displacement.segment<3>(3 * body.free_index()[vertex]) = -(1 - s) * height * normal;
    const TissueCompression squeezed = MeasureTissueCompression(body, state);
    EXPECT_LE(squeezed.min_principal_stretch, s + 1e-12) << s;
    EXPECT_LE(squeezed.min_volume_ratio, s + 1e-12) << s;
    EXPECT_GE(squeezed.tets_beyond_threshold, 1) << s;
    EXPECT_EQ(squeezed.inverted_tets > 0, s < 0) << s;
    EXPECT_EQ(static_cast<int>(squeezed.beyond_threshold_points.size()),
              squeezed.tets_beyond_threshold);
    bool touches = false;
    for (int k = 0; k < 4; ++k) touches = touches || tets(squeezed.worst_tet, k) == vertex;
    EXPECT_TRUE(touches) << s;
  }
}

}  // namespace
}  // namespace ergo
