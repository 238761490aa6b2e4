// Point-triangle classification into the 7 Voronoi regions, including the degenerate
// configurations: queries exactly on vertices and edges, slivers, collapsed edges.
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "ergo/contact/closest_feature.h"
#include "tests/contact/contact_test_util.h"

namespace ergo {
namespace {

using Eigen::Vector3d;

void ExpectFinite(const TriangleProjection& q) {
  EXPECT_TRUE(q.point.allFinite());
  EXPECT_TRUE(std::isfinite(q.squared_distance));
  EXPECT_GE(q.squared_distance, 0.0);
}

// Brute force on a fine barycentric grid: the closest point is never beaten.
double GridSquaredDistance(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                           const Vector3d& c, int n) {
  double best = INFINITY;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const Vector3d x = a + (b - a) * i / n + (c - a) * j / n;
      best = std::min(best, (p - x).squaredNorm());
    }
  return best;
}

TEST(Contact, TriangleClassificationFindsEachConstructedRegion) {
  std::mt19937 rng(3);
  for (const auto& region : contact_testing::AllRegions()) {
    for (int trial = 0; trial < 50; ++trial) {
      const auto t = contact_testing::RandomTriangle(rng, 0.2);
      const Vector3d p = contact_testing::PointInRegion(rng, t, region, 0.2);
      const TriangleProjection q = ClosestPointOnTriangle(p, t[0], t[1], t[2]);
      EXPECT_EQ(q.type, region.type) << contact_testing::RegionName(region);
      EXPECT_EQ(q.index, region.index) << contact_testing::RegionName(region);
      EXPECT_NEAR(q.squared_distance, (p - q.point).squaredNorm(), 1e-15);
      // Never beaten by a point of the triangle (grid spacing bounds the gap).
      EXPECT_LE(q.squared_distance, GridSquaredDistance(p, t[0], t[1], t[2], 40) + 1e-15);
    }
  }
}

TEST(Contact, TriangleClassificationBreaksTiesTowardsTheHigherDimensionalFeature) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // Exactly at a vertex or on an edge, in the plane or off it: the face (closed face
  // region), at the exact distance.
  const Vector3d corners[3] = {a, b, c};
  for (double z : {0.0, 0.5, -0.5}) {
    for (int i = 0; i < 3; ++i) {
      const TriangleProjection q = ClosestPointOnTriangle(corners[i] + Vector3d(0, 0, z), a, b, c);
      EXPECT_EQ(q.type, FeatureType::kFace);
      EXPECT_EQ(q.squared_distance, z * z);
      EXPECT_EQ(q.point, corners[i]);
    }
    for (const Vector3d& on_edge :
         {Vector3d(0.5, 0, z), Vector3d(0.5, 0.5, z), Vector3d(0, 0.25, z)}) {
      const TriangleProjection q = ClosestPointOnTriangle(on_edge, a, b, c);
      EXPECT_EQ(q.type, FeatureType::kFace);
      EXPECT_EQ(q.squared_distance, z * z);
    }
  }
  // Outside edge 0 on the plane through vertex 0 perpendicular to it: the edge (closed
  // towards its vertices), anchored at the vertex.
  TriangleProjection q = ClosestPointOnTriangle(Vector3d(0, -1, 0.3), a, b, c);
  EXPECT_EQ(q.type, FeatureType::kEdge);
  EXPECT_EQ(q.index, 0);
  EXPECT_EQ(q.point, a);
  // Strictly inside the vertex region: the vertex.
  q = ClosestPointOnTriangle(Vector3d(-1, -1, 0.3), a, b, c);
  EXPECT_EQ(q.type, FeatureType::kVertex);
  EXPECT_EQ(q.index, 0);
  // Strictly outside an edge: the edge.
  q = ClosestPointOnTriangle(Vector3d(0.5, -0.5, 0.3), a, b, c);
  EXPECT_EQ(q.type, FeatureType::kEdge);
  EXPECT_EQ(q.index, 0);
  // Rounding-level excursions outside the face (1e-15 of the size) still report the face;
  // clear ones (1e-9) do not.
  EXPECT_EQ(ClosestPointOnTriangle(Vector3d(0.5, -1e-15, 0.3), a, b, c).type, FeatureType::kFace);
  EXPECT_EQ(ClosestPointOnTriangle(Vector3d(0.5, -1e-9, 0.3), a, b, c).type, FeatureType::kEdge);
  EXPECT_EQ(ClosestPointOnTriangle(Vector3d(-1e-15, -1, 0.3), a, b, c).type, FeatureType::kEdge);
  EXPECT_EQ(ClosestPointOnTriangle(Vector3d(-1e-9, -1, 0.3), a, b, c).type, FeatureType::kVertex);
  // Same answer on repetition (no hidden state).
  for (int repeat = 0; repeat < 3; ++repeat) {
    const TriangleProjection again = ClosestPointOnTriangle(Vector3d(0, -1, 0.3), a, b, c);
    EXPECT_EQ(again.type, FeatureType::kEdge);
    EXPECT_EQ(again.index, 0);
    EXPECT_EQ(again.point, a);
  }
}

TEST(Contact, SliverTrianglesNeverReportTheirFace) {
  // Height 1e-10 over a unit base: twice area / longest² = 1e-10 < kSliverRatio.
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0.5, 1e-10, 0);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-0.5, 1.5);
  for (int i = 0; i < 2000; ++i) {
    const Vector3d p(u(rng), 1e-10 * u(rng), u(rng) - 0.5);
    const TriangleProjection q = ClosestPointOnTriangle(p, a, b, c);
    ExpectFinite(q);
    EXPECT_NE(q.type, FeatureType::kFace);
    // The fallback errs by at most the sliver's height.
    EXPECT_LE(std::sqrt(q.squared_distance) - std::sqrt(GridSquaredDistance(p, a, b, c, 200)),
              1e-9);
  }
  // A query right above the sliver's interior.
  const TriangleProjection q = ClosestPointOnTriangle(Vector3d(0.5, 0.5e-10, 1), a, b, c);
  ExpectFinite(q);
  EXPECT_NE(q.type, FeatureType::kFace);
  EXPECT_NEAR(q.squared_distance, 1.0, 1e-9);
  // Just above the threshold the face is reported.
  const Vector3d fat(0.5, 1e-7, 0);
  EXPECT_EQ(ClosestPointOnTriangle(Vector3d(0.5, 0.5e-7, 1), a, b, fat).type, FeatureType::kFace);
}

TEST(Contact, CollapsedTrianglesGiveFiniteDeterministicAnswers) {
  const Vector3d a(0.3, -0.2, 0.1), b(1.3, 0.4, -0.2);
  const Vector3d p(0.7, 0.9, 0.4);
  // Two coincident vertices: edge 0 collapsed -> never that edge; the other edges are fine.
  TriangleProjection q = ClosestPointOnTriangle(p, a, a, b);
  ExpectFinite(q);
  EXPECT_FALSE(q.type == FeatureType::kEdge && q.index == 0);
  EXPECT_NE(q.type, FeatureType::kFace);
  // A nearly collapsed edge (1e-12 of the longest): reported as a vertex, never the edge.
  const Vector3d a2 = a + Vector3d(1e-12, 0, 0);
  q = ClosestPointOnTriangle(a + Vector3d(0, 0, 1), a, a2, b);
  ExpectFinite(q);
  EXPECT_FALSE(q.type == FeatureType::kEdge && q.index == 0);
  // All three coincident: vertex 0 at the exact distance.
  q = ClosestPointOnTriangle(p, a, a, a);
  ExpectFinite(q);
  EXPECT_EQ(q.type, FeatureType::kVertex);
  EXPECT_EQ(q.index, 0);
  EXPECT_EQ(q.squared_distance, (p - a).squaredNorm());
  // Exactly collinear: never the face, distance to the segment.
  const Vector3d m = 0.5 * (a + b);
  q = ClosestPointOnTriangle(p, a, m, b);
  ExpectFinite(q);
  EXPECT_NE(q.type, FeatureType::kFace);
  const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  EXPECT_NEAR(q.squared_distance, (p - (a + t * (b - a))).squaredNorm(), 1e-14);
}

}  // namespace
}  // namespace ergo
