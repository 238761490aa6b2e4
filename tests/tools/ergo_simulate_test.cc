// ergo_simulate end to end: a ball built by ergo_body resting on a slab — outputs, force
// balance, calibrated penetration, honest failure reports and clear input errors.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/mesh/json.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"
#include "tools/common/child_process.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

struct CommandResult {
  int status = -1;
  std::string output;
};

CommandResult RunCommand(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  char buffer[4096];
  while (fgets(buffer, sizeof(buffer), pipe)) result.output += buffer;
  const int status = pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// The command's stdout and stderr apart (RunCommand merges them).
struct SplitResult {
  int status = -1;
  std::string out, err;
};

SplitResult RunSplit(const std::string& command, const std::string& dir) {
  const std::string out = dir + "/stdout.txt", err = dir + "/stderr.txt";
  const int raw = std::system((command + " >" + out + " 2>" + err).c_str());
  SplitResult result;
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  auto slurp = [](const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  result.out = slurp(out);
  result.err = slurp(err);
  return result;
}

// One ball body and one slab for all tests (building the body takes a second).
class ToolsSimulate : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(testing::MakeScratchDir("simulate"));
    const CommandResult build =
        RunCommand("timeout 120 " ERGO_BIN_DIR
                   "/ergo_body build --shape=sphere_shell --outer_radius=0.05 "
                   "--core_radius=0.03 --youngs_modulus=1e4 --edge_length=0.012 --out=" +
                   *dir_ + "/ball");
    ASSERT_EQ(build.status, 0) << build.output;
    // A slab whose top is 1 cm below the ball (centred at the origin), in millimetres.
    TriMesh slab = MakeBox({-150, -110, -150}, {150, -60, 150}, {2, 1, 2});
    WriteTriMesh(*dir_ + "/slab_mm.stl", slab);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  // The pictures take a second or two of matplotlib per run: only the test of the pressure
  // map asks for them.
  static std::string Simulate(const std::string& extra, const std::string& out,
                              bool pictures = false) {
    return "timeout 300 " ERGO_BIN_DIR "/ergo_simulate --body=" + *dir_ +
           "/ball --support=" + *dir_ +
           "/slab_mm.stl --unit=mm --lock=tx,tz,rx,ry,rz --out=" + *dir_ + "/" + out +
           (pictures ? " " : " --plot=false ") + extra;
  }
  static std::string* dir_;
};
std::string* ToolsSimulate::dir_ = nullptr;

TEST_F(ToolsSimulate, CalibratedRunBalancesTheLoadAndWritesEveryOutput) {
  const CommandResult run = RunCommand(Simulate("--contact_stiffness=auto", "auto"));
  ASSERT_EQ(run.status, 0) << run.output;
  for (const char* file : {"body_deformed.vtu", "support.vtu", "summary.json"})
    EXPECT_TRUE(fs::exists(*dir_ + "/auto/" + file)) << file;
  const Json summary = ReadJsonFile(*dir_ + "/auto/summary.json");
  EXPECT_TRUE(GetBool(summary, "converged", "summary"));
  const Json& force = GetMember(summary, "total_contact_force_N", "summary");
  const Json& load = GetMember(summary, "load_N", "summary");
  // y is the one free translation (the lock holds tx, tz and the rotations, which carry any
  // sideways push of the ball's faceted skin on the slab's vertices).
  EXPECT_NEAR(force.at(1).get<double>(), -load.at(1).get<double>(),
              1e-6 * std::abs(load.at(1).get<double>()));
  EXPECT_LT(std::hypot(force.at(0).get<double>(), force.at(2).get<double>()),
            1e-2 * std::abs(load.at(1).get<double>()));
  // The calibration's acceptance band (0.3 mm ± 0.03 mm).
  EXPECT_NEAR(GetNumber(summary, "max_penetration_m", "summary"), 3e-4, 3e-5);
  EXPECT_GT(GetNumber(summary, "peak_pressure_Pa", "summary"), 0);
  EXPECT_GT(GetNumber(summary, "contact_area_m2", "summary"), 0);
  EXPECT_GT(GetNumber(summary, "contact_stiffness_Pa_per_m", "summary"), 0);
  // A 5 mm plate under the ball reads its largest cell under the centre of pressure (the ball
  // presses symmetrically about it), within a pitch; and the run says what it read.
  const Json& plate = GetMember(summary, "plate_peak", "summary");
  EXPECT_GT(GetNumber(plate, "pressure_Pa", "plate_peak"), 0);
  EXPECT_EQ(GetNumber(plate, "pitch_m", "plate_peak"), 0.005);
  const Json& cell = GetMember(plate, "cell_centre_xz_m", "plate_peak");
  const Json& cop = GetMember(summary, "centre_of_pressure_m", "summary");
  EXPECT_LE(std::hypot(cell.at(0).get<double>() - cop.at(0).get<double>(),
                       cell.at(1).get<double>() - cop.at(2).get<double>()),
            0.005);
  EXPECT_NE(run.output.find("a 5 mm pressure plate under the skin would read"), std::string::npos)
      << run.output;
  // The ball's own weight squeezes its layer mildly: nothing near the material's threshold.
  const Json& squeeze = GetMember(summary, "tissue_compression", "summary");
  EXPECT_EQ(GetNumber(squeeze, "tets_beyond_inversion_threshold", "tissue_compression"), 0);
  EXPECT_GT(GetNumber(squeeze, "min_principal_stretch", "tissue_compression"), 0.5);
  EXPECT_EQ(run.output.find("crushed"), std::string::npos) << run.output;
  std::ifstream vtu(*dir_ + "/auto/body_deformed.vtu");
  std::string first;
  std::getline(vtu, first);
  EXPECT_NE(first.find("<?xml"), std::string::npos);
}

// 300 N pressed through the ball's 2 cm layer of 10 kPa tissue crushes it under the core
// (about 300 N over 30 cm² is 100 kPa, ten times E): the run still converges, and says on
// stderr and in summary.json how many tets went beyond the material's inversion threshold and
// where the worst is: under the core, within 2 cm of the ball's axis and 1 cm of the slab's
// top (y = −0.06 m; the penalty lets the crushed skin sink a few millimetres into it).
TEST_F(ToolsSimulate, ACrushedLayerIsReportedWithWhereItIs) {
  const CommandResult run =
      RunCommand(Simulate("--contact_stiffness=1e9 --external_force=0,-300,0", "crushed"));
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("crushed beyond its material law"), std::string::npos) << run.output;
  const Json summary = ReadJsonFile(*dir_ + "/crushed/summary.json");
  const Json& squeeze = GetMember(summary, "tissue_compression", "summary");
  EXPECT_GT(GetNumber(squeeze, "tets_beyond_inversion_threshold", "tissue_compression"), 0);
  EXPECT_LT(GetNumber(squeeze, "min_principal_stretch", "tissue_compression"), 0.1);
  EXPECT_EQ(GetNumber(squeeze, "inversion_threshold", "tissue_compression"), 0.1);
  const Json& worst = GetMember(squeeze, "worst_point_m", "tissue_compression");
  const double x = worst.at(0).get<double>(), y = worst.at(1).get<double>(),
               z = worst.at(2).get<double>();
  EXPECT_LT(std::hypot(x, z), 0.02);
  EXPECT_NEAR(y, -0.06, 0.01);
  // The pressure map marks each of those tets.
  const Json plot = ReadJsonFile(*dir_ + "/crushed/plot_data.json");
  EXPECT_EQ(
      GetMember(plot, "crushed_points2d", "plot_data").size(),
      GetMember(squeeze, "tets_beyond_inversion_threshold", "tissue_compression").get<size_t>());
}

// `ergo_mesh box` writes the slab the suite builds with MakeBox, vertex for vertex (its OBJ
// keeps 17 significant digits: 1e-9 mm covers the millimetre conversion), and the ball stands
// on it as on the suite's own slab.
TEST_F(ToolsSimulate, ErgoMeshBoxWritesTheSlabToStandOn) {
  const std::string box = *dir_ + "/box_mm.obj";
  const CommandResult made =
      RunCommand("timeout 60 " ERGO_BIN_DIR "/ergo_mesh box " + box +
                 " --lo=-0.15,-0.11,-0.15 --hi=0.15,-0.06,0.15 --cells=2,1,2 --out_unit=mm");
  ASSERT_EQ(made.status, 0) << made.output;
  const TriMesh written = ReadTriMesh(box);
  const TriMesh expected = MakeBox({-150, -110, -150}, {150, -60, 150}, {2, 1, 2});
  ASSERT_EQ(written.vertices.rows(), expected.vertices.rows());
  ASSERT_EQ(written.triangles, expected.triangles);
  EXPECT_LT((written.vertices - expected.vertices).cwiseAbs().maxCoeff(), 1e-9);
  const CommandResult check =
      RunCommand("timeout 60 " ERGO_BIN_DIR "/ergo_mesh check " + box + " --closed --unit=mm");
  EXPECT_EQ(check.status, 0) << check.output;
  const CommandResult stand = RunCommand(
      "timeout 300 " ERGO_BIN_DIR "/ergo_simulate --plot=false --body=" + *dir_ +
      "/ball --support=" + box +
      " --unit=mm --lock=tx,tz,rx,ry,rz --contact_stiffness=1e8 --out=" + *dir_ + "/on_box");
  EXPECT_EQ(stand.status, 0) << stand.output;
}

// The pressure map behind the pictures (plot_data.json): one pressure per skin vertex whose
// largest is the summary's peak, seen along the load (x, z for gravity along -y); every skin
// vertex in contact is a corner of a drawn triangle (those facing the support: with the facing
// test turned round, the contact patch's inner vertices would be on none); the centre of
// pressure under the ball's centre, to 1 mm (1 % of its diameter: the faceted mesh's asymmetry,
// measured 0.2 mm along z). The pictures themselves when matplotlib is there.
TEST_F(ToolsSimulate, ThePressureMapIsTheSkinSeenFromTheSupportWithItsPictures) {
  const CommandResult run = RunCommand(Simulate("--contact_stiffness=1e8", "map", true));
  ASSERT_EQ(run.status, 0) << run.output;
  const std::string out = *dir_ + "/map";
  const Json summary = ReadJsonFile(out + "/summary.json");
  const Json data = ReadJsonFile(out + "/plot_data.json");
  EXPECT_EQ(GetString(data, "tool", "plot_data"), "ergo_simulate");
  const Json& axes = GetMember(GetMember(data, "view", "plot_data"), "axes", "view");
  EXPECT_EQ(axes.at(0).get<std::string>(), "x");
  EXPECT_EQ(axes.at(1).get<std::string>(), "z");
  const Json& skin = GetMember(data, "skin", "plot_data");
  const Json& points = GetMember(skin, "points2d", "skin");
  const Json& pressure = GetMember(skin, "pressure", "skin");
  const Json& triangles = GetMember(skin, "triangles", "skin");
  ASSERT_EQ(points.size(), pressure.size());
  ASSERT_GT(triangles.size(), 0u);
  double peak = 0;
  for (const Json& p : pressure) peak = std::max(peak, p.get<double>());
  EXPECT_NEAR(peak, GetNumber(summary, "peak_pressure_Pa", "summary"), 1e-9 * peak);
  std::vector<char> drawn(points.size(), 0);
  for (const Json& t : triangles) {
    for (const Json& corner : t) {
      const size_t i = corner.get<size_t>();
      ASSERT_LT(i, points.size());
      drawn[i] = 1;
    }
  }
  int in_contact = 0;
  for (size_t i = 0; i < pressure.size(); ++i) {
    if (pressure[i].get<double>() <= 0) continue;
    ++in_contact;
    EXPECT_TRUE(drawn[i]) << "skin vertex " << i << " in contact is on no drawn triangle";
  }
  EXPECT_GT(in_contact, 3);
  const Json& cop = GetMember(data, "centre_of_pressure2d", "plot_data");
  EXPECT_LT(std::hypot(cop.at(0).get<double>(), cop.at(1).get<double>()), 1e-3);
  EXPECT_EQ(FindMember(data, "regions"), nullptr);  // a ball has no foot's bands
  EXPECT_TRUE(GetMember(data, "crushed_points2d", "plot_data").empty());
  if (!FindPythonWithMatplotlib().empty()) {
    for (const char* png : {"pressure_map.png", "pressure_histogram.png"})
      EXPECT_GT(fs::file_size(out + "/" + png), 1000u) << png;
  }
}

TEST_F(ToolsSimulate, ANonConvergedSolveExitsNonZeroAndStillWritesTheSummary) {
  const CommandResult run =
      RunCommand(Simulate("--contact_stiffness=600 --max_iterations=1 --place=none", "capped"));
  EXPECT_EQ(run.status, 1) << run.output;
  const Json summary = ReadJsonFile(*dir_ + "/capped/summary.json");
  EXPECT_FALSE(GetBool(summary, "converged", "summary"));
  EXPECT_NE(GetString(summary, "reason", "summary").find("Newton iterations"), std::string::npos);
  // Said after the figures, so nobody takes them for an equilibrium's.
  const size_t said = run.output.find("the equilibrium did not converge");
  ASSERT_NE(said, std::string::npos) << run.output;
  EXPECT_GT(said, run.output.find("peak skin pressure")) << run.output;
}

TEST_F(ToolsSimulate, BadInputsExitWithStatusTwoNamingTheCulprit) {
  CommandResult run = RunCommand(Simulate("--contact_stiffness=soft", "bad1"));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("--contact_stiffness"), std::string::npos) << run.output;
  run = RunCommand(Simulate("--external_force=1,2", "bad2"));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("--external_force"), std::string::npos) << run.output;
  run = RunCommand("timeout 60 " ERGO_BIN_DIR
                   "/ergo_simulate --body=/nonexistent --support=x.off --out=/tmp/x");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("/nonexistent"), std::string::npos) << run.output;
  run = RunCommand(Simulate("--lock=rz", "bad3"));
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("rotation"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(*dir_ + "/bad1/summary.json"));
}

TEST_F(ToolsSimulate, ProgressGoesToStderrWithElapsedTimeAndCanBeSilenced) {
  const std::string command = Simulate("--contact_stiffness=auto", "progress");
  const SplitResult run = RunSplit(command, *dir_);
  ASSERT_EQ(run.status, 0) << run.out << run.err;
  // Progress on stderr only, every kind of line with the elapsed time first.
  EXPECT_EQ(run.out.find(" s  Newton"), std::string::npos) << run.out;
  for (const char* kind : {" s  placed ", " s  calibration  1: κ", " s  Newton   1  residual",
                           " s  stiffness calibration: ", " s  equilibrium: "})
    EXPECT_NE(run.err.find(kind), std::string::npos) << kind << "\n" << run.err;
  const SplitResult quiet = RunSplit(command + " --progress=false", *dir_);
  ASSERT_EQ(quiet.status, 0) << quiet.out << quiet.err;
  EXPECT_EQ(quiet.err.find(" s  "), std::string::npos) << quiet.err;
}

TEST_F(ToolsSimulate, MaxSecondsStopsCleanlyWithExitOneAndWritesNothing) {
  // A budget far below one calibration (each step is a full equilibrium).
  const CommandResult run =
      RunCommand(Simulate("--contact_stiffness=auto --max_seconds=1e-4", "late"));
  EXPECT_EQ(run.status, 1) << run.output;
  EXPECT_NE(run.output.find("--max_seconds=0.0001 ran out"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(*dir_ + "/late")) << run.output;
  const CommandResult bad = RunCommand(Simulate("--max_seconds=-1", "bad"));
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("--max_seconds"), std::string::npos) << bad.output;
}

// --load_point: the whole load's line of action at a fraction of the body's length from its
// heel end, as a torque on the core. For the ball (its centre of mass at its core's centre) the
// torque is τ = (P − C) × (−W ŷ) = (Δz W, 0, 0), Δz = (0.3 − 0.5) × 0.1 m; its rotations are
// locked, so the lock carries it. 1.5 %: the meshed sphere's extent along z falls short of its
// 0.1 m diameter by 0.6 %, and its centre of mass lies off the core's centre by a few tenths of a
// millimetre (the (G − C) × Mg term, the sum of the two ends' torques below: 0.6 % of one).
// Turned end for end (--heel_end=max_z) the torque changes sign. A ball has no ankle, so
// without --heel_end the heel end is refused, naming the flag.
TEST_F(ToolsSimulate, LoadPointIsTheWholeLoadThroughTheStatedPoint) {
  double torque[2] = {0, 0};
  double weight = 0;
  const char* ends[2] = {"min_z", "max_z"};
  for (int k = 0; k < 2; ++k) {
    const std::string out = std::string("load_point_") + ends[k];
    const CommandResult run = RunCommand(Simulate(
        "--contact_stiffness=1e8 --load_point=0.3 --heel_end=" + std::string(ends[k]), out));
    ASSERT_EQ(run.status, 0) << run.output;
    const Json summary = ReadJsonFile(*dir_ + "/" + out + "/summary.json");
    const Json& load = GetMember(summary, "load_point", "summary");
    EXPECT_EQ(GetNumber(load, "fraction", "load_point"), 0.3);
    EXPECT_EQ(GetString(load, "heel_end", "load_point"), ends[k]);
    torque[k] = GetMember(load, "external_torque_Nm", "load_point").at(0).get<double>();
    weight = -GetMember(summary, "load_N", "summary").at(1).get<double>();
    // A plain body without --regions says nothing of a foot's split.
    EXPECT_EQ(FindMember(summary, "region_shares"), nullptr);
  }
  ASSERT_GT(weight, 0);
  EXPECT_NEAR(torque[0], -0.2 * 0.1 * weight, 0.015 * 0.02 * weight);
  EXPECT_NEAR(torque[1], 0.2 * 0.1 * weight, 0.015 * 0.02 * weight);
  EXPECT_LT(std::abs(torque[0] + torque[1]), 0.015 * 0.02 * weight);

  const CommandResult no_ankle = RunCommand(Simulate("--load_point=0.3", "no_ankle"));
  EXPECT_EQ(no_ankle.status, 2) << no_ankle.output;
  EXPECT_NE(no_ankle.output.find("--heel_end"), std::string::npos) << no_ankle.output;
  for (const char* bad :
       {"--load_point=1.2", "--load_point=heel", "--regions=hand", "--heel_end=top"}) {
    const CommandResult refused = RunCommand(Simulate(bad, "bad_length"));
    EXPECT_EQ(refused.status, 2) << bad << ": " << refused.output;
    const std::string flag = std::string(bad).substr(0, std::string(bad).find('='));
    EXPECT_NE(refused.output.find(flag), std::string::npos) << refused.output;
  }
}

// --roll turns the body about its length before it is placed; the lock holds it there, and
// summary.json says so. A ball turned stands as the ball level does: the same force balance, and
// its contact area within 8 % (which skin vertices touch changes with the turn: 4.5 % measured;
// the turn itself is checked exactly in design_tests' StartRotation). --roll=stance needs a foot:
// on the ball it exits 2 saying why; bad angles exit 2 naming the flag.
TEST_F(ToolsSimulate, RollTurnsTheBodyBeforeItIsPlacedAndStanceNeedsAFoot) {
  const CommandResult level = RunCommand(Simulate("--contact_stiffness=1e8", "roll_level"));
  ASSERT_EQ(level.status, 0) << level.output;
  const CommandResult turned =
      RunCommand(Simulate("--contact_stiffness=1e8 --roll=12", "roll_turned"));
  ASSERT_EQ(turned.status, 0) << turned.output;
  const Json flat = ReadJsonFile(*dir_ + "/roll_level/summary.json");
  const Json summary = ReadJsonFile(*dir_ + "/roll_turned/summary.json");
  EXPECT_EQ(FindMember(flat, "roll"), nullptr);
  const Json& roll = GetMember(summary, "roll", "summary");
  EXPECT_NEAR(GetNumber(roll, "degrees", "roll"), 12, 1e-12);
  EXPECT_EQ(GetString(roll, "rule", "roll"), "given");
  const double area = GetNumber(flat, "contact_area_m2", "summary");
  EXPECT_NEAR(GetNumber(summary, "contact_area_m2", "summary"), area, 0.08 * area);
  EXPECT_NEAR(GetMember(summary, "total_contact_force_N", "summary").at(1).get<double>(),
              GetMember(flat, "total_contact_force_N", "summary").at(1).get<double>(), 1e-6);

  const CommandResult stance = RunCommand(Simulate("--roll=stance", "roll_stance"));
  EXPECT_EQ(stance.status, 2) << stance.output;
  EXPECT_NE(stance.output.find("ergo_simulate: "), std::string::npos) << stance.output;
  EXPECT_FALSE(fs::exists(*dir_ + "/roll_stance/summary.json"));
  // --calcaneal_stance=4 without --roll=stance and --foot_side with a given roll would be
  // ignored: refused too.
  for (const std::string bad :
       {"--roll=40", "--roll=twist", "--calcaneal_stance=45", "--roll=stance --foot_side=middle",
        "--calcaneal_stance=4", "--roll=3 --foot_side=left"}) {
    const CommandResult refused = RunCommand(Simulate(bad, "roll_bad"));
    EXPECT_EQ(refused.status, 2) << bad << "\n" << refused.output;
    const std::string flag = bad.substr(0, bad.find('='));
    const std::string named = bad.find("foot_side") != std::string::npos ? "--foot_side" : flag;
    EXPECT_NE(refused.output.find(named), std::string::npos) << bad << "\n" << refused.output;
  }
}

// A body built with --anatomy=foot records its anatomy and landmarks in body.json; ergo_simulate
// then reports the load's split along the length from the heel the landmarks name, as
// ergo_optimize does for the shoe. Here the ball's record is edited to say it is a foot with its
// heel at +z: the split comes with heel_end max_z, its shares sum to 1, and the centre of
// pressure's fraction from the heel is 1 minus its fraction from the smallest z. The ball's
// centre of pressure lies at its middle (0.5; 0.01 covers the mesh's asymmetry, measured 0.498).
TEST_F(ToolsSimulate, RecordedFootGetsTheLoadSplitFromItsHeel) {
  const std::string foot = *dir_ + "/ball_foot";
  fs::copy(*dir_ + "/ball", foot,
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  Json record = ReadJsonFile(foot + "/body.json");
  record["source"]["anatomy"] = "foot";
  record["source"]["landmarks"] =
      Json::array({Json{{"name", "heel"}, {"point_m", {0.0, -0.05, 0.04}}},
                   Json{{"name", "toe tip"}, {"point_m", {0.0, -0.04, -0.05}}}});
  WriteJsonFile(foot + "/body.json", record);
  auto simulate_foot = [&](const std::string& extra, const std::string& out) {
    return RunCommand("timeout 300 " ERGO_BIN_DIR "/ergo_simulate --plot=false --body=" + foot +
                      " --support=" + *dir_ +
                      "/slab_mm.stl --unit=mm --lock=tx,tz,rx,ry,rz --contact_stiffness=1e8 " +
                      extra + " --out=" + *dir_ + "/" + out);
  };
  const CommandResult run = simulate_foot("", "foot_split");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("load split rearfoot / midfoot / forefoot"), std::string::npos)
      << run.output;
  const Json summary = ReadJsonFile(*dir_ + "/foot_split/summary.json");
  const Json& split = GetMember(summary, "region_shares", "summary");
  EXPECT_EQ(GetString(split, "heel_end", "region_shares"), "max_z");
  const Json& shares = GetMember(split, "shares", "region_shares");
  double sum = 0;
  for (const char* name : {"rearfoot", "midfoot", "forefoot"}) {
    const double share = GetNumber(shares, name, "shares");
    EXPECT_GE(share, 0) << name;
    sum += share;
  }
  EXPECT_NEAR(sum, 1, 1e-12);
  const double from_heel = GetNumber(summary, "centre_of_pressure_heel_fraction", "summary");
  EXPECT_NEAR(from_heel, 1 - GetNumber(summary, "centre_of_pressure_z_fraction", "summary"), 1e-12);
  EXPECT_NEAR(from_heel, 0.5, 0.01);
  // The pressure map marks the same bands: from the heel at the largest z towards the smallest,
  // end to end over the ball's 0.1 m (its mesh 0.6 % short), each with the summary's share.
  const Json plot = ReadJsonFile(*dir_ + "/foot_split/plot_data.json");
  const Json& bands = GetMember(plot, "regions", "plot_data");
  ASSERT_EQ(bands.size(), 3u);
  const char* names[3] = {"rearfoot", "midfoot", "forefoot"};
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(GetString(bands[k], "name", "band"), names[k]);
    EXPECT_EQ(GetNumber(bands[k], "share", "band"), GetNumber(shares, names[k], "shares"));
    EXPECT_GT(GetNumber(bands[k], "v_from", "band"), GetNumber(bands[k], "v_to", "band"));
    if (k > 0) {
      EXPECT_EQ(GetNumber(bands[k], "v_from", "band"), GetNumber(bands[k - 1], "v_to", "band"));
    }
  }
  EXPECT_NEAR(GetNumber(bands[0], "v_from", "band") - GetNumber(bands[2], "v_to", "band"), 0.1,
              1e-3);
  EXPECT_NEAR(GetNumber(bands[0], "v_to", "band") - GetNumber(bands[0], "v_from", "band"),
              -0.3 * (GetNumber(bands[0], "v_from", "band") - GetNumber(bands[2], "v_to", "band")),
              1e-12);
  // --regions=none keeps it out; --plot=false writes the map's data but no picture.
  const CommandResult quiet = simulate_foot("--regions=none", "foot_quiet");
  ASSERT_EQ(quiet.status, 0) << quiet.output;
  EXPECT_EQ(FindMember(ReadJsonFile(*dir_ + "/foot_quiet/summary.json"), "region_shares"), nullptr);
  EXPECT_EQ(FindMember(ReadJsonFile(*dir_ + "/foot_quiet/plot_data.json"), "regions"), nullptr);
  EXPECT_FALSE(fs::exists(*dir_ + "/foot_quiet/pressure_map.png"));
  // A foot built from a scan records its heel's bisector as measured on the scan; --roll=stance
  // stands it from that record without bisecting the (here round) skin: a heel 2 degrees
  // everted at rest with its medial side at -x is turned by -(2 - 6.07) = 4.07 degrees.
  record["source"]["heel_eversion_deg"] = 2.0;
  record["source"]["medial_side"] = "-x";
  WriteJsonFile(foot + "/body.json", record);
  const CommandResult stance = simulate_foot("--roll=stance", "foot_stance");
  ASSERT_EQ(stance.status, 0) << stance.output;
  EXPECT_NE(stance.output.find("on the scan"), std::string::npos) << stance.output;
  const Json stood = ReadJsonFile(*dir_ + "/foot_stance/summary.json");
  const Json& roll = GetMember(stood, "roll", "summary");
  EXPECT_NEAR(GetNumber(roll, "degrees", "roll"), 4.07, 1e-12);
  EXPECT_NEAR(GetNumber(roll, "heel_eversion_deg", "roll"), 2.0, 1e-12);
}

// The slab as foam (--support_model=soft): Mesh_3 of the slab, its bottom held; the ball sinks
// into it, the base carries the load, and the deformed solid with its stress is written. A
// user's tet mesh of the slab (--support_tets, millimetres) gives the same kind of run; bad
// soft-support flags exit 2 naming the flag.
TEST_F(ToolsSimulate, ASoftSlabDeformsUnderTheBallAndItsSolidIsWritten) {
  const std::string soft =
      "--contact_stiffness=1e8 --support_model=soft --support_youngs_modulus=2e4 "
      "--soft_support_edge_length=0.02 --soft_support_base_edge_length=0.05";
  const CommandResult run = RunCommand(Simulate(soft, "soft"));
  ASSERT_EQ(run.status, 0) << run.output;
  for (const char* file : {"body_deformed.vtu", "support.vtu", "support_solid.vtu", "summary.json"})
    EXPECT_TRUE(fs::exists(*dir_ + "/soft/" + file)) << file;
  const Json summary = ReadJsonFile(*dir_ + "/soft/summary.json");
  EXPECT_TRUE(GetBool(summary, "converged", "summary"));
  const Json& force = GetMember(summary, "total_contact_force_N", "summary");
  const Json& load = GetMember(summary, "load_N", "summary");
  EXPECT_NEAR(force.at(1).get<double>(), -load.at(1).get<double>(),
              1e-6 * std::abs(load.at(1).get<double>()));
  const Json& foam = GetMember(summary, "soft_support", "summary");
  // A 20 kPa slab under a ball of ~1 kg: it gives way by more than the contact penetration.
  EXPECT_GT(GetNumber(foam, "max_displacement_m", "soft_support"),
            GetNumber(summary, "max_penetration_m", "summary"));
  EXPECT_NE(GetString(summary, "support_model", "summary").find("soft"), std::string::npos);

  // The same slab from a tet file in millimetres.
  TetMesh slab = MakeTetGrid({-150, -110, -150}, {150, -60, 150}, {6, 2, 6});
  WriteTetMesh(*dir_ + "/slab_mm.msh", slab);
  const CommandResult tets =
      RunCommand("timeout 300 " ERGO_BIN_DIR "/ergo_simulate --plot=false --body=" + *dir_ +
                 "/ball --support_tets=" + *dir_ +
                 "/slab_mm.msh --unit=mm --lock=tx,tz,rx,ry,rz --contact_stiffness=1e8 "
                 "--support_model=soft --out=" +
                 *dir_ + "/soft_tets");
  ASSERT_EQ(tets.status, 0) << tets.output;
  EXPECT_TRUE(fs::exists(*dir_ + "/soft_tets/support_solid.vtu"));
  // Its held vertices given as a list (the bottom plane's, and a bad index refused by line).
  {
    std::ofstream held(*dir_ + "/held.txt");
    held << "# the slab's bottom\n";
    for (Eigen::Index v = 0; v < slab.vertices.rows(); ++v)
      if (slab.vertices(v, 1) < -110 + 1e-9) held << v << "\n";
    std::ofstream bad(*dir_ + "/held_bad.txt");
    bad << "0 1\n2 99999\n";
  }
  const std::string with_tets =
      "timeout 300 " ERGO_BIN_DIR "/ergo_simulate --plot=false --body=" + *dir_ +
      "/ball --support_tets=" + *dir_ +
      "/slab_mm.msh --unit=mm --lock=tx,tz,rx,ry,rz "
      "--contact_stiffness=1e8 --support_model=soft ";
  const CommandResult listed =
      RunCommand(with_tets + "--support_held=" + *dir_ + "/held.txt --out=" + *dir_ + "/soft_held");
  ASSERT_EQ(listed.status, 0) << listed.output;
  const CommandResult refused = RunCommand(with_tets + "--support_held=" + *dir_ +
                                           "/held_bad.txt --out=" + *dir_ + "/soft_bad");
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("held_bad.txt:line 2"), std::string::npos) << refused.output;

  // Two soft supports, one tet file each: the slab cut in two under the ball (a 10 mm gap),
  // both bases held; the ball rests on both. A held-file list of the wrong length is refused.
  WriteTetMesh(*dir_ + "/left_mm.msh", MakeTetGrid({-150, -110, -150}, {-5, -60, 150}, {3, 2, 6}));
  WriteTetMesh(*dir_ + "/right_mm.msh", MakeTetGrid({5, -110, -150}, {150, -60, 150}, {3, 2, 6}));
  const std::string two_slabs =
      "timeout 300 " ERGO_BIN_DIR "/ergo_simulate --plot=false --body=" + *dir_ +
      "/ball --support_tets=" + *dir_ + "/left_mm.msh," + *dir_ +
      "/right_mm.msh --unit=mm --lock=tx,tz,rx,ry,rz "
      "--contact_stiffness=1e8 --support_model=soft ";
  const CommandResult two = RunCommand(two_slabs + "--out=" + *dir_ + "/soft_two");
  ASSERT_EQ(two.status, 0) << two.output;
  const Json two_summary = ReadJsonFile(*dir_ + "/soft_two/summary.json");
  EXPECT_TRUE(GetBool(two_summary, "converged", "summary"));
  EXPECT_NEAR(GetMember(two_summary, "total_contact_force_N", "summary").at(1).get<double>(),
              -GetMember(two_summary, "load_N", "summary").at(1).get<double>(),
              1e-6 * std::abs(GetMember(two_summary, "load_N", "summary").at(1).get<double>()));
  const CommandResult one_held =
      RunCommand(two_slabs + "--support_held=" + *dir_ + "/held.txt --out=" + *dir_ + "/soft_2h");
  EXPECT_EQ(one_held.status, 2) << one_held.output;
  EXPECT_NE(one_held.output.find("--support_held"), std::string::npos) << one_held.output;

  // An open support surface is refused as a support, before any meshing.
  {
    TriMesh open = MakeBox({-150, -110, -150}, {150, -60, 150}, {2, 1, 2});
    open.triangles.conservativeResize(open.triangles.rows() - 2, 3);
    WriteTriMesh(*dir_ + "/open_mm.stl", open);
  }
  const CommandResult open_run =
      RunCommand("timeout 120 " ERGO_BIN_DIR "/ergo_simulate --plot=false --body=" + *dir_ +
                 "/ball --support=" + *dir_ +
                 "/open_mm.stl --unit=mm --support_model=soft --out=" + *dir_ + "/soft_open");
  EXPECT_EQ(open_run.status, 2) << open_run.output;
  EXPECT_NE(open_run.output.find("open_mm.stl"), std::string::npos) << open_run.output;
  EXPECT_EQ(open_run.output.find("Mesh_3"), std::string::npos) << open_run.output;

  CommandResult bad = RunCommand(Simulate("--support_model=foam", "bad_soft1"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("--support_model"), std::string::npos) << bad.output;
  bad = RunCommand(Simulate("--support_model=soft --support_poisson_ratio=0.5", "bad_soft2"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("--support_poisson_ratio"), std::string::npos) << bad.output;
  bad = RunCommand(Simulate(
      "--support_model=soft --soft_support_edge_length=0.03 --soft_support_base_edge_length=0.01",
      "bad_soft3"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("--soft_support_base_edge_length"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace ergo
