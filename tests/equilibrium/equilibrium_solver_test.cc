// The Newton equilibrium against answers known without the code: force and moment balance,
// a tilt that balances an off-centre load, agreement with an independent minimiser
// (Ceres L-BFGS), calibration of the penalty stiffness, and honest failure reports.
#include "ergo/equilibrium/equilibrium_solver.h"

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "ergo/body/core_lock.h"
#include "ergo/contact/stiffness_calibration.h"
#include "ergo/equilibrium/ceres_equilibrium.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"

namespace ergo {
namespace {

// A 10 cm hollow cube of 10 kPa tissue (≈ 1 kg) and a 40 cm x 40 cm slab whose top is y = 0.
LayeredBody CubeBody(const std::string& lock,
                     const Eigen::Vector3d& force = Eigen::Vector3d::Zero(),
                     const Eigen::Vector3d& torque = Eigen::Vector3d::Zero()) {
  LayeredBodyOptions options;
  options.lock = ParseCoreLock(lock);
  options.external_force = force;
  options.external_torque = torque;
  return testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options, Eigen::Vector3d(0, 0.05, 0));
}

Support FlatSupport(double top = 0.0) {
  return Support(MakeBox({-0.2, top - 0.1, -0.2}, {0.2, top, 0.2}, {4, 1, 4}), "flat slab");
}

// κ = 4e6 Pa/m: about 1 mm of sag for the cube's weight on its bottom face's 0.01 m².
EquilibriumOptions Options(double k = 4e6) {
  EquilibriumOptions options;
  options.contact_stiffness = k;
  return options;
}

// Σ over vertices of (x − c) × (force on the vertex), plus the external torque: the net
// moment about the core centre of everything acting on the body.
Eigen::Vector3d NetMoment(const LayeredBody& body, const EquilibriumSolver& solver,
                          const EquilibriumResult& result, const Support& support) {
  TotalPotential::Evaluation e;
  solver.potential().Evaluate(result.state, support, HessianKind::kExact, false, nullptr, &e);
  const Eigen::Vector3d c = result.state.centre;
  Eigen::Vector3d moment = body.options().external_torque;
  const Eigen::VectorXi& skin = body.skin().vertices;
  for (Eigen::Index l = 0; l < skin.size(); ++l)
    moment +=
        (e.positions.row(skin[l]).transpose() - c).cross(e.contacts.skin_force.row(l).transpose());
  for (Eigen::Index v = 0; v < e.positions.rows(); ++v)
    moment += (e.positions.row(v).transpose() - c).cross(body.vertex_mass()[v] * body.gravity());
  return moment;
}

TEST(Equilibrium, ContactForceBalancesTheLoadAndMomentsBalanceAboutTheCore) {
  const LayeredBody body = CubeBody("tx,tz", Eigen::Vector3d(0, -5, 0));
  const Support support = FlatSupport();
  EquilibriumSolver solver(body, Options());
  const EquilibriumResult result = solver.Solve(support, TranslatedRestState(body, {0, 0.002, 0}));
  ASSERT_TRUE(result.converged) << result.FullReport();
  // The residual is ≤ 1e-8 of the load; the force balance along the free translation (y)
  // holds to that order. The locked tx, tz carry whatever sideways force the dimpled skin
  // meets (the support's vertex under the cube pushes on tilted skin triangles).
  const Eigen::Vector3d load = body.TotalLoad();
  EXPECT_LT(std::abs(result.contact_force.y() + load.y()), 1e-6 * load.norm())
      << result.FullReport();
  const double lever = 0.05;
  EXPECT_LT(NetMoment(body, solver, result, support).norm(), 1e-6 * load.norm() * lever);
  EXPECT_GT(result.contact_vertices, 0);
  EXPECT_GT(result.max_penetration, 0);
}

// One-way, the Newton iterations leave the score-only support samples out; the solver fills
// them in at the state it returns, so what the score reads there is what an evaluation of
// that state with its samples gives.
TEST(Equilibrium, TheReturnedStateCarriesItsSupportSamples) {
  const LayeredBody body = CubeBody("tx,tz", Eigen::Vector3d(0, -5, 0));
  const Support support(MakeBox({-0.2, -0.1, -0.2}, {0.2, 0, 0.2}, {16, 1, 16}), "fine slab");
  EquilibriumOptions options = Options();
  ASSERT_FALSE(options.contact_support_springs) << "the test is about one-way contact";
  EquilibriumSolver solver(body, options);
  const EquilibriumResult result = solver.Solve(support, TranslatedRestState(body, {0, 0.002, 0}));
  ASSERT_TRUE(result.converged) << result.FullReport();
  const SurfaceContacts& kept = solver.last_evaluation().contacts;
  TotalPotential::Evaluation fresh;
  solver.potential().Evaluate(result.state, support, HessianKind::kExact, true, nullptr, &fresh);
  ASSERT_TRUE(kept.support_sampled);
  ASSERT_GT(fresh.contacts.support.size(), 0) << "slab vertices must poke into the skin";
  ASSERT_EQ(kept.support.size(), fresh.contacts.support.size());
  for (int i = 0; i < kept.support.size(); ++i) {
    EXPECT_EQ(kept.support.contacts[i].point, fresh.contacts.support.contacts[i].point);
    EXPECT_NEAR(kept.support.contacts[i].spring.energy,
                fresh.contacts.support.contacts[i].spring.energy,
                1e-12 * fresh.contacts.support.energy);
  }
  EXPECT_NEAR((kept.support_load - fresh.contacts.support_load).cwiseAbs().maxCoeff(), 0.0,
              1e-12 * fresh.contacts.support_load.sum());
}

TEST(Equilibrium, AnOffCentreForceTiltsTheBodyUntilTheContactMomentBalancesIt) {
  // 20 N pushing down 2 cm right of the core centre: τ = r × F = (0, 0, −0.4) N·m.
  const Eigen::Vector3d force(0, -20, 0), arm(0.02, 0, 0);
  const LayeredBody body = CubeBody("tx,tz,rx,ry", force, arm.cross(force));
  const Support support = FlatSupport();
  EquilibriumSolver solver(body, Options());
  const EquilibriumResult result = solver.Solve(support, TranslatedRestState(body, {0, 0.002, 0}));
  ASSERT_TRUE(result.converged) << result.FullReport();
  // Pitch about z, right side down: a negative rotation angle about z.
  const double angle = Eigen::AngleAxisd(result.state.rotation).angle() *
                       Eigen::AngleAxisd(result.state.rotation).axis().z();
  EXPECT_LT(angle, -1e-3);
  EXPECT_LT(std::abs(NetMoment(body, solver, result, support).z()),
            1e-6 * body.TotalLoad().norm() * 0.05);
  // The centre of pressure moved right of the core centre.
  TotalPotential::Evaluation e;
  solver.potential().Evaluate(result.state, support, HessianKind::kExact, false, nullptr, &e);
  double weighted = 0, total = 0;
  for (Eigen::Index l = 0; l < body.skin().vertices.size(); ++l) {
    weighted += e.positions(body.skin().vertices[l], 0) * e.contacts.skin_force(l, 1);
    total += e.contacts.skin_force(l, 1);
  }
  EXPECT_GT(weighted / total, result.state.centre.x() + 0.005);
}

TEST(Equilibrium, NewtonAndCeresLbfgsReachTheSameEquilibrium) {
  const LayeredBody body = CubeBody("tx,tz");
  const Support support = FlatSupport();
  EquilibriumSolver solver(body, Options());
  const EquilibriumResult newton = solver.Solve(support, TranslatedRestState(body, {0, 0.001, 0}));
  ASSERT_TRUE(newton.converged) << newton.FullReport();
  // L-BFGS from a nearby contact state (not from free fall, where it would crawl).
  BodyState start = newton.state;
  start.centre.y() += 2e-4;
  start.free_displacement.array() += 1e-4;
  ceres::GradientProblemSolver::Options options;
  options.line_search_direction_type = ceres::LBFGS;
  options.max_num_iterations = 20000;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-13;
  options.parameter_tolerance = 1e-16;
  const EquilibriumResult lbfgs =
      SolveEquilibriumWithCeres(solver.potential(), support, start, 1e-8, options);
  const Vertices a = DeformedPositions(body, newton.state),
                 b = DeformedPositions(body, lbfgs.state);
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-6) << lbfgs.BriefReport() << " / " << lbfgs.message;
}

TEST(Equilibrium, CalibrationHitsThreeTenthsOfAMillimetrePenetration) {
  const LayeredBody body = CubeBody("tx,tz");
  const Support support = FlatSupport();
  EquilibriumSolver solver(body, Options());
  BodyState warm = TranslatedRestState(body, {0, 0.001, 0});
  auto penetration_at = [&](double k) -> std::optional<double> {
    solver.set_contact_stiffness(k);
    const EquilibriumResult r = solver.Solve(support, warm);
    if (!r.converged) return std::nullopt;
    warm = r.state;
    return r.max_penetration;
  };
  CalibrationOptions calibration_options;
  calibration_options.initial_stiffness = 4e6;  // κ, Pa/m
  const CalibrationResult calibration =
      CalibrateStiffness(penetration_at, 3e-4, calibration_options);
  ASSERT_TRUE(calibration.converged) << calibration.BriefReport();
  EXPECT_NEAR(calibration.penetration, 3e-4, 3e-5) << calibration.BriefReport();
  // Re-solving with the calibrated k reproduces the penetration.
  solver.set_contact_stiffness(calibration.stiffness);
  EXPECT_NEAR(solver.Solve(support, warm).max_penetration, 3e-4, 3e-5);
}

TEST(Equilibrium, ABodyThatNeverMeetsTheSupportEndsWithANoContactReport) {
  const LayeredBody body = CubeBody("tx,tz");
  const Support beside = Support(MakeBox({1, -0.1, 1}, {1.4, 0, 1.4}, {2, 1, 2}), "slab aside");
  EquilibriumSolver solver(body, Options());
  const EquilibriumResult result = solver.Solve(beside, TranslatedRestState(body, {0, 0.01, 0}));
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.status, EquilibriumStatus::kNoContact) << result.FullReport();
  EXPECT_NE(result.message.find("no contact"), std::string::npos);
  EXPECT_LT(result.iterations, 20);
}

TEST(Equilibrium, FreeHorizontalTranslationOnAFlatSupportIsRefusedWithItsCause) {
  const LayeredBody body = CubeBody("none");
  const Support support = FlatSupport();
  EquilibriumSolver solver(body, Options());
  const EquilibriumResult result = solver.Solve(support, TranslatedRestState(body, {0, 0.001, 0}));
  EXPECT_EQ(result.status, EquilibriumStatus::kUnconstrained) << result.FullReport();
  EXPECT_NE(result.message.find("tx, tz"), std::string::npos) << result.message;
}

TEST(Equilibrium, WarmStartAfterATenthOfAMillimetreSupportChangeNeedsFewIterations) {
  const LayeredBody body = CubeBody("tx,tz");
  EquilibriumSolver solver(body, Options());
  const EquilibriumResult cold =
      solver.Solve(FlatSupport(), TranslatedRestState(body, {0, 0.001, 0}));
  ASSERT_TRUE(cold.converged);
  const EquilibriumResult warm = solver.Solve(FlatSupport(1e-4), cold.state);
  ASSERT_TRUE(warm.converged) << warm.FullReport();
  EXPECT_LE(warm.iterations, 6);
  EXPECT_LT(warm.iterations, cold.iterations);
  EXPECT_NEAR(warm.state.centre.y() - cold.state.centre.y(), 1e-4, 1e-6);
}

// The active-set counts are a bookkeeping identity: from a start out of contact every vertex
// in contact at the end entered once more than it left, and the per-iteration reports add
// up to the result's totals. A fine slab (16 x 16 cells under the 3 x 3 cube face) makes the
// skin cross face and edge regions while it settles.
TEST(Equilibrium, ActiveSetChangesAddUpToTheFinalContactSet) {
  const LayeredBody body = CubeBody("tx,tz", Eigen::Vector3d(0, -5, 0));
  const Support support(MakeBox({-0.2, -0.1, -0.2}, {0.2, 0, 0.2}, {16, 1, 16}), "fine slab");
  EquilibriumOptions options = Options();
  int entered = 0, left = 0, switched = 0, reports = 0;
  options.progress = [&](const NewtonIterationReport& r) {
    EXPECT_EQ(r.iteration, reports++);
    entered += r.contacts_entered;
    left += r.contacts_left;
    switched += r.feature_switches;
  };
  EquilibriumSolver solver(body, options);
  const EquilibriumResult result = solver.Solve(support, TranslatedRestState(body, {0, 0.002, 0}));
  ASSERT_TRUE(result.converged) << result.FullReport();
  ASSERT_GT(result.contact_vertices, 0);
  EXPECT_EQ(result.contacts_entered - result.contacts_left, result.contact_vertices);
  // The last iterate (the converged one) is counted in the result but takes no step, so it
  // reports nothing: the reports cover all but its changes.
  EXPECT_EQ(reports, result.iterations);
  EXPECT_LE(entered, result.contacts_entered);
  EXPECT_LE(left, result.contacts_left);
  EXPECT_LE(switched, result.feature_switches);
  EXPECT_GT(entered, 0);
  // Solving again from the converged state: nothing enters beyond the set already there,
  // nothing leaves, nothing switches.
  const EquilibriumResult again = solver.Solve(support, result.state);
  ASSERT_TRUE(again.converged) << again.FullReport();
  EXPECT_EQ(again.iterations, 0);
  EXPECT_EQ(again.contacts_entered, result.contact_vertices);
  EXPECT_EQ(again.contacts_left, 0);
  EXPECT_EQ(again.feature_switches, 0);
}

// A residual held below the stalled tolerance for stall_iterations iterates in a row is
// accepted as converged, with its own status and a message that says which tolerance it met;
// the state is the strict solve's to within what that residual allows. The stall is forced
// here by a loose stalled tolerance (1e-3 of the load, two iterates); on the paper chair it
// is a faceted support's crease (README, Performance).
TEST(Equilibrium, AResidualHeldBelowTheStalledToleranceIsAcceptedAndSaysSo) {
  const LayeredBody body = CubeBody("tx,tz");
  const BodyState start = TranslatedRestState(body, {0, 0.01, 0});
  EquilibriumSolver strict(body, Options());
  const EquilibriumResult reference = strict.Solve(FlatSupport(), start);
  ASSERT_EQ(reference.status, EquilibriumStatus::kConverged) << reference.FullReport();

  EquilibriumOptions options = Options();
  options.stalled_relative_tolerance = 1e-3;
  options.stall_iterations = 2;
  EquilibriumSolver loose(body, options);
  const EquilibriumResult stalled = loose.Solve(FlatSupport(), start);
  std::cout << stalled.BriefReport() << "\n" << stalled.message << "\n";
  ASSERT_EQ(stalled.status, EquilibriumStatus::kStalled) << stalled.FullReport();
  EXPECT_TRUE(stalled.converged);
  EXPECT_STREQ(EquilibriumStatusName(stalled.status), "converged (stalled)");
  EXPECT_NE(stalled.message.find("stalled: 2 iterations within 0.001"), std::string::npos)
      << stalled.message;
  EXPECT_LE(stalled.relative_residual, 1e-3);
  EXPECT_GT(stalled.relative_residual, options.relative_tolerance);
  EXPECT_LT(stalled.iterations, reference.iterations);
  // Near the strict equilibrium: the core's height within 2 % of its sag (the contact's
  // stiffness is linear, so a residual of 1e-3 of the load is about 1e-3 of the sag; the
  // tissue's is stiffer, not softer).
  const double sag = RestState(body).centre.y() - reference.state.centre.y();
  ASSERT_GT(sag, 1e-4) << "the cube rests on the slab's top at its rest pose";
  EXPECT_NEAR(stalled.state.centre.y(), reference.state.centre.y(), 0.02 * sag);

  // stall_iterations = 0 turns the acceptance off: the strict tolerance or nothing.
  options.stall_iterations = 0;
  EquilibriumSolver off(body, options);
  EXPECT_EQ(off.Solve(FlatSupport(), start).status, EquilibriumStatus::kConverged);
}

TEST(Equilibrium, AnIterationCapIsReportedNotHidden) {
  const LayeredBody body = CubeBody("tx,tz");
  EquilibriumOptions options = Options();
  options.max_iterations = 2;
  EquilibriumSolver solver(body, options);
  const EquilibriumResult result =
      solver.Solve(FlatSupport(), TranslatedRestState(body, {0, 0.01, 0}));
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.status, EquilibriumStatus::kIterationCap);
  EXPECT_NE(result.BriefReport().find("iteration cap"), std::string::npos);
}

}  // namespace
}  // namespace ergo
