// Whole point-set contact evaluation (issue 4, items 4–5): agreement with a one-point
// evaluation, determinism, and the bi-directional springs — support vertices inside a
// deformed closed skin — against finite differences in the support vertex and in the
// skin vertices of the feature (which the adjoint's ∂f/∂y uses).
#include "ergo/contact/contact_set.h"

#include <random>

#include <gtest/gtest.h>
#include <omp.h>

#include "ergo/mesh/primitives.h"
#include "tests/support/finite_difference.h"

namespace ergo {
namespace {

// Points scattered in a shell around a sphere of radius 0.1 (about half inside).
Vertices ShellPoints(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> radius(0.095, 0.105);
  Vertices points(count, 3);
  for (int i = 0; i < count; ++i) {
    Eigen::Vector3d d(normal(rng), normal(rng), normal(rng));
    points.row(i) = (radius(rng) * d.normalized()).transpose();
  }
  return points;
}

TEST(Contact, ContactSetAgreesWithOnePointEvaluationsAndBalancesItsForces) {
  const Support sphere(MakeIcosphere(0.1, 3));
  const Vertices points = ShellPoints(2000, 1);
  const Eigen::VectorXi all = Eigen::VectorXi::LinSpaced(2000, 0, 1999);
  const double k = 1e4;
  const ContactSet set = EvaluateContacts(sphere, points, all, k, true);
  double energy = 0, deepest = 0;
  int expected = 0;
  for (int i = 0; i < 2000; ++i) {
    const auto hit = sphere.Penetration(points.row(i).transpose());
    if (!hit) continue;
    ++expected;
    energy += k * hit->squared_distance;
    deepest = std::max(deepest, std::sqrt(hit->squared_distance));
  }
  EXPECT_EQ(set.size(), expected);
  EXPECT_GT(expected, 500);
  EXPECT_NEAR(set.energy, energy, 1e-12 * energy);
  EXPECT_NEAR(set.max_penetration, deepest, 1e-15);
  for (const Contact& c : set.contacts) {
    // The force pushes the point out along p − π, with magnitude 2k·depth.
    EXPECT_NEAR(c.force().norm(), 2 * k * c.penetration(), 1e-9 * k * c.penetration());
    EXPECT_GT(c.force().dot(c.anchor.point - points.row(c.point).transpose()), 0);
  }
}

TEST(Contact, ContactSetIsIdenticalForAnyThreadCount) {
  const Support sphere(MakeIcosphere(0.1, 3));
  const Vertices points = ShellPoints(5000, 2);
  const Eigen::VectorXi all = Eigen::VectorXi::LinSpaced(5000, 0, 4999);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const ContactSet one = EvaluateContacts(sphere, points, all, 1e4, true);
  omp_set_num_threads(2);
  const ContactSet two = EvaluateContacts(sphere, points, all, 1e4, true);
  omp_set_num_threads(threads);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(one.energy, two.energy);
  for (int i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one.contacts[i].point, two.contacts[i].point);
    EXPECT_EQ(one.contacts[i].spring.gradient, two.contacts[i].spring.gradient);
  }
}

// Bi-directional: a coarse closed "skin" (an icosphere squashed into an ellipsoid) and
// support vertices inside it. Each reverse spring's energy, as a function of the support
// vertex and of the skin vertices spanning its feature, against its gradient and Hessian.
TEST(Contact, BidirectionalSpringsMatchFiniteDifferencesInSupportAndSkinVertices) {
  TriMesh skin = MakeIcosphere(0.1, 2);
  for (Eigen::Index v = 0; v < skin.vertices.rows(); ++v) skin.vertices(v, 1) *= 0.6;
  Support surface(skin, "skin");
  Vertices support_points = ShellPoints(400, 3);
  support_points.col(1) *= 0.6;  // a shell around the ellipsoid: about half inside
  const ContactSet set =
      EvaluateContacts(surface, support_points, Eigen::VectorXi::LinSpaced(400, 0, 399), 5e3, true);
  ASSERT_GT(set.size(), 20);
  int checked[3] = {0, 0, 0};
  for (const Contact& c : set.contacts) {
    const int n = c.anchor.feature.size();
    const int dofs = 3 * (n + 1);
    Eigen::VectorXd z(dofs);
    z.head<3>() = support_points.row(c.point).transpose();
    for (int j = 0; j < n; ++j)
      z.segment<3>(3 + 3 * j) = skin.vertices.row(c.anchor.feature.vertices[j]).transpose();
    // The energy of this spring with the support vertex and the feature's skin vertices
    // moved: rebuild the skin, evaluate the same region's formula (sliding anchor).
    auto energy = [&](const Eigen::VectorXd& w) {
      FeaturePositions x;
      for (int j = 0; j < n; ++j) x[j] = w.segment<3>(3 + 3 * j);
      return EvaluateSlidingAnchor(c.anchor.feature.type, w.head<3>(), x, 5e3, false).energy;
    };
    auto gradient = [&](const Eigen::VectorXd& w) {
      FeaturePositions x;
      for (int j = 0; j < n; ++j) x[j] = w.segment<3>(3 + 3 * j);
      return Eigen::VectorXd(
          EvaluateSlidingAnchor(c.anchor.feature.type, w.head<3>(), x, 5e3, false)
              .gradient.head(dofs));
    };
    // The evaluated spring agrees with the mesh state: energy k·depth², same gradient.
    EXPECT_NEAR(energy(z), c.spring.energy, 1e-12 * c.spring.energy + 1e-300);
    std::string report;
    const double scale = c.spring.gradient.head(dofs).norm();
    // Smooth within the region; 1e-6 as in the one-spring tests.
    EXPECT_LT(testing::WorstGradientError(energy, c.spring.gradient.head(dofs), z, 1e-3 * scale,
                                          testing::StepSweep(1e-6, 4), 3, dofs, 7, &report),
              1e-6)
        << report;
    EXPECT_LT(testing::WorstJacobianError(gradient, c.spring.hessian.topLeftCorner(dofs, dofs), z,
                                          1e-3 * c.spring.hessian.norm(),
                                          testing::StepSweep(1e-6, 4), 3, dofs, 7, &report),
              1e-6)
        << report;
    ++checked[static_cast<int>(c.anchor.feature.type)];
  }
  EXPECT_GT(checked[static_cast<int>(FeatureType::kFace)], 0);
  // Moving the skin moves the anchors: the set re-evaluated on a displaced skin changes.
  Vertices moved = skin.vertices;
  moved.col(1) *= 0.98;
  surface.UpdateVertices(moved);
  const ContactSet after = EvaluateContacts(surface, support_points,
                                            Eigen::VectorXi::LinSpaced(400, 0, 399), 5e3, false);
  EXPECT_NE(after.energy, set.energy);
}

}  // namespace
}  // namespace ergo
