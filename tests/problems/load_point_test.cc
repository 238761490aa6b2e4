#include "problems/load_point.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/contact/support.h"
#include "ergo/design/centre_of_pressure.h"
#include "ergo/design/lengthwise_shares.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/mesh/input_error.h"
#include "problems/chair_scenario.h"
#include "problems/roll_balance.h"
#include "problems/shoe_scenario.h"
#include "problems/stance_roll.h"
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

// Issue 14's standing split, on ergo's own foot: the generated foot on a flat sole with the
// default load point (0.445 of its length from the heel, quiet standing, Teranishi et al.
// 2013) carries 40–65 % of its load under the rearfoot (< 30 % of the length) and under 25 %
// under the midfoot (30–60 %), as feet standing barefoot do (rearfoot 54–55 % of 416 adults on
// a pressure plate, J Physiol Anthropol 2020; midfoot 8 %, Cavanagh et al. 1987). Measured
// 2026-12-07: 51.1 / 0.0 / 48.9 %; the arch (the core 35 mm above the plantar line) does not
// touch. With the load through the core's centre (the default before) the centre of pressure
// was at 0.348 and the rearfoot carried 69.1 %, over the range. The shipped scan does not
// meet the split level (README "Scans"): its lateral border is its lowest skin.
TEST(Problems, GeneratedFootWithTheDefaultLoadPointSplitsItsLoadAsStandingFeetDo) {
  // Two quick-shoe equilibria (4 s here, a minute under the sanitizers, whose CI stage is near
  // its budget): the load-point test above runs the same code there.
  if (testing::SanitizedBuild()) GTEST_SKIP() << "two quick-shoe equilibria";
  const ShoeScenarioOptions options = ShoeScenarioOptions::FromPreset("quick");
  ASSERT_TRUE(options.load_point.has_value());
  EXPECT_EQ(*options.load_point, 0.445);
  const Scenario scenario = MakeShoeScenario(options);
  EquilibriumSolver solver(*scenario.body, scenario.design.equilibrium);
  const EquilibriumResult result = solver.Solve(Support(scenario.support), scenario.start);
  ASSERT_TRUE(result.converged) << result.FullReport();
  const SurfaceContacts& contacts = solver.last_evaluation().contacts;
  ASSERT_EQ(scenario.regions.names, (std::vector<std::string>{"rearfoot", "midfoot", "forefoot"}));
  EXPECT_TRUE(scenario.regions.from_min_z);  // the generated foot's heel is at its smallest z
  const LengthwiseShares split =
      ComputeLengthwiseShares(*scenario.body, contacts, scenario.regions.ends, true);
  ASSERT_EQ(split.shares.size(), 3u);
  std::cout << "generated foot, load point 0.445: rearfoot " << split.shares[0] << ", midfoot "
            << split.shares[1] << ", forefoot " << split.shares[2] << "\n";
  EXPECT_GE(split.shares[0], 0.40);
  EXPECT_LE(split.shares[0], 0.65);
  EXPECT_LT(split.shares[1], 0.25);
  const CentreOfPressure cop = ComputeCentreOfPressure(*scenario.body, result.state, contacts);
  EXPECT_NEAR(cop.z_fraction, 0.445, 0.01);

  // The load through the core's centre (--shoe_load_point=none, the default before): the
  // centre of pressure falls back to about a third of the length and the heel takes too much.
  ShoeScenarioOptions centred = options;
  centred.load_point.reset();
  const Scenario old = MakeShoeScenario(centred);
  EquilibriumSolver old_solver(*old.body, old.design.equilibrium);
  const EquilibriumResult old_result = old_solver.Solve(Support(old.support), old.start);
  ASSERT_TRUE(old_result.converged) << old_result.FullReport();
  const SurfaceContacts& old_contacts = old_solver.last_evaluation().contacts;
  const LengthwiseShares old_split =
      ComputeLengthwiseShares(*old.body, old_contacts, old.regions.ends, true);
  std::cout << "through the core's centre: rearfoot " << old_split.shares[0] << ", CoP "
            << ComputeCentreOfPressure(*old.body, old_result.state, old_contacts).z_fraction
            << "\n";
  EXPECT_GT(old_split.shares[0], 0.65);
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
// 49.0 %; which roll a person stands at is theirs to state (README "Scans"). The footprint's
// arch index (Cavanagh & Rodgers 1987; normal 0.21–0.26) says why: 0.286 level, a low arch,
// then 0.274, 0.250 and 0.235 (2026-12-07). The generated foot, whose arch does not touch,
// meets the split level (the test above). At the stance roll (its heel stood at the adults'
// mean resting calcaneal stance, 6.07 degrees everted: 5.16 degrees here; later on 2026-12-07)
// 37.1 / 23.0 / 39.9 %, arch index 0.273: the midfoot's target met, the rearfoot's not.
TEST(Problems, ScannedFootWithAnatomicalPriorsStandsWithItsCentreOfPressureAtTheLoadPoint) {
  if (std::getenv("ERGO_LONG_TESTS") == nullptr)
    GTEST_SKIP() << "a long run: set ERGO_LONG_TESTS=1";
  const std::string dir = testing::RealScanDir();
  if (dir.empty()) GTEST_SKIP() << "../shared/real-scans is not present";
  ShoeScenarioOptions options = ShoeScenarioOptions::FromPreset("quick");
  // ERGO_SCAN_FILE: another scan in the same axes, e.g. a posed copy (tools/pose_foot_scan.py,
  // README "Scans": the standing-pose table).
  const char* scan_file = std::getenv("ERGO_SCAN_FILE");
  options.user_body.skin_surface =
      scan_file != nullptr ? std::string(scan_file) : dir + "/foot_find_template.obj";
  options.user_body.axes = "y,z,x";
  options.user_body.anatomy.anatomy = Anatomy::kFoot;
  options.user_body.edge_length = 0.008;  // 10 mm pinches the skin between the toes
  options.user_body.total_mass = 1.4;
  options.contact_stiffness = 1.4e9;
  options.load_point = 0.445;
  ScenarioBuildReport report;
  const Scenario scenario = MakeShoeScenario(options, &report);  // at the stance (auto)
  EquilibriumSolver solver(*scenario.body, scenario.design.equilibrium);
  // Level as scanned, then rolled about the length towards pronation (+x, the lateral side,
  // up): the shares at each roll are the README's measurement.
  // "stance": the roll that stands the heel's bisector at the adults' mean resting calcaneal
  // stance (problems/stance_roll.h; 5.16 degrees, the heel bisected on the scan).
  // ERGO_SCAN_ROLLS: other rolls, in degrees or stance, separated by spaces (e.g. "0 2 4").
  std::vector<std::string> rolls = {"0", "stance", "6", "11.5", "15"};
  if (const char* text = std::getenv("ERGO_SCAN_ROLLS")) {
    rolls.clear();
    std::istringstream in(text);
    for (std::string roll; in >> roll;) rolls.push_back(roll);
    ASSERT_FALSE(rolls.empty()) << "ERGO_SCAN_ROLLS='" << text << "' holds no roll";
  }
  for (const std::string& roll : rolls) {
    double degrees = 0;
    if (roll == "stance") {  // the scenario's own: the heel bisected on the scan as read
      std::cout << report.roll << "\n";
      ASSERT_FALSE(report.roll.empty());
      degrees = report.roll_radians / StanceRoll::kDegree;
    } else {
      char* end = nullptr;
      degrees = std::strtod(roll.c_str(), &end);
      ASSERT_TRUE(end != roll.c_str() && *end == '\0') << "ERGO_SCAN_ROLLS: '" << roll << "'";
    }
    const BodyState start = StartAbove(
        *scenario.body, RolledRestState(*scenario.body, degrees * RollBalanceOptions::kDegree),
        scenario.support, options.start_gap, "scan");
    const EquilibriumResult result = solver.Solve(Support(scenario.support), start);
    ASSERT_TRUE(result.converged) << result.FullReport();
    const SurfaceContacts& contacts = solver.last_evaluation().contacts;
    const Vertices& rest = scenario.body->rest().vertices;
    const bool heel_at_min = HeelAtMinZ(rest, HeelEnd::kAuto, "scan");
    const double min_z = rest.col(2).minCoeff(), length = rest.col(2).maxCoeff() - min_z;
    auto split = [&](const std::vector<double>& ends) {
      return ComputeLengthwiseShares(*scenario.body, contacts, ends, heel_at_min).shares;
    };
    const std::vector<double> share = split(FootRegionEnds());
    const std::vector<double> thirds = split({0.27, 0.54, 1});  // of the 0.81 before the toes
    const double rear_half = split({0.5, 1})[0];
    // The arch index of the footprint (Cavanagh & Rodgers 1987): the contact area of the middle
    // third of its length (toes excluded; here they carry nothing) over the whole; 0.21–0.26
    // for a normal arch, above for a low one.
    const Skin& skin = scenario.body->skin();
    auto fraction = [&](Eigen::Index l) {
      const double s = (rest(skin.vertices[l], 2) - min_z) / length;
      return heel_at_min ? s : 1 - s;
    };
    double begin = 1, end = 0, area[3] = {0, 0, 0};
    for (Eigen::Index l = 0; l < skin.vertices.size(); ++l) {
      if (contacts.skin_force(l, 1) <= 0) continue;
      begin = std::min(begin, fraction(l));
      end = std::max(end, fraction(l));
    }
    for (Eigen::Index l = 0; l < skin.vertices.size(); ++l) {
      if (contacts.skin_force(l, 1) <= 0) continue;
      const double t = (fraction(l) - begin) / (end - begin);
      area[t < 1.0 / 3 ? 0 : t < 2.0 / 3 ? 1 : 2] += skin.rest_areas(l);
    }
    const double footprint = area[0] + area[1] + area[2];
    const CentreOfPressure cop = ComputeCentreOfPressure(*scenario.body, result.state, contacts);
    std::cout << "roll " << degrees << " degrees: rearfoot " << share[0] << ", midfoot " << share[1]
              << ", forefoot " << share[2] << "; peak contact at " << 1e3 * result.max_penetration
              << " mm penetration; CoP " << (heel_at_min ? cop.z_fraction : 1 - cop.z_fraction)
              << " of the length\n"
              << "arch-index thirds: rearfoot " << thirds[0] << ", midfoot " << thirds[1]
              << ", forefoot " << thirds[2] << "; rear half " << rear_half << "\n"
              << "footprint " << begin << "–" << end << " of the length, " << 1e4 * footprint
              << " cm², arch index " << area[1] / footprint << "\n";
    EXPECT_NEAR(heel_at_min ? cop.z_fraction : 1 - cop.z_fraction, 0.445, 0.01);
  }
}

}  // namespace
}  // namespace ergo
