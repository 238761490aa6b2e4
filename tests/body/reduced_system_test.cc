// The reduced energy, gradient and Hessian of the layered body against finite differences,
// hand-computed loads, rigid-motion invariance, and thread-count determinism.
#include "ergo/body/reduced_system.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <omp.h>
#include <Eigen/Dense>

#include "ergo/body/body_state.h"
#include "ergo/mesh/sparse_cholesky.h"
#include "tests/support/body/body_fixtures.h"
#include "tests/support/dense_symmetric.h"
#include "tests/support/finite_difference.h"

namespace ergo {
namespace {

using testing::DenseSymmetric;

// A 0.1 m hollow cube of soft tissue, deformed randomly by ~1 % of its size and with the
// core turned and moved, so that every term (elastic, gravity, wrench, lever arms) is on.
struct Deformed {
  LayeredBody body;
  BodyState state;
};

Deformed MakeDeformed(const CoreLock& lock, unsigned seed) {
  LayeredBodyOptions options;
  options.lock = lock;
  options.external_force = Eigen::Vector3d(3, -20, 1);
  options.external_torque = Eigen::Vector3d(0.2, -0.1, 0.3);
  Deformed d{testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options), {}};
  d.state = RestState(d.body);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (Eigen::Index i = 0; i < d.state.free_displacement.size(); ++i)
    d.state.free_displacement[i] = 1e-3 * uniform(rng);
  d.state.centre += Eigen::Vector3d(1e-3, -2e-3, 5e-4);
  d.state.rotation = RotationExp(Eigen::Vector3d(0.02, -0.03, 0.01));
  d.state.torque_angle = Eigen::Vector3d(0.02, -0.03, 0.01);
  return d;
}

struct Evaluated {
  double energy;
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
};

Evaluated EvaluateAt(const ReducedSystem& system, const BodyState& state, HessianKind kind) {
  const Vertices positions = DeformedPositions(system.body(), state);
  ReducedSystem::Evaluation e;
  system.Evaluate(state, positions, kind, true, &e);
  Evaluated out;
  out.gradient = system.Finalize(state, positions, kind, &e);
  out.energy = e.energy;
  out.hessian = DenseSymmetric(e.hessian);
  return out;
}

double EnergyAfterStep(const ReducedSystem& system, const BodyState& state,
                       const Eigen::VectorXd& step) {
  const BodyState moved = system.layout().Retract(state, step);
  return system.Energy(moved, DeformedPositions(system.body(), moved));
}

class BodyReducedSystem : public ::testing::TestWithParam<std::string> {};

// Energy → reduced gradient. The energy is smooth here (all stretches near 1), so central
// differences reach ~1e-9; 1e-6 is the bound and leaves room for round-off.
TEST_P(BodyReducedSystem, ReducedGradientMatchesFiniteDifferences) {
  const Deformed d = MakeDeformed(ParseCoreLock(GetParam()), 11);
  const ReducedSystem system(d.body);
  const Evaluated at = EvaluateAt(system, d.state, HessianKind::kExact);
  EXPECT_NEAR(at.energy, system.Energy(d.state, DeformedPositions(d.body, d.state)),
              1e-12 * std::abs(at.energy));
  auto f = [&](const Eigen::VectorXd& step) { return EnergyAfterStep(system, d.state, step); };
  std::string report;
  const double error = testing::WorstGradientError(
      f, at.gradient, Eigen::VectorXd::Zero(system.size()), 1e-3 * at.gradient.norm(),
      testing::StepSweep(1e-4, 5), 8, 400, 3, &report);
  EXPECT_LT(error, 1e-6) << report;
}

// Gradient → Hessian along directions without a rotation part: there the reduced
// coordinates are Euclidean and the Jacobian of the gradient is exactly K̂.
TEST_P(BodyReducedSystem, ReducedHessianMatchesFiniteDifferencesOfTheGradient) {
  const Deformed d = MakeDeformed(ParseCoreLock(GetParam()), 12);
  const ReducedSystem system(d.body);
  const Evaluated at = EvaluateAt(system, d.state, HessianKind::kExact);
  const ReducedLayout& layout = system.layout();
  auto gradient_after = [&](const Eigen::VectorXd& step) {
    return EvaluateAt(system, layout.Retract(d.state, step), HessianKind::kExact).gradient;
  };
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  std::vector<Eigen::VectorXd> directions;
  for (int k = 0; k < 6; ++k) {
    Eigen::VectorXd dir(system.size());
    for (Eigen::Index i = 0; i < dir.size(); ++i) dir[i] = normal(rng);
    directions.push_back(dir);
  }
  for (Eigen::Index i = 0; i < system.size(); i += 7)
    directions.push_back(Eigen::VectorXd::Unit(system.size(), i));
  for (int j = 0; j < layout.core_count(); ++j)
    directions.push_back(Eigen::VectorXd::Unit(system.size(), layout.core_offset() + j));
  for (Eigen::VectorXd dir : directions) {
    for (int j = 0; j < layout.core_count(); ++j)
      if (layout.core_components()[j] >= 3) dir[layout.core_offset() + j] = 0;  // no rotation
    if (dir.norm() == 0) continue;
    dir.normalize();
    const testing::SweepResult r = testing::CheckJacobianVector(
        gradient_after, Eigen::VectorXd::Zero(system.size()), dir, at.hessian * dir,
        1e-3 * at.hessian.cwiseAbs().maxCoeff(), testing::StepSweep(1e-5, 4));
    EXPECT_LT(r.best_relative_error, 1e-6) << r.report;
  }
}

// Rotation block (with the lever-arm term) by second differences of the energy along pairs
// of directions: d1ᵀK̂d2 = ∂²E(Retract(y, s d1 + t d2))/∂s∂t, exact for the exp-map Hessian.
TEST_P(BodyReducedSystem, ReducedHessianMatchesSecondDifferencesOfTheEnergy) {
  const Deformed d = MakeDeformed(ParseCoreLock(GetParam()), 13);
  const ReducedSystem system(d.body);
  const Evaluated at = EvaluateAt(system, d.state, HessianKind::kExact);
  const ReducedLayout& layout = system.layout();
  const Eigen::Index n = system.size();
  std::mt19937 rng(9);
  std::normal_distribution<double> normal;
  auto random_direction = [&] {
    Eigen::VectorXd dir(n);
    for (Eigen::Index i = 0; i < n; ++i) dir[i] = normal(rng);
    return Eigen::VectorXd(dir.normalized());
  };
  std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> pairs;
  for (int i = 0; i < layout.core_count(); ++i)
    for (int j = i; j < layout.core_count(); ++j)
      pairs.emplace_back(Eigen::VectorXd::Unit(n, layout.core_offset() + i),
                         Eigen::VectorXd::Unit(n, layout.core_offset() + j));
  for (int k = 0; k < 4; ++k) pairs.emplace_back(random_direction(), random_direction());
  const double scale = at.hessian.cwiseAbs().maxCoeff();
  for (const auto& [d1, d2] : pairs) {
    const double analytic = d1.dot(at.hessian * d2);
    double best = INFINITY;
    std::string report;
    for (double t : {1e-4, 3e-5, 1e-5, 3e-6}) {  // truncation ∝ t², round-off ∝ ε|E|/t²
      auto e = [&](double a, double b) {
        return EnergyAfterStep(system, d.state, a * t * d1 + b * t * d2);
      };
      const double fd = (e(1, 1) - e(1, -1) - e(-1, 1) + e(-1, -1)) / (4 * t * t);
      const double error = std::abs(fd - analytic) / std::max(std::abs(analytic), 1e-3 * scale);
      report += "  t=" + std::to_string(t) + " fd=" + std::to_string(fd) +
                " analytic=" + std::to_string(analytic) + "\n";
      best = std::min(best, error);
    }
    EXPECT_LT(best, 1e-6) << report;
  }
}

TEST_P(BodyReducedSystem, ProjectedHessianIsPositiveSemiDefinite) {
  const Deformed d = MakeDeformed(ParseCoreLock(GetParam()), 14);
  const ReducedSystem system(d.body);
  const Evaluated at = EvaluateAt(system, d.state, HessianKind::kProjectedPsd);
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(at.hessian).eigenvalues();
  EXPECT_GE(eigenvalues.minCoeff(), -1e-12 * eigenvalues.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(Locks, BodyReducedSystem,
                         ::testing::Values("none", "tx,tz", "tx,tz,rx,ry", "tx,tz,rx,ry,rz"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == ',') c = '_';
                           return name;
                         });

TEST(Body, RigidMotionGivesZeroElasticEnergyAndForces) {
  LayeredBodyOptions options;
  options.gravity.setZero();
  const LayeredBody body = testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options);
  const ReducedSystem system(body);
  BodyState state = RestState(body);
  state.rotation = RotationExp(Eigen::Vector3d(0.7, -0.4, 1.1));  // a large rotation
  state.centre += Eigen::Vector3d(0.3, 0.2, -0.1);
  const Vertices& rest = body.rest().vertices;
  for (Eigen::Index i = 0; i < body.free_vertices().size(); ++i) {
    const Eigen::Vector3d x = rest.row(body.free_vertices()[i]);
    state.free_displacement.segment<3>(3 * i) =
        state.centre + state.rotation * (x - body.core_centre()) - x;
  }
  const Vertices positions = DeformedPositions(body, state);
  ReducedSystem::Evaluation e;
  system.Evaluate(state, positions, HessianKind::kExact, false, &e);
  // Stresses are ~E·(round-off strain) = 1e4 · 1e-15; forces ~ stress · area (1e-3 m²).
  EXPECT_NEAR(e.energy, 0.0, 1e-12);
  EXPECT_LT(e.vertex_gradient.cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Body, GravityAndWrenchGiveTheHandComputedGradientAtRest) {
  LayeredBodyOptions options;
  options.external_force = Eigen::Vector3d(1, -2, 3);
  options.external_torque = Eigen::Vector3d(0.5, 0.25, -1);
  const LayeredBody body = testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options);
  const ReducedSystem system(body);
  const Evaluated at = EvaluateAt(system, RestState(body), HessianKind::kExact);
  const Eigen::Vector3d g = body.gravity();
  for (Eigen::Index i = 0; i < body.free_vertices().size(); ++i)
    EXPECT_LT(
        (at.gradient.segment<3>(3 * i) + body.vertex_mass()[body.free_vertices()[i]] * g).norm(),
        1e-12);
  // Core: the attached vertices' and the core's weight, the external force; the attached
  // masses are symmetric about the centre so their gravity has no torque.
  double attached_mass = 0;
  for (Eigen::Index a : body.attached_vertices()) attached_mass += body.vertex_mass()[a];
  const Eigen::Index c = system.layout().core_offset();
  EXPECT_LT(
      (at.gradient.segment<3>(c) + (attached_mass + body.core_mass()) * g + options.external_force)
          .norm(),
      1e-12);
  EXPECT_LT((at.gradient.segment<3>(c + 3) + options.external_torque).norm(), 1e-12);
}

TEST(Body, AssemblyIsBitwiseDeterministicAcrossThreadCounts) {
  const Deformed d = MakeDeformed(ParseCoreLock("tx,tz"), 15);
  const ReducedSystem system(d.body);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Evaluated one = EvaluateAt(system, d.state, HessianKind::kProjectedPsd);
  omp_set_num_threads(2);
  const Evaluated two = EvaluateAt(system, d.state, HessianKind::kProjectedPsd);
  omp_set_num_threads(threads);
  EXPECT_EQ(one.energy, two.energy);
  EXPECT_TRUE((one.gradient.array() == two.gradient.array()).all());
  EXPECT_TRUE((one.hessian.array() == two.hessian.array()).all());
  EXPECT_GT(system.colour_count(), 1);
}

TEST(Body, ScaledMassMakesTheFreeFallingHessianPositiveDefinite) {
  const LayeredBody body = testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, {});
  const ReducedSystem system(body);
  const BodyState state = RestState(body);
  const Vertices positions = DeformedPositions(body, state);
  ReducedSystem::Evaluation e;
  system.Evaluate(state, positions, HessianKind::kProjectedPsd, true, &e);
  system.Finalize(state, positions, HessianKind::kProjectedPsd, &e);
  // At rest the six rigid motions have no stiffness: K̂ is singular.
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(DenseSymmetric(e.hessian)).eigenvalues();
  EXPECT_LT(std::abs(eigenvalues[5]), 1e-9 * eigenvalues.maxCoeff());
  system.AddScaledMass(1e3, state, positions, &e.hessian);
  SparseCholesky cholesky;
  cholesky.Analyze(e.hessian);
  EXPECT_TRUE(cholesky.Factorize(e.hessian).ok);
}

}  // namespace
}  // namespace ergo
