// ζ of one surface against hand-computed values and its derivatives against finite
// differences; ψ likewise; the designer's statistics on a hand-made field.
#include "ergo/ergonomics/pressure_cost.h"

#include <cmath>
#include <algorithm>
#include <iostream>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/ergonomics/pressure_statistics.h"
#include "ergo/ergonomics/smoothness_term.h"
#include "ergo/mesh/primitives.h"
#include "ergo/mesh/surface_geometry.h"
#include "tests/support/finite_difference.h"

namespace ergo {
namespace {

class ErgonomicsUniform
    : public ::testing::TestWithParam<std::tuple<int, double, double>> {};

// A uniform pressure p on a closed surface of area A: every smoothing leaves it uniform
// (rows of L sum to zero; the Helmholtz filter passes constants, K·1 = 0), so
// ζ = Σ s_i p^e = A p^e.
TEST_P(ErgonomicsUniform, UniformPressureGivesAreaTimesPressureToTheExponent) {
  const auto [exponent, smoothing, radius] = GetParam();
  const TriMesh box = MakeBox({0, 0, 0}, {0.5, 0.2, 0.5}, {5, 2, 5});
  const Eigen::VectorXd area = BarycentricVertexAreas(box);
  const double p = 1234.5, total_area = 2 * (0.5 * 0.2 + 0.2 * 0.5 + 0.5 * 0.5);
  const PressureCostOptions options{exponent, smoothing, radius};
  const SurfacePressure result =
      EvaluateSurfacePressure(p * area, area, MakePressureSmoothing(box, options), options);
  EXPECT_NEAR(result.cost, total_area * std::pow(p, exponent),
              1e-9 * total_area * std::pow(p, exponent));
  EXPECT_LT((result.smoothed.array() - p).abs().maxCoeff(), 1e-9 * p);
}

INSTANTIATE_TEST_SUITE_P(ExponentsAndSmoothing, ErgonomicsUniform,
                         ::testing::Combine(::testing::Values(2, 3, 4),
                                            ::testing::Values(0.0, 0.5, 1.0),
                                            ::testing::Values(0.0, 0.05)));

TEST(Ergonomics, PressureCostDerivativesMatchFiniteDifferences) {
  const TriMesh sphere = MakeIcosphere(0.1, 2);
  const Eigen::Index n = sphere.vertices.rows();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(0.5, 1.5);
  Eigen::VectorXd forces(n), areas(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    forces[i] = i % 3 == 0 ? 0.0 : uniform(rng);  // some vertices out of contact
    areas[i] = 1e-4 * uniform(rng);
  }
  for (int exponent : {2, 3, 4}) {
    for (double smoothing : {0.0, 0.7, 1.0}) {
     for (double radius : {0.0, 0.04}) {  // umbrella, and a Helmholtz filter of 4 cm
      const PressureCostOptions options{exponent, smoothing, radius};
      const PressureSmoothing smoother = MakePressureSmoothing(sphere, options);
      const SurfacePressure at = EvaluateSurfacePressure(forces, areas, smoother, options);
      // Variables: forces of contact vertices (a zero force is a kink) and all areas.
      Eigen::VectorXd x(2 * n), gradient(2 * n);
      x << forces, areas;
      gradient << at.d_force_magnitude, at.d_area;
      for (Eigen::Index i = 0; i < n; ++i)
        if (forces[i] == 0) gradient[i] = 0;
      auto cost = [&](const Eigen::VectorXd& v) {
        Eigen::VectorXd f = v.head(n);
        for (Eigen::Index i = 0; i < n; ++i)
          if (forces[i] == 0) f[i] = 0;  // stay off the kink
        return EvaluateSurfacePressure(f, v.tail(n), smoother, options).cost;
      };
      std::string report;
      // ζ is a polynomial in ‖f‖ and 1/s here: smooth; 1e-7 allows the sweep's round-off.
      const double error = testing::WorstGradientError(
          cost, gradient, x, 1e-6 * gradient.norm(), testing::StepSweep(1e-6, 5), 6, 0, 1, &report);
      EXPECT_LT(error, 1e-7) << "e=" << exponent << " λ=" << smoothing << " r=" << radius << "\n"
                             << report;
     }
    }
  }
}

// The same pressure field (a smooth bump with a hot spot of σ = 1 cm) on a plate meshed at
// 10, 5 and 2.5 mm: ζ with the Helmholtz smoothing of one radius agrees across the three,
// where the paper's umbrella smoothing (reach: one ring) does not — it smooths a 10 mm mesh
// four times as far as a 2.5 mm one.
TEST(Ergonomics, HelmholtzPressureSmoothingGivesTheSameScoreOnEveryMesh) {
  auto pressure_at = [](const Eigen::Vector3d& x) {
    const double r2 = (x.x() * x.x() + x.z() * x.z());
    const double hot = (x.x() - 0.01) * (x.x() - 0.01) + (x.z() + 0.02) * (x.z() + 0.02);
    return 5e4 * std::exp(-r2 / (2 * 0.03 * 0.03)) + 1e5 * std::exp(-hot / (2 * 0.01 * 0.01));
  };
  std::vector<double> helmholtz, umbrella;
  for (int cells : {16, 32, 64}) {  // 160 mm plate: 10, 5, 2.5 mm
    const TriMesh plate = MakeBox({-0.08, -0.02, -0.08}, {0.08, 0, 0.08}, {cells, 1, cells});
    const Eigen::VectorXd area = BarycentricVertexAreas(plate);
    Eigen::VectorXd load = Eigen::VectorXd::Zero(plate.vertices.rows());
    for (Eigen::Index v = 0; v < plate.vertices.rows(); ++v)
      if (plate.vertices(v, 1) > -1e-9) load[v] = pressure_at(plate.vertices.row(v)) * area[v];
    for (double radius : {0.0, 0.0173}) {
      const PressureCostOptions options{3, 1.0, radius};
      const double zeta =
          EvaluateSurfacePressure(load, area, MakePressureSmoothing(plate, options), options).cost;
      (radius > 0 ? helmholtz : umbrella).push_back(zeta);
    }
  }
  auto spread = [](const std::vector<double>& v) {
    return (*std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end())) /
           *std::min_element(v.begin(), v.end());
  };
  std::cout << "zeta at 10/5/2.5 mm: Helmholtz " << helmholtz[0] << " " << helmholtz[1] << " "
            << helmholtz[2] << " (spread " << spread(helmholtz) << "), umbrella " << umbrella[0]
            << " " << umbrella[1] << " " << umbrella[2] << " (spread " << spread(umbrella) << ")\n";
  EXPECT_LT(spread(helmholtz), 0.02);
  EXPECT_GT(spread(umbrella), 0.1);  // the defect the filter removes
}

TEST(Ergonomics, SmoothnessOfTheOctahedronIsHandComputed) {
  // One Taubin step scales the octahedron by 0.765 (see the mesh tests), so
  // ψ = ‖(1 − 0.765) x‖² = 0.235² · 6 for unit vertices.
  TriMesh octahedron;
  octahedron.vertices.resize(6, 3);
  octahedron.vertices << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  octahedron.triangles.resize(8, 3);
  octahedron.triangles << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
  const SparseMatrix laplacian = UmbrellaLaplacian(octahedron.triangles, 6);
  const SmoothnessValue psi = EvaluateSmoothness(octahedron.vertices, laplacian, {0.5, -0.53, 1});
  EXPECT_NEAR(psi.value, 0.235 * 0.235 * 6, 1e-14);
}

TEST(Ergonomics, SmoothnessGradientMatchesFiniteDifferences) {
  const TriMesh box = MakeBox({0, 0, 0}, {0.5, 0.2, 0.5}, {4, 2, 4});
  const SparseMatrix laplacian = UmbrellaLaplacian(box.triangles, box.vertices.rows());
  for (int m : {1, 3}) {
    const TaubinParameters taubin{0.5, -0.53, m};
    const SmoothnessValue at = EvaluateSmoothness(box.vertices, laplacian, taubin);
    const Eigen::VectorXd x =
        Eigen::Map<const Eigen::VectorXd>(box.vertices.data(), box.vertices.size());
    const Eigen::VectorXd gradient =
        Eigen::Map<const Eigen::VectorXd>(at.gradient.data(), at.gradient.size());
    auto psi = [&](const Eigen::VectorXd& v) {
      const Vertices positions = Eigen::Map<const Vertices>(v.data(), box.vertices.rows(), 3);
      return EvaluateSmoothness(positions, laplacian, taubin).value;
    };
    std::string report;
    // ψ is quadratic: central differences are exact up to round-off.
    EXPECT_LT(testing::WorstGradientError(psi, gradient, x, 1e-6 * gradient.norm(),
                                          testing::StepSweep(1e-3, 3), 6, 0, 2, &report),
              1e-8)
        << report;
  }
}

TEST(Ergonomics, StatisticsOfAHandMadeField) {
  Eigen::VectorXd pressure(6), area(6);
  pressure << 0, 100, 200, 300, 400, 1000;
  area << 1, 0.5, 0.5, 0.5, 0.5, 0.1;
  const PressureStatistics s = ComputePressureStatistics(pressure, area, 10);
  EXPECT_EQ(s.contact_vertices, 5);
  EXPECT_EQ(s.peak, 1000);
  EXPECT_EQ(s.percentile95, 1000);  // nearest rank: ceil(0.95·5) = 5th of 5
  EXPECT_DOUBLE_EQ(s.contact_area, 2.1);
  EXPECT_DOUBLE_EQ(s.total_force, 50 + 100 + 150 + 200 + 100);
  EXPECT_DOUBLE_EQ(s.mean, 600 / 2.1);
  EXPECT_EQ(s.bin_counts[1], 1);  // 100 in [100, 200)
  EXPECT_EQ(s.bin_counts[9], 1);  // 1000 in the last bin
}

}  // namespace
}  // namespace ergo
