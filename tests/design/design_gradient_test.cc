// The project's most important test (DESIGN.md §3, §6): the adjoint shape gradient dφ/dx
// against central finite differences of φ through fully re-solved equilibria, for ζ and ψ
// separately and together, along random directions, along the computed gradient and
// component by component, with contacts in face, edge and vertex regions, core rotation
// free and locked, and both design parameterisations.
#include <cmath>
#include <iostream>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "ergo/body/core_lock.h"
#include "ergo/design/design_problem.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"
#include "tests/support/finite_difference.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

struct Case {
  std::string name;
  std::string lock;
  DesignParameterization parameterization;
  double smoothing_radius = 0;     // pressure smoothing: 0 = umbrella, else Helmholtz, m
  double filter_radius = 0;        // for kFiltered, m
  bool support_springs = true;     // two-way contact, or support vertices scored only
  bool score_support_side = true;  // ζ of both surfaces, or of the skin alone
};

// A 10 cm soft hollow cube standing on a corner in a coarse square pyramid pit (45° facets,
// 5 cm grid), pressed in by 50 N on its core. The pit is a concave support: its apex, its
// valleys and its facets hold skin vertices in the vertex, edge and face Voronoi regions
// (interior points reach edge and vertex regions only at concave features), and pit
// vertices poke into the skin (the bi-directional springs) — checked below for every case.
struct PitScene {
  LayeredBody body;
  TriMesh support;
  BodyState start;
  std::vector<bool> active;
};

PitScene MakePitScene(const std::string& lock) {
  LayeredBodyOptions options;
  options.lock = ParseCoreLock(lock);
  options.external_force = Eigen::Vector3d(0, -50, 0);
  // Corner (−1,−1,−1) of the cube pointing straight down, 0.2 mm off the apex.
  const Eigen::Matrix3d corner_down =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d(-1, -1, -1).normalized(),
                                         Eigen::Vector3d(0, -1, 0))
          .toRotationMatrix();
  const Eigen::Vector3d centre(0.0002, 0.05 * std::sqrt(3.0) - 0.1 + 0.02, -0.0001);
  PitScene scene{
      testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options, centre, corner_down), {}, {}, {}};
  scene.support = MakeHeightfieldBlock(
      {-0.15, -0.2, -0.15}, {0.15, 0, 0.15}, {6, 1, 6},
      [](double x, double z) { return std::min(0.0, -0.1 + std::max(std::abs(x), std::abs(z))); });
  scene.start = RestState(scene.body);
  // The pit's vertices move (top face, inside the pit's rim).
  scene.active.resize(static_cast<size_t>(scene.support.vertices.rows()));
  for (Eigen::Index v = 0; v < scene.support.vertices.rows(); ++v) {
    const Eigen::Vector3d p = scene.support.vertices.row(v);
    scene.active[v] =
        p.y() > -0.1 - 1e-9 && std::max(std::abs(p.x()), std::abs(p.z())) < 0.1 + 1e-9;
  }
  return scene;
}

DesignOptions TightOptions(DesignParameterization parameterization, const std::vector<bool>& active,
                           double smoothing_radius = 0, double filter_radius = 0,
                           bool support_springs = true, bool score_support_side = true) {
  DesignOptions options;
  options.equilibrium.contact_stiffness = 3e7;  // κ, Pa/m
  // Tight equilibria: the FD quotient differences φ at x ± h d; an equilibrium error δy
  // would enter as |∂φ/∂y| δy / h.
  options.equilibrium.relative_tolerance = 1e-11;
  options.equilibrium.max_iterations = 200;
  options.pressure = {3, 1.0, smoothing_radius};
  options.filter_radius = filter_radius;
  options.equilibrium.contact_support_springs = support_springs;
  options.score_support_side = score_support_side;
  options.taubin = {0.5, -0.53, 2};
  options.gamma = 0;  // set per check
  options.parameterization = parameterization;
  options.active = active;
  return options;
}

// Best-over-sweep relative error of the directional derivative of `part` of φ.
struct DirectionCheck {
  double error = INFINITY;
  std::string report;
};

enum class Part { kZeta, kPsi, kPhi };

double PartValue(const DesignEvaluation& e, Part part) {
  return part == Part::kZeta ? e.zeta : part == Part::kPsi ? e.psi : e.phi;
}

DirectionCheck CheckDirection(DesignProblem& problem, const Eigen::VectorXd& x,
                              const Eigen::VectorXd& d, double analytic, double floor, Part part,
                              double length_scale) {
  DirectionCheck check;
  // Steps from 1 µm down to 10 nm (×length_scale for the normal parameterisation):
  // large enough to beat the equilibrium's round-off, small enough that no vertex crosses
  // a Voronoi-region or contact boundary in most directions. Under the sanitizers, which
  // look for memory errors, the two steps that alone pass every direction of the Release run
  // (measured: worst relative error 1.1e-6 over all six scenes).
  const std::vector<double> steps = testing::SanitizedBuild()
                                        ? std::vector<double>{1e-6, 1e-7}
                                        : std::vector<double>{1e-6, 3e-7, 1e-7, 3e-8, 1e-8};
  for (double h : steps) {
    const double step = h * length_scale;
    const DesignEvaluation plus = problem.Evaluate(x + step * d, false);
    const DesignEvaluation minus = problem.Evaluate(x - step * d, false);
    if (!plus.ok || !minus.ok) {
      check.report += "  h=" + std::to_string(step) + ": evaluation failed\n";
      continue;
    }
    const double fd = (PartValue(plus, part) - PartValue(minus, part)) / (2 * step);
    const double error = std::abs(fd - analytic) / std::max(std::abs(analytic), floor);
    char line[160];
    std::snprintf(line, sizeof(line), "  h=%.1e fd=%.10e analytic=%.10e rel=%.2e\n", step, fd,
                  analytic, error);
    check.report += line;
    check.error = std::min(check.error, error);
  }
  return check;
}

class DesignGradient : public ::testing::TestWithParam<Case> {};

TEST_P(DesignGradient, AdjointGradientMatchesFiniteDifferencesThroughTheEquilibrium) {
  const Case& c = GetParam();
  const PitScene scene = MakePitScene(c.lock);
  DesignProblem problem(scene.body, scene.support, scene.start,
                        TightOptions(c.parameterization, scene.active, c.smoothing_radius,
                                     c.filter_radius, c.support_springs, c.score_support_side));
  const Eigen::VectorXd x0 = problem.InitialDesign();
  // γ of the same order as ζ/ψ so that both parts matter in φ.
  DesignEvaluation at = problem.Evaluate(x0, true);
  ASSERT_TRUE(at.ok) << at.message;
  problem.set_gamma(at.zeta / at.psi);
  at = problem.Evaluate(x0, true);
  ASSERT_TRUE(at.ok) << at.message;
  // Both kinds of spring act in the equilibrium, and the skin's springs exercise every
  // Voronoi region type of the support.
  const SurfaceContacts& contacts = at.pressures.contacts;
  ASSERT_GT(contacts.support.size(), 0)
      << "no support vertex inside the skin: the two-way part is untested";
  ASSERT_GT(at.zeta_support, 0);
  EXPECT_EQ(at.zeta, c.score_support_side ? at.zeta_human + at.zeta_support : at.zeta_human);
  {
    std::set<FeatureType> types;
    for (const Contact& contact : contacts.skin.contacts) types.insert(contact.anchor.feature.type);
    EXPECT_EQ(types.size(), 3u) << "skin contacts do not cover vertex, edge and face regions";
  }

  const double length = c.parameterization == DesignParameterization::kPositions ? 1.0 : 1.0;
  std::mt19937 rng(17);
  std::normal_distribution<double> normal;
  const Eigen::Index n = x0.size();
  auto random_unit = [&] {
    Eigen::VectorXd d(n);
    for (Eigen::Index i = 0; i < n; ++i) d[i] = normal(rng);
    return Eigen::VectorXd(d.normalized());
  };
  // 1e-4 relative (the bound); the floor 1e-3‖∇‖ only matters for directions almost
  // orthogonal to the gradient, where it bounds the absolute error by 1e-7‖∇‖.
  constexpr double kTolerance = 1e-4;
  struct PartCheck {
    Part part;
    const Eigen::VectorXd* gradient;
    const char* name;
  };
  for (const PartCheck& pc : {PartCheck{Part::kZeta, &at.zeta_gradient, "zeta"},
                              PartCheck{Part::kPsi, &at.psi_gradient, "psi"},
                              PartCheck{Part::kPhi, &at.gradient, "phi"}}) {
    const Eigen::VectorXd& g = *pc.gradient;
    ASSERT_GT(g.norm(), 0) << pc.name;
    const double floor = 1e-3 * g.norm();
    std::vector<std::pair<std::string, Eigen::VectorXd>> directions = {
        {"along the gradient", g.normalized()},
        {"random 1", random_unit()},
        {"random 2", random_unit()}};
    if (pc.part == Part::kPhi) {
      // Component-wise on φ: every design variable (under the sanitizers, the three largest
      // |∂φ/∂xᵢ| and three more spread over the design).
      const std::vector<Eigen::Index> components =
          testing::SanitizedBuild() ? testing::CheckedComponents(g, 3, 3)
                                    : testing::CheckedComponents(g, 0, static_cast<int>(n));
      for (Eigen::Index i : components)
        directions.emplace_back("component " + std::to_string(i), Eigen::VectorXd::Unit(n, i));
    }
    double worst = 0;
    for (const auto& [name, d] : directions) {
      const DirectionCheck check = CheckDirection(problem, x0, d, g.dot(d), floor, pc.part, length);
      EXPECT_LT(check.error, kTolerance) << c.name << " " << pc.name << " " << name << "\n"
                                         << check.report;
      worst = std::max(worst, check.error);
    }
    std::cout << c.name << ": " << pc.name << " worst relative error " << worst << " over "
              << directions.size() << " directions\n";
  }
}

INSTANTIATE_TEST_SUITE_P(
    PitScenes, DesignGradient,
    ::testing::Values(
        Case{"rotation_free_positions", "tx,tz", DesignParameterization::kPositions},
        Case{"rotation_locked_positions", "tx,tz,rx,ry,rz", DesignParameterization::kPositions},
        Case{"rotation_free_normal", "tx,tz", DesignParameterization::kNormalDisplacement},
        Case{"pitch_only_normal", "tx,tz,rx,ry", DesignParameterization::kNormalDisplacement},
        // The scenarios' default: the filtered design space and the Helmholtz pressure
        // smoothing (radii of the order of the cube's 3.3 cm skin edge).
        Case{"rotation_free_filtered_helmholtz", "tx,tz", DesignParameterization::kFiltered, 0.05,
             0.08},
        // The paper's uni-directional equilibrium with the support's vertices scored only.
        Case{"one_way_filtered_helmholtz", "tx,tz", DesignParameterization::kFiltered, 0.05, 0.08,
             false},
        // The same with ζ of the skin's side alone (--score_sides=skin).
        Case{"one_way_skin_side_filtered_helmholtz", "tx,tz", DesignParameterization::kFiltered,
             0.05, 0.08, false, false}),
    [](const auto& info) { return info.param.name; });

TEST(DesignGradientFailure, ANonConvergingEquilibriumGivesAClearFailureNotANumber) {
  const PitScene scene = MakePitScene("tx,tz");
  DesignOptions options = TightOptions(DesignParameterization::kPositions, scene.active);
  options.equilibrium.max_iterations = 1;
  BodyState high = TranslatedRestState(scene.body, {0, 0.05, 0});
  DesignProblem problem(scene.body, scene.support, high, options);
  const DesignEvaluation e = problem.Evaluate(problem.InitialDesign(), true);
  EXPECT_FALSE(e.ok);
  EXPECT_NE(e.message.find("equilibrium failed"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("iteration cap"), std::string::npos) << e.message;
  EXPECT_EQ(e.gradient.size(), 0);
  EXPECT_EQ(problem.counters().failures.load(), 1);
}

}  // namespace
}  // namespace ergo
