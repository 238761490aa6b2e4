// Finite-difference checks of the sliding-anchor energy in all 7 Voronoi regions of a
// triangle, with respect to the skin vertex p and all support vertices, at scales from
// 1 mm to 10 m, plus one-sided checks at region boundaries.
//
// Tolerance 1e-6 (relative): the energies are rational functions, smooth inside a region;
// central differences swept over six decades of step reach ~1e-9 relative on well-shaped
// triangles (truncation h²|f'''|/6 against rounding ε|f|/h), so 1e-6 leaves three orders of
// margin for the random shapes while any wrong term — a sign, a missing sliding term, a
// factor 2 — errs by O(1) and fails by six orders.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "ergo/contact/closest_feature.h"
#include "ergo/contact/point_feature_energy.h"
#include "tests/contact/contact_test_util.h"
#include "tests/support/finite_difference.h"

namespace ergo {
namespace {

using contact_testing::AllRegions;
using contact_testing::Region;
using contact_testing::RegionName;
using contact_testing::Triangle;
using Eigen::Vector3d;
using Eigen::VectorXd;

constexpr double kTolerance = 1e-6;
constexpr double kScales[] = {1e-3, 1e-2, 0.1, 1.0, 10.0};

Vector12d Pack(const Vector3d& p, const Triangle& t) {
  Vector12d x;
  x << p, t[0], t[1], t[2];
  return x;
}
void Unpack(const VectorXd& x, Vector3d* p, Triangle* t) {
  *p = x.segment<3>(0);
  for (int i = 0; i < 3; ++i) (*t)[i] = x.segment<3>(3 + 3 * i);
}

FeaturePositions RegionPositions(const Region& region, const Triangle& t) {
  std::array<int, 3> blocks;
  const int n = contact_testing::RegionVertexBlocks(region, &blocks);
  FeaturePositions x;
  for (int i = 0; i < n; ++i) x[i] = t[blocks[i] - 1];
  return x;
}

// The region formula's gradient and Hessian scattered into the 12 coordinates (p, x0, x1, x2).
void Scatter(const Region& region, const SlidingAnchorEnergy& e, Vector12d* gradient,
             Matrix12d* hessian) {
  std::array<int, 3> blocks;
  const int n = contact_testing::RegionVertexBlocks(region, &blocks);
  int map[4] = {0, 0, 0, 0};
  for (int i = 0; i < n; ++i) map[i + 1] = blocks[i];
  gradient->setZero();
  if (hessian) hessian->setZero();
  for (int a = 0; a <= n; ++a) {
    gradient->segment<3>(3 * map[a]) = e.gradient.segment<3>(3 * a);
    if (!hessian) continue;
    for (int b = 0; b <= n; ++b)
      hessian->block<3, 3>(3 * map[a], 3 * map[b]) = e.hessian.block<3, 3>(3 * a, 3 * b);
  }
}

// The true sliding-anchor energy k·dist²(p, triangle): classification then distance.
struct TrueEnergy {
  double k;
  // Every region that an evaluation fell into, so a test can insist the FD stayed inside.
  mutable std::map<std::pair<FeatureType, int>, int> seen;

  double Energy(const VectorXd& x) const {
    Vector3d p;
    Triangle t;
    Unpack(x, &p, &t);
    const TriangleProjection q = ClosestPointOnTriangle(p, t[0], t[1], t[2]);
    ++seen[{q.type, q.index}];
    return k * q.squared_distance;
  }
  // Gradient of the region the point is in, over all 12 coordinates.
  VectorXd Gradient(const VectorXd& x) const {
    Vector3d p;
    Triangle t;
    Unpack(x, &p, &t);
    const TriangleProjection q = ClosestPointOnTriangle(p, t[0], t[1], t[2]);
    ++seen[{q.type, q.index}];
    const Region region{q.type, q.index};
    Vector12d gradient;
    Scatter(region, EvaluateSlidingAnchor(q.type, p, RegionPositions(region, t), k, false),
            &gradient, nullptr);
    return gradient;
  }
};

double RandomStiffness(std::mt19937& rng) {
  return std::pow(10.0, std::uniform_real_distribution<double>(2, 6)(rng));
}

// Worst FD errors per region, printed once at the end of the suite for the README.
std::map<std::string, std::pair<double, double>>& WorstErrors() {
  static std::map<std::string, std::pair<double, double>> worst;
  return worst;
}

TEST(Contact, RegionFormulasMatchFiniteDifferencesInAllSevenRegions) {
  std::mt19937 rng(20240611);
  for (const Region& region : AllRegions()) {
    for (double scale : kScales) {
      for (int trial = 0; trial < 4; ++trial) {
        const Triangle t = contact_testing::RandomTriangle(rng, scale);
        const Vector3d p = contact_testing::PointInRegion(rng, t, region, scale);
        const double k = RandomStiffness(rng);
        SCOPED_TRACE(RegionName(region) + " scale " + std::to_string(scale) + " trial " +
                     std::to_string(trial));

        const TriangleProjection q = ClosestPointOnTriangle(p, t[0], t[1], t[2]);
        ASSERT_EQ(q.type, region.type);
        ASSERT_EQ(q.index, region.index);

        const SlidingAnchorEnergy e =
            EvaluateSlidingAnchor(region.type, p, RegionPositions(region, t), k);
        EXPECT_EQ(e.size, 3 * (FeatureVertexCount(region.type) + 1));
        // The region formula is the squared distance to the closest point.
        EXPECT_NEAR(e.energy, k * q.squared_distance, 1e-12 * e.energy);
        EXPECT_LT((SlidingAnchor(region.type, p, RegionPositions(region, t)) - q.point).norm(),
                  1e-12 * scale);

        Vector12d gradient;
        Matrix12d hessian;
        Scatter(region, e, &gradient, &hessian);
        const VectorXd x = Pack(p, t);
        const std::vector<double> steps = testing::StepSweep(1e-3 * scale, 6);
        TrueEnergy truth{k, {}};
        std::string report;
        const double gradient_error = testing::WorstGradientError(
            [&](const VectorXd& y) { return truth.Energy(y); }, gradient, x, 1e-3 * gradient.norm(),
            steps, 4, 12, rng(), &report);
        EXPECT_LE(gradient_error, kTolerance) << report;
        const double hessian_error = testing::WorstJacobianError(
            [&](const VectorXd& y) { return truth.Gradient(y); }, hessian, x,
            1e-3 * hessian.cwiseAbs().maxCoeff(), steps, 4, 12, rng(), &report);
        EXPECT_LE(hessian_error, kTolerance) << report;
        // Every FD evaluation stayed in the region: strictly inside, as constructed.
        EXPECT_EQ(truth.seen.size(), 1u);
        EXPECT_TRUE(truth.seen.count({region.type, region.index}));

        auto& worst = WorstErrors()[RegionName(region)];
        worst.first = std::max(worst.first, gradient_error);
        worst.second = std::max(worst.second, hessian_error);
      }
    }
  }
  for (const auto& [name, errors] : WorstErrors()) {
    std::printf("[ fd errors ] %-8s energy->gradient %.1e  gradient->Hessian %.1e\n", name.c_str(),
                errors.first, errors.second);
  }
}

TEST(Contact, GradientsMatchTheSlidingAnchorClosedForms) {
  // DESIGN §3 cross-checks: ∂E/∂(p, x_v) = 2k r (1, −w_v) with w the anchor's weights on
  // the feature's vertices (1; 1−t, t; barycentric b).
  std::mt19937 rng(7);
  for (const Region& region : AllRegions()) {
    for (double scale : kScales) {
      const Triangle t = contact_testing::RandomTriangle(rng, scale);
      const Vector3d p = contact_testing::PointInRegion(rng, t, region, scale);
      const double k = RandomStiffness(rng);
      const FeaturePositions x = RegionPositions(region, t);
      const Vector3d anchor = SlidingAnchor(region.type, p, x);
      const Vector3d r = p - anchor;
      Eigen::Vector3d weights = Eigen::Vector3d::Zero();
      if (region.type == FeatureType::kVertex) {
        weights[0] = 1;
      } else if (region.type == FeatureType::kEdge) {
        const double s = (anchor - x[0]).dot(x[1] - x[0]) / (x[1] - x[0]).squaredNorm();
        weights << 1 - s, s, 0;
      } else {
        const Vector3d n = (x[1] - x[0]).cross(x[2] - x[0]);
        for (int v = 0; v < 3; ++v) {
          weights[v] = n.dot((x[(v + 2) % 3] - x[(v + 1) % 3]).cross(anchor - x[(v + 1) % 3])) /
                       n.squaredNorm();
        }
      }
      const SlidingAnchorEnergy e = EvaluateSlidingAnchor(region.type, p, x, k);
      const double norm = 2 * k * r.norm();
      EXPECT_LT((e.gradient.segment<3>(0) - 2 * k * r).norm(), 1e-9 * norm) << RegionName(region);
      for (int v = 0; v < FeatureVertexCount(region.type); ++v) {
        EXPECT_LT((e.gradient.segment<3>(3 + 3 * v) + 2 * k * weights[v] * r).norm(), 1e-9 * norm)
            << RegionName(region) << " vertex " << v;
      }
      // (p, p) block: 2k I, 2k (I − ê êᵀ) (corrected Eq. 29), 2k n nᵀ (Eq. 32).
      Eigen::Matrix3d expected = 2 * k * Eigen::Matrix3d::Identity();
      if (region.type == FeatureType::kEdge) {
        const Vector3d u = (x[1] - x[0]).normalized();
        expected = 2 * k * (Eigen::Matrix3d::Identity() - u * u.transpose());
      } else if (region.type == FeatureType::kFace) {
        const Vector3d n = (x[1] - x[0]).cross(x[2] - x[0]).normalized();
        expected = 2 * k * n * n.transpose();
      }
      EXPECT_LT((e.hessian.block<3, 3>(0, 0) - expected).norm(), 1e-9 * 2 * k)
          << RegionName(region);
      // Symmetric Hessian; translation invariance: rows sum to zero over the blocks.
      const int size = e.size;
      EXPECT_LT(
          (e.hessian.topLeftCorner(size, size) - e.hessian.topLeftCorner(size, size).transpose())
              .norm(),
          1e-12 * e.hessian.norm());
      Eigen::Matrix3d block_sum = Eigen::Matrix3d::Zero();
      Vector3d gradient_sum = Vector3d::Zero();
      for (int b = 0; b < size / 3; ++b) {
        block_sum += e.hessian.block<3, 3>(0, 3 * b);
        gradient_sum += e.gradient.segment<3>(3 * b);
      }
      EXPECT_LT(block_sum.norm(), 1e-9 * 2 * k * (1 + e.hessian.norm() / k));
      EXPECT_LT(gradient_sum.norm(), 1e-9 * norm);
    }
  }
}

TEST(Contact, SeparateRegionFunctionsAgreeWithTheDispatcher) {
  std::mt19937 rng(11);
  const Triangle t = contact_testing::RandomTriangle(rng, 0.1);
  const double k = 3e4;
  for (const Region& region : AllRegions()) {
    const Vector3d p = contact_testing::PointInRegion(rng, t, region, 0.1);
    const FeaturePositions x = RegionPositions(region, t);
    const SlidingAnchorEnergy e = EvaluateSlidingAnchor(region.type, p, x, k);
    switch (region.type) {
      case FeatureType::kVertex:
        EXPECT_EQ(e.energy, PointVertexEnergy(p, x[0], k));
        EXPECT_EQ((e.gradient.head<6>()), PointVertexEnergyGradient(p, x[0], k));
        EXPECT_EQ((e.hessian.topLeftCorner<6, 6>()), PointVertexEnergyHessian(p, x[0], k));
        break;
      case FeatureType::kEdge:
        EXPECT_NEAR(e.energy, PointEdgeEnergy(p, x[0], x[1], k), 1e-14 * e.energy);
        EXPECT_EQ((e.gradient.head<9>()), PointEdgeEnergyGradient(p, x[0], x[1], k));
        EXPECT_EQ((e.hessian.topLeftCorner<9, 9>()), PointEdgeEnergyHessian(p, x[0], x[1], k));
        break;
      case FeatureType::kFace:
        EXPECT_NEAR(e.energy, PointFaceEnergy(p, x[0], x[1], x[2], k), 1e-14 * e.energy);
        EXPECT_EQ(e.gradient, PointFaceEnergyGradient(p, x[0], x[1], x[2], k));
        EXPECT_EQ(e.hessian, PointFaceEnergyHessian(p, x[0], x[1], x[2], k));
        break;
    }
    // Without the Hessian the value and gradient are the same.
    const SlidingAnchorEnergy light = EvaluateSlidingAnchor(region.type, p, x, k, false);
    EXPECT_EQ(light.energy, e.energy);
    EXPECT_EQ(light.gradient, e.gradient);
    EXPECT_EQ(light.hessian, Matrix12d::Zero());
  }
}

// ---- One-sided checks at region boundaries ----

// Central differences centred h past the boundary point x0 on one side, step h: they only
// evaluate at x0 and x0 + 2h·d, never across the boundary. Best over the sweep.
double OneSidedGradientError(const TrueEnergy& truth, const VectorXd& x0, const VectorXd& d,
                             const std::function<Vector12d(const VectorXd&)>& side_gradient,
                             double scale_floor, const std::vector<double>& steps) {
  double best = INFINITY;
  for (double h : steps) {
    const VectorXd centre = x0 + h * d;
    const testing::SweepResult r =
        testing::CheckDirectional([&](const VectorXd& y) { return truth.Energy(y); }, centre, d,
                                  side_gradient(centre).dot(d), scale_floor, {h});
    best = std::min(best, r.best_relative_error);
  }
  return best;
}
double OneSidedHessianError(const TrueEnergy& truth, const VectorXd& x0, const VectorXd& d,
                            const std::function<Matrix12d(const VectorXd&)>& side_hessian,
                            double scale_floor, const std::vector<double>& steps) {
  double best = INFINITY;
  for (double h : steps) {
    const VectorXd centre = x0 + h * d;
    const testing::SweepResult r =
        testing::CheckJacobianVector([&](const VectorXd& y) { return truth.Gradient(y); }, centre,
                                     d, side_hessian(centre) * d, scale_floor, {h});
    best = std::min(best, r.best_relative_error);
  }
  return best;
}

// A point on the boundary between two regions of `t`, with the direction (in p) that enters
// each side.
struct Boundary {
  Region first, second;
  Vector3d p;
  Vector3d into_first, into_second;
};

std::vector<Boundary> Boundaries(std::mt19937& rng, const Triangle& t, double scale) {
  const Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
  std::uniform_real_distribution<double> uniform(0.2, 0.8);
  std::vector<Boundary> boundaries;
  for (int i = 0; i < 3; ++i) {
    const Vector3d& a = t[i];
    const Vector3d& b = t[(i + 1) % 3];
    const Vector3d along = (b - a).normalized();
    const Vector3d outward = along.cross(n);
    const double depth = scale * uniform(rng);
    // Face | edge i: p projects onto the edge's interior.
    const Vector3d on_edge = a + uniform(rng) * (b - a) - depth * n;
    boundaries.push_back(
        {Region{FeatureType::kFace, 0}, Region{FeatureType::kEdge, i}, on_edge, -outward, outward});
    // Edge i | vertex i: p in the plane through x_i perpendicular to the edge, outside it.
    const Vector3d beside_vertex = a + scale * uniform(rng) * outward - depth * n;
    boundaries.push_back({Region{FeatureType::kEdge, i}, Region{FeatureType::kVertex, i},
                          beside_vertex, along, -along});
  }
  return boundaries;
}

TEST(Contact, EachSideOfARegionBoundaryMatchesItsOwnOneSidedDifferences) {
  std::mt19937 rng(99);
  for (double scale : kScales) {
    const Triangle t = contact_testing::RandomTriangle(rng, scale);
    const double k = RandomStiffness(rng);
    for (const Boundary& boundary : Boundaries(rng, t, scale)) {
      const VectorXd x0 = Pack(boundary.p, t);
      SCOPED_TRACE(RegionName(boundary.first) + " | " + RegionName(boundary.second) + " scale " +
                   std::to_string(scale));
      // Both formulas at the boundary: equal energy and gradient (the squared distance to a
      // triangle is C¹), different Hessians (the jump the line search has to live with).
      Vector12d g1, g2;
      Matrix12d h1, h2;
      const SlidingAnchorEnergy e1 = EvaluateSlidingAnchor(boundary.first.type, boundary.p,
                                                           RegionPositions(boundary.first, t), k);
      const SlidingAnchorEnergy e2 = EvaluateSlidingAnchor(boundary.second.type, boundary.p,
                                                           RegionPositions(boundary.second, t), k);
      Scatter(boundary.first, e1, &g1, &h1);
      Scatter(boundary.second, e2, &g2, &h2);
      EXPECT_NEAR(e1.energy, e2.energy, 1e-9 * e1.energy);
      EXPECT_LT((g1 - g2).norm(), 1e-8 * g1.norm());
      EXPECT_GT((h1 - h2).norm(), 1e-3 * h1.norm());

      for (int side = 0; side < 2; ++side) {
        const Region& region = side == 0 ? boundary.first : boundary.second;
        VectorXd d = VectorXd::Zero(12);
        d.head<3>() = side == 0 ? boundary.into_first : boundary.into_second;
        const auto gradient = [&](const VectorXd& y) {
          Vector3d p;
          Triangle u;
          Unpack(y, &p, &u);
          Vector12d g;
          Scatter(region, EvaluateSlidingAnchor(region.type, p, RegionPositions(region, u), k), &g,
                  nullptr);
          return g;
        };
        const auto hessian = [&](const VectorXd& y) {
          Vector3d p;
          Triangle u;
          Unpack(y, &p, &u);
          Vector12d g;
          Matrix12d h;
          Scatter(region, EvaluateSlidingAnchor(region.type, p, RegionPositions(region, u), k), &g,
                  &h);
          return h;
        };
        TrueEnergy truth{k, {}};
        const std::vector<double> steps = testing::StepSweep(1e-3 * scale, 6);
        EXPECT_LE(OneSidedGradientError(truth, x0, d, gradient, 1e-3 * g1.norm(), steps),
                  kTolerance)
            << "side " << RegionName(region);
        EXPECT_LE(
            OneSidedHessianError(truth, x0, d, hessian, 1e-3 * h1.cwiseAbs().maxCoeff(), steps),
            kTolerance)
            << "side " << RegionName(region);
        // Points strictly on this side (the centres above) were classified into this region.
        truth.seen.clear();
        truth.Energy(x0 + 1e-4 * scale * d);
        EXPECT_TRUE(truth.seen.count({region.type, region.index})) << "side " << RegionName(region);

        // The fixed-region formula is smooth across the boundary: central differences on both
        // sides of x0, in every direction, match it too.
        std::string report;
        const auto energy = [&](const VectorXd& y) {
          Vector3d p;
          Triangle u;
          Unpack(y, &p, &u);
          return EvaluateSlidingAnchor(region.type, p, RegionPositions(region, u), k, false).energy;
        };
        EXPECT_LE(testing::WorstGradientError(energy, gradient(x0), x0, 1e-3 * g1.norm(), steps, 4,
                                              12, rng(), &report),
                  kTolerance)
            << report;
        EXPECT_LE(testing::WorstJacobianError(
                      [&](const VectorXd& y) -> VectorXd { return gradient(y); }, hessian(x0), x0,
                      1e-3 * h1.cwiseAbs().maxCoeff(), steps, 4, 12, rng(), &report),
                  kTolerance)
            << report;
      }
    }
  }
}

}  // namespace
}  // namespace ergo
