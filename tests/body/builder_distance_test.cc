// Signed distance to the skin (ergo/body/surface_distance.h) against a sphere, and the
// flat caps that close open scans (ergo/body/hole_filling.h).
#include <cmath>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "ergo/body/hole_filling.h"
#include "ergo/body/surface_distance.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/primitives.h"

namespace ergo {
namespace {

constexpr double kRadius = 0.1;

TEST(Body, SurfaceDistanceMatchesTheSphereUpToTheFacets) {
  const TriMesh sphere = MakeIcosphere(kRadius, 4);  // edges ~7.5 mm: facets sag < 0.2 mm
  const SurfaceDistance distance(sphere);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d p(u(random), u(random), u(random));
    const double exact = p.norm() - kRadius;
    SurfaceDistance::Closest closest;
    const double d = distance.Signed(p, &closest);
    EXPECT_NEAR(d, exact, 2e-4) << p.transpose();
    EXPECT_NEAR(closest.distance, std::abs(d), 1e-15);
    EXPECT_NEAR(closest.point.norm(), kRadius, 2e-4);
    if (std::abs(exact) > 2e-4) {
      EXPECT_EQ(distance.Inside(p), exact < 0);
    }
    // NearestWithin agrees with Nearest when the nearest point is within the radius,
    // including balls that swallow whole triangles.
    for (double radius : {0.005, 0.05, 0.3}) {
      const std::optional<SurfaceDistance::Closest> within = distance.NearestWithin(p, radius);
      EXPECT_EQ(within.has_value(), closest.distance <= radius) << radius;
      if (within) {
        EXPECT_NEAR(within->distance, closest.distance, 1e-15);
      }
    }
  }
  // The centre: 0.1 from everything; a ball of 0.11 contains the whole surface.
  EXPECT_TRUE(distance.NearestWithin(Eigen::Vector3d::Zero(), 0.11).has_value());
  EXPECT_FALSE(distance.NearestWithin(Eigen::Vector3d::Zero(), 0.09).has_value());
}

TEST(Body, FlatCapsCloseACutSphere) {
  // Cut the icosphere by dropping the triangles with a vertex above z = 0.05.
  const TriMesh sphere = MakeIcosphere(kRadius, 3);
  TriMesh cut;
  cut.vertices = sphere.vertices;  // unused vertices are fine here
  std::vector<Eigen::RowVector3i> kept;
  for (Eigen::Index f = 0; f < sphere.triangles.rows(); ++f) {
    bool below = true;
    for (int k = 0; k < 3; ++k) below = below && sphere.vertices(sphere.triangles(f, k), 2) < 0.05;
    if (below) kept.push_back(sphere.triangles.row(f));
  }
  cut.triangles.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t f = 0; f < kept.size(); ++f) cut.triangles.row(f) = kept[f];
  const CappedSurface capped = CloseWithFlatCaps(cut, "cut");
  EXPECT_EQ(capped.holes_capped, 1);
  EXPECT_GT(capped.cap_triangles, 0);
  ASSERT_EQ(capped.notes.size(), 1u);
  EXPECT_EQ(capped.surface.triangles.rows(), cut.triangles.rows() + capped.cap_triangles);
  // Closed and outward: positive enclosed volume, every edge used twice.
  double volume = 0;
  std::map<std::pair<int, int>, int> edges;
  for (Eigen::Index f = 0; f < capped.surface.triangles.rows(); ++f) {
    const Eigen::Vector3d a = capped.surface.vertices.row(capped.surface.triangles(f, 0));
    const Eigen::Vector3d b = capped.surface.vertices.row(capped.surface.triangles(f, 1));
    const Eigen::Vector3d c = capped.surface.vertices.row(capped.surface.triangles(f, 2));
    volume += a.dot(b.cross(c)) / 6;
    for (int k = 0; k < 3; ++k) {
      const int i = capped.surface.triangles(f, k), j = capped.surface.triangles(f, (k + 1) % 3);
      ++edges[{std::min(i, j), std::max(i, j)}];
    }
  }
  EXPECT_GT(volume, 0);
  for (const auto& [edge, count] : edges) EXPECT_EQ(count, 2);
  // An inside-out input comes back outward, and a closed input gets no cap.
  TriMesh flipped = sphere;
  flipped.triangles.col(1).swap(flipped.triangles.col(2));
  const CappedSurface unflipped = CloseWithFlatCaps(flipped, "flipped");
  EXPECT_EQ(unflipped.holes_capped, 0);
  EXPECT_EQ(unflipped.surface.triangles, sphere.triangles);
}

}  // namespace
}  // namespace ergo
