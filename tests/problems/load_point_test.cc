#include "problems/load_point.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/contact/support.h"
#include "ergo/design/centre_of_pressure.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/mesh/input_error.h"
#include "problems/chair_scenario.h"
#include "problems/roll_balance.h"
#include "problems/shoe_scenario.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

struct Solved {
  EquilibriumResult result;
  CentreOfPressure cop;
  Eigen::Vector3d load;
};

Solved SolveOnce(const Scenario& scenario) {
  EquilibriumSolver solver(*scenario.body, scenario.design.equilibrium);
  Solved s;
  s.result = solver.Solve(Support(scenario.support), scenario.start);
  s.cop =
      ComputeCentreOfPressure(*scenario.body, s.result.state, solver.last_evaluation().contacts);
  s.load = scenario.body->TotalLoad();
  std::cout << scenario.description << ": " << s.result.BriefReport() << ", CoP at "
            << s.cop.z_fraction << " of the length\n";
  return s;
}

// Moment balance on a flat frictionless sole: every contact force is vertical, so the centre
// of pressure is where the whole load's line of action meets the sole — the stated load
// point. The torque uses the part's rest centre of mass; the deformed one moves by about a
// millimetre (tissue compression, a small pitch) on a 26 cm foot, hence 0.01 of the length.
TEST(Problems, ShoeLoadPointPutsTheCentreOfPressureThereOnAFlatSole) {
  // Under the sanitizers (10–20x slower) one load point; both in Release.
  const std::vector<double> fractions =
      testing::SanitizedBuild() ? std::vector<double>{0.55} : std::vector<double>{0.35, 0.55};
  for (double fraction : fractions) {
    ShoeScenarioOptions options = ShoeScenarioOptions::FromPreset("quick");
    options.load_point = fraction;
    const Solved s = SolveOnce(MakeShoeScenario(options));
    ASSERT_TRUE(s.result.converged) << s.result.FullReport();
    // All of the load is carried by vertical contact forces.
    EXPECT_NEAR(s.cop.normal_force, s.load.norm(), 1e-6 * s.load.norm());
    EXPECT_NEAR(s.cop.z_fraction, fraction, 0.01);
  }
}

// The chair's load point is a fraction of the seat's depth. The torque uses the body's rest
// centre of mass; a 30 kg seated body pitches when its load line is moved back, and its
// centre of mass with it: measured 0.3567 for 0.35 and 0.4500 for 0.45 (3 mm of 0.5 m at
// most), hence 0.01.
TEST(Problems, ChairLoadPointPutsTheCentreOfPressureThere) {
  // Two 30 kg seated solves (20 s here): the shoe's test covers the same code under the
  // sanitizers.
  if (testing::SanitizedBuild()) GTEST_SKIP() << "two chair solves";
  for (double fraction : {0.35, 0.45}) {
    ChairScenarioOptions options = ChairScenarioOptions::FromPreset("quick");
    options.load_point = fraction;
    const Scenario scenario = MakeChairScenario(options);
    const Solved s = SolveOnce(scenario);
    ASSERT_TRUE(s.result.converged) << s.result.FullReport();
    const double back = scenario.support.vertices.col(2).minCoeff();
    const double depth = scenario.support.vertices.col(2).maxCoeff() - back;
    const double at = (s.cop.point.z() - back) / depth;
    std::cout << "chair load point " << fraction << ": centre of pressure at " << at << "\n";
    EXPECT_NEAR(at, fraction, 0.01);
  }
}

TEST(Problems, LoadPointOutsideTheFootIsRefused) {
  ShoeScenarioOptions options = ShoeScenarioOptions::FromPreset("quick");
  options.load_point = 1.5;
  EXPECT_THROW(MakeShoeScenario(options), InputError);
}

// Issue 14: the shipped real scan as a user's foot with the anatomical priors, standing with
// half of 75 kg on a flat sole with the default load point (0.445 of the foot's length). A
// long run (CGAL skin meshing at 8 mm, 1–5 min), so only with ERGO_LONG_TESTS=1 and never
// in CI. What holds: the centre of pressure sits at the load point (moment balance). What
// does not yet: the region shares (rearfoot 40–65 %, midfoot under 25 %). Measured
// (2026-12-04, midfoot tissue 15 kPa): 32 / 39 / 29 % rearfoot / midfoot / forefoot over
// < 0.3, 0.3–0.6 and beyond of the length from the heel (28 / 48 / 24 % at 40 kPa); 30 / 20 /
// 50 % over the arch index's thirds of the footprint without the toes (Cavanagh & Rodgers
// 1987; toes from 0.81); 44.5 % on the rear half (the plate study's split). The load sits
// where the scan's lateral column lies 4.5 mm below the line through the heel's and the
// ball's lowest skin (0.5–0.65 of the length), which a rigid skeleton cannot lift; README.md
// "Scans" gives the figures and what is left. With the fat pads stiffening (alpha 6.82, since
// 2026-12-06): 32.3 / 38.8 / 28.9 %, arch-index thirds 30.7 / 20.1 / 49.2 %, rear half 44.7 %.
// Rolled towards pronation (--shoe_roll, the lateral side up) the shares reach the targets:
// 6 degrees 37.9 / 20.9 / 41.2 %, 11.5 degrees 43.1 / 10.2 / 46.7 %, 15 degrees 45.7 / 5.3 /
// 49.0 %; which roll a person stands at is theirs to state (README "Scans").
TEST(Problems, ScannedFootWithAnatomicalPriorsStandsWithItsCentreOfPressureAtTheLoadPoint) {
  if (std::getenv("ERGO_LONG_TESTS") == nullptr)
    GTEST_SKIP() << "a long run: set ERGO_LONG_TESTS=1";
  const std::string dir = testing::RealScanDir();
  if (dir.empty()) GTEST_SKIP() << "../shared/real-scans is not present";
  ShoeScenarioOptions options = ShoeScenarioOptions::FromPreset("quick");
  options.user_body.skin_surface = dir + "/foot_find_template.obj";
  options.user_body.axes = "y,z,x";
  options.user_body.anatomy.anatomy = Anatomy::kFoot;
  options.user_body.edge_length = 0.008;  // 10 mm pinches the skin between the toes
  options.user_body.total_mass = 1.4;
  options.contact_stiffness = 1.4e9;
  options.load_point = 0.445;
  const Scenario scenario = MakeShoeScenario(options);
  EquilibriumSolver solver(*scenario.body, scenario.design.equilibrium);
  // Level as scanned, then rolled about the length towards pronation (+x, the lateral side,
  // up): the shares at each roll are the README's measurement.
  for (double degrees : {0.0, 6.0, 11.5, 15.0}) {
    const BodyState start = StartAbove(
        *scenario.body, RolledRestState(*scenario.body, degrees * RollBalanceOptions::kDegree),
        scenario.support, options.start_gap, "scan");
    const EquilibriumResult result = solver.Solve(Support(scenario.support), start);
    ASSERT_TRUE(result.converged) << result.FullReport();
    const SurfaceContacts& contacts = solver.last_evaluation().contacts;
    const Vertices& rest = scenario.body->rest().vertices;
    const bool heel_at_min = HeelAtMinZ(rest, HeelEnd::kAuto, "scan");
    const double min_z = rest.col(2).minCoeff(), length = rest.col(2).maxCoeff() - min_z;
    double share[3] = {0, 0, 0}, thirds[3] = {0, 0, 0}, rear_half = 0, total = 0;
    const Skin& skin = scenario.body->skin();
    for (Eigen::Index l = 0; l < skin.vertices.size(); ++l) {
      const double force = contacts.skin_force(l, 1);  // upward on the foot
      if (force <= 0) continue;
      double s = (rest(skin.vertices[l], 2) - min_z) / length;
      if (!heel_at_min) s = 1 - s;
      share[s < 0.3 ? 0 : s < 0.6 ? 1 : 2] += force;
      thirds[s < 0.27 ? 0 : s < 0.54 ? 1 : 2] += force;  // thirds of the 0.81 before the toes
      if (s < 0.5) rear_half += force;
      total += force;
    }
    for (double& region : share) region /= total;
    for (double& region : thirds) region /= total;
    const CentreOfPressure cop = ComputeCentreOfPressure(*scenario.body, result.state, contacts);
    std::cout << "roll " << degrees << " degrees: rearfoot " << share[0] << ", midfoot " << share[1]
              << ", forefoot " << share[2] << "; peak contact at " << 1e3 * result.max_penetration
              << " mm penetration; CoP " << (heel_at_min ? cop.z_fraction : 1 - cop.z_fraction)
              << " of the length\n"
              << "arch-index thirds: rearfoot " << thirds[0] << ", midfoot " << thirds[1]
              << ", forefoot " << thirds[2] << "; rear half " << rear_half / total << "\n";
    EXPECT_NEAR(heel_at_min ? cop.z_fraction : 1 - cop.z_fraction, 0.445, 0.01);
  }
}

}  // namespace
}  // namespace ergo
