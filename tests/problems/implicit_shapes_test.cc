#include "problems/implicit_shapes.h"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

namespace ergo {
namespace {

// Brute-force distance from p to the ellipsoid surface over a fine parametric grid, then
// refined by a local grid search around the best sample.
double BruteEllipsoidDistance(const Ellipsoid& e, const Eigen::Vector3d& p) {
  auto point = [&](double theta, double phi) {
    const Eigen::Vector3d local(e.semi_axes[0] * std::sin(theta) * std::cos(phi),
                                e.semi_axes[1] * std::sin(theta) * std::sin(phi),
                                e.semi_axes[2] * std::cos(theta));
    return Eigen::Vector3d(e.centre + e.axes * local);
  };
  double best = std::numeric_limits<double>::infinity(), bt = 0, bp = 0;
  const int n = 400;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j < 2 * n; ++j) {
      const double t = M_PI * i / n, f = M_PI * j / n;
      const double d = (point(t, f) - p).norm();
      if (d < best) best = d, bt = t, bp = f;
    }
  }
  double step = M_PI / n;
  for (int level = 0; level < 40; ++level, step *= 0.5) {
    for (int i = -2; i <= 2; ++i) {
      for (int j = -2; j <= 2; ++j) {
        const double d = (point(bt + i * step, bp + j * step) - p).norm();
        if (d < best) best = d, bt += i * step, bp += j * step;
      }
    }
  }
  return best;
}

TEST(Problems, EllipsoidSignedDistanceMatchesBruteForceInsideAndOutside) {
  Ellipsoid e;
  e.centre = Eigen::Vector3d(0.01, -0.02, 0.03);
  e.semi_axes = Eigen::Vector3d(0.12, 0.05, 0.08);
  e.axes = EulerXYZ(0.3, -0.2, 0.5);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-0.16, 0.16);
  for (int sample = 0; sample < 40; ++sample) {
    const Eigen::Vector3d p =
        e.centre + Eigen::Vector3d(uniform(random), uniform(random), uniform(random));
    const double signed_distance = SignedDistance(e, p);
    const Eigen::Vector3d q = e.axes.transpose() * (p - e.centre);
    const bool inside = (q.array() / e.semi_axes.array()).matrix().squaredNorm() < 1;
    EXPECT_EQ(signed_distance < 0, inside) << p.transpose();
    EXPECT_NEAR(std::abs(signed_distance), BruteEllipsoidDistance(e, p), 1e-9) << p.transpose();
  }
  // Points on the principal planes (the algorithm's special cases), inside and outside.
  for (const Eigen::Vector3d& local :
       {Eigen::Vector3d(0.05, 0, 0), Eigen::Vector3d(0, 0.01, 0), Eigen::Vector3d(0, 0, 0.02),
        Eigen::Vector3d(0.2, 0, 0), Eigen::Vector3d(0.03, 0.02, 0), Eigen::Vector3d(0, 0, 0),
        Eigen::Vector3d(0.1, 0, 0.05), Eigen::Vector3d(0, 0.09, 0.01)}) {
    const Eigen::Vector3d p = e.centre + e.axes * local;
    EXPECT_NEAR(std::abs(SignedDistance(e, p)), BruteEllipsoidDistance(e, p), 1e-9)
        << local.transpose();
  }
}

TEST(Problems, RoundConeDistanceIsExactForCapsulesAndTaperedLimbs) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(-0.2, 0.2);
  RoundCone capsule{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0.05, -0.02), 0.04, 0.04};
  RoundCone tapered{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0.05, -0.02), 0.06, 0.03};
  for (int sample = 0; sample < 200; ++sample) {
    const Eigen::Vector3d p(uniform(random), uniform(random), uniform(random));
    // Capsule: distance to the segment minus the radius, inside and outside.
    const Eigen::Vector3d ab = capsule.b - capsule.a;
    const double t = std::clamp((p - capsule.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    EXPECT_NEAR(SignedDistance(capsule, p), (p - capsule.a - t * ab).norm() - 0.04, 1e-12);
    // Tapered: the hull of two balls is the union of the interpolated balls, so outside
    // it the distance is min over t of |p − c(t)| − r(t).
    double brute = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 200000; ++k) {
      const double s = k / 200000.0;
      const Eigen::Vector3d c = tapered.a + s * (tapered.b - tapered.a);
      brute = std::min(brute, (p - c).norm() - (0.06 + s * (0.03 - 0.06)));
    }
    const double d = SignedDistance(tapered, p);
    if (brute > 0) {
      EXPECT_NEAR(d, brute, 1e-9) << p.transpose();
    } else {
      EXPECT_LE(d, 0.0) << p.transpose();
    }
  }
  // Reversed radii give the same shape.
  RoundCone reversed{tapered.b, tapered.a, 0.03, 0.06};
  const Eigen::Vector3d p(0.05, 0.08, 0.01);
  EXPECT_NEAR(SignedDistance(reversed, p), SignedDistance(tapered, p), 1e-14);
}

TEST(Problems, SignedDistancesHaveUnitGradient) {
  Ellipsoid e;
  e.semi_axes = Eigen::Vector3d(0.1, 0.06, 0.04);
  RoundCone cone{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.12, 0, 0), 0.05, 0.02};
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-0.15, 0.15);
  const double h = 1e-6;
  for (int sample = 0; sample < 100; ++sample) {
    const Eigen::Vector3d p(uniform(random), uniform(random), uniform(random));
    for (int shape = 0; shape < 2; ++shape) {
      auto f = [&](const Eigen::Vector3d& x) {
        return shape == 0 ? SignedDistance(e, x) : SignedDistance(cone, x);
      };
      if (shape == 0 && f(p) < -0.03) continue;  // near the medial axis |∇f| may jump
      Eigen::Vector3d gradient;
      for (int a = 0; a < 3; ++a) {
        const Eigen::Vector3d d = h * Eigen::Vector3d::Unit(a);
        gradient[a] = (f(p + d) - f(p - d)) / (2 * h);
      }
      EXPECT_NEAR(gradient.norm(), 1.0, 1e-5) << "shape " << shape << " at " << p.transpose();
    }
  }
}

TEST(Problems, SmoothMinBlendsOnlyWithinItsRadius) {
  EXPECT_DOUBLE_EQ(SmoothMin(0.1, 0.3, 0.1), 0.1);
  EXPECT_DOUBLE_EQ(SmoothMin(-0.2, 0.0, 0.1), -0.2);
  EXPECT_DOUBLE_EQ(SmoothMin(0.05, 0.05, 0.02), 0.05 - 0.005);
  for (double a = -0.1; a <= 0.1; a += 0.013) {
    EXPECT_LE(SmoothMin(a, 0.02, 0.04), std::min(a, 0.02));
    EXPECT_GE(SmoothMin(a, 0.02, 0.04), std::min(a, 0.02) - 0.01);
  }
}

TEST(Problems, BlendedShapeSkipsFarPrimitivesWithoutChangingTheResult) {
  BlendedShape shape(0.02, 0.03, 3);
  shape.Add(Ellipsoid{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0.05, 0.08),
                      Eigen::Matrix3d::Identity()},
            0);
  shape.Add(RoundCone{Eigen::Vector3d(0.05, 0, 0), Eigen::Vector3d(0.3, 0.02, 0), 0.05, 0.03}, 1);
  shape.Add(RoundCone{Eigen::Vector3d(-0.05, 0, 0), Eigen::Vector3d(-0.3, 0, 0.1), 0.04, 0.04}, 2);
  shape.Add(Ellipsoid{Eigen::Vector3d(0.5, 0.3, 0), Eigen::Vector3d(0.03, 0.02, 0.02),
                      EulerXYZ(0.1, 0.2, 0.3)},
            2);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-0.4, 0.6);
  for (int sample = 0; sample < 500; ++sample) {
    const Eigen::Vector3d p(uniform(random), 0.5 * uniform(random), 0.5 * uniform(random));
    // The naive evaluation: every primitive, in order.
    const double d[4] = {
        SignedDistance(Ellipsoid{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0.05, 0.08),
                                 Eigen::Matrix3d::Identity()},
                       p),
        SignedDistance(
            RoundCone{Eigen::Vector3d(0.05, 0, 0), Eigen::Vector3d(0.3, 0.02, 0), 0.05, 0.03}, p),
        SignedDistance(
            RoundCone{Eigen::Vector3d(-0.05, 0, 0), Eigen::Vector3d(-0.3, 0, 0.1), 0.04, 0.04}, p),
        SignedDistance(Ellipsoid{Eigen::Vector3d(0.5, 0.3, 0), Eigen::Vector3d(0.03, 0.02, 0.02),
                                 EulerXYZ(0.1, 0.2, 0.3)},
                       p)};
    double naive = d[0];
    for (int i = 1; i < 4; ++i) naive = SmoothMin(naive, d[i], 0.02);
    double weights[3];
    EXPECT_NEAR(shape.Evaluate(p, weights), naive, 1e-15);
    EXPECT_NEAR(weights[0] + weights[1] + weights[2], 1.0, 1e-12);
    EXPECT_GE(std::min({weights[0], weights[1], weights[2]}), 0.0);
  }
}

}  // namespace
}  // namespace ergo
