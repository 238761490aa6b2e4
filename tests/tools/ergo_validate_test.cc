// ergo_validate end to end on the quick shoe: synthetic plate and sensor measurements made
// from the simulated map come back as that map — the plate with a known rotation and shift
// found again — and unusable input is refused before any work, naming the file, line and fix,
// with the previous output left as it was.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/ergonomics/pressure_plate_csv.h"
#include "ergo/ergonomics/rigid_motion_2d.h"
#include "ergo/mesh/json.h"
#include "tests/support/test_paths.h"
#include "tests/support/text_files.h"
#include "tools/common/child_process.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

constexpr double kDegree = M_PI / 180;

struct ToolRun {
  int status = -1;
  std::string output;  // stdout and stderr
};

// The tool with the quick shoe's flagfile and `arguments`, its output captured (no shell).
ToolRun Validate(const std::string& scratch, const std::vector<std::string>& arguments) {
  static int count = 0;
  std::vector<std::string> argv = {std::string(ERGO_BIN_DIR) + "/ergo_validate",
                                   "--flagfile=" + testing::SourcePath("data/shoe.flags")};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  ChildOptions options;
  options.output = scratch + "/log" + std::to_string(count++) + ".txt";
  const ChildProcessResult result = RunChildProcess(argv, options);
  ToolRun run;
  run.status = result.started && result.signal == 0 ? result.exit_code : -1;
  run.output = testing::ReadTextFile(options.output);
  return run;
}

// The motion the synthetic plate was made with, from its comment line.
RigidMotion2d PlateMotion(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  RigidMotion2d motion;
  while (std::getline(in, line)) {
    double angle = 0, tx = 0, tz = 0;
    if (std::sscanf(line.c_str(), "# synthetic_plate_to_support: angle_deg=%lf tx_mm=%lf tz_mm=%lf",
                    &angle, &tx, &tz) == 3) {
      motion.angle = angle * kDegree;
      motion.translation = 1e-3 * Eigen::Vector2d(tx, tz);
      return motion;
    }
  }
  ADD_FAILURE() << "no synthetic motion line in " << path;
  return motion;
}

// Each test in its own scratch directory, making the synthetic measurement it compares (one
// simulation each: ctest runs every test in a process of its own).
class ToolsValidate : public ::testing::Test {
 protected:
  void SetUp() override { scratch_ = testing::MakeScratchDir("validate"); }
  void TearDown() override { fs::remove_all(scratch_); }
  std::string Plate() const { return scratch_ + "/plate.csv"; }
  std::string Sensors() const { return scratch_ + "/sensors.csv"; }
  std::string scratch_;
};

// Tolerances, from what the synthetic plate does to the map: 5 mm cells average a map whose
// skin vertices are 7 mm apart and add 2 % noise; measured: Pearson 0.996, Dice 0.945, force
// +0.15 %, shares within 0.01, the motion within 0.3° and 1 mm. Required: Pearson ≥ 0.95,
// Dice ≥ 0.85, force within 1 %, shares within 0.03, the motion within 1° and one pitch.
TEST_F(ToolsValidate, SyntheticPlateRoundTripRecoversMapAndMotion) {
  // Two quick-shoe solves: 20–30 s here, many minutes under the sanitizers, which the
  // ergonomics tests of the same pieces already cover.
  if (testing::SanitizedBuild()) GTEST_SKIP() << "two quick-shoe solves";
  // The plate: 5 mm cells, 2 % noise, the map rotated 8° and shifted (12, −7) mm on it.
  const ToolRun made =
      Validate(scratch_, {"--write_synthetic_plate=" + Plate(), "--synthetic_rotation_deg=8",
                          "--synthetic_shift_mm=12,-7"});
  ASSERT_EQ(made.status, 0) << made.output;
  const std::string out = scratch_ + "/plate_out";
  const ToolRun run = Validate(scratch_, {"--plate=" + Plate(), "--out=" + out});
  ASSERT_EQ(run.status, 0) << run.output;
  const Json c = ReadJsonFile(out + "/comparison.json");
  EXPECT_GE(c["pearson"].get<double>(), 0.95) << run.output;
  EXPECT_GE(c["dice"].get<double>(), 0.85);
  EXPECT_NEAR(c["total_force_ratio"].get<double>(), 1, 0.01);
  // The simulation read on the plate's own cells peaks where the plate does and reads what it
  // read, up to the noise (σ = 2 % of the peak per cell: within 3σ; measured 1.003, same cell),
  // though the map's vertex peak lies elsewhere (the forefoot's, 15 cm away).
  const Json& cells = GetMember(c, "on_the_plates_cells", "comparison.json");
  EXPECT_NEAR(GetNumber(cells, "peak_ratio", "on_the_plates_cells"), 1, 0.06) << run.output;
  EXPECT_LT(GetNumber(cells, "peak_distance_mm", "on_the_plates_cells"), 5.0);
  EXPECT_NE(
      testing::ReadTextFile(out + "/comparison.md").find("| peak on the plate's 5.0 mm cells"),
      std::string::npos);
  EXPECT_NEAR(c["simulated_map"]["total_force_n"].get<double>(),
              c["simulated"]["load_n"].get<double>(),
              1e-6 * c["simulated"]["load_n"].get<double>());
  ASSERT_EQ(c["regions"].size(), 3u);
  EXPECT_EQ(c["regions"][0]["name"], "rearfoot");
  for (const Json& region : c["regions"])
    EXPECT_NEAR(region["measured_share"].get<double>(), region["simulated_share"].get<double>(),
                0.03)
        << region["name"];

  const RigidMotion2d truth = PlateMotion(Plate());
  RigidMotion2d found;
  found.angle = c["alignment"]["angle_deg"].get<double>() * kDegree;
  found.translation = 1e-3 * Eigen::Vector2d(c["alignment"]["translation_mm"][0].get<double>(),
                                             c["alignment"]["translation_mm"][1].get<double>());
  EXPECT_LT(std::abs(std::remainder(found.angle - truth.angle, 2 * M_PI)), 1 * kDegree);
  const PressurePlateReading plate = ReadPressurePlateCsv(Plate(), {});
  double worst = 0;
  for (Eigen::Index r = 0; r < plate.grid.rows(); ++r)
    for (Eigen::Index k = 0; k < plate.grid.columns(); ++k)
      if (plate.grid.pressure(r, k) > 0)
        worst = std::max(worst, (found.Apply(plate.grid.CellCentre(r, k)) -
                                 truth.Apply(plate.grid.CellCentre(r, k)))
                                    .norm());
  EXPECT_LT(worst, plate.grid.pitch) << "loaded cells land up to " << 1e3 * worst << " mm off";

  for (const char* file : {"comparison.md", "maps.json"})
    EXPECT_TRUE(fs::exists(out + "/" + file)) << file;
  EXPECT_NE(testing::ReadTextFile(out + "/comparison.md").find("| rearfoot share"),
            std::string::npos);
  if (!FindPythonWithMatplotlib().empty()) {
    EXPECT_TRUE(fs::exists(out + "/comparison.png")) << run.output;
  }
}

// The sensors see the map at 144 points 15 mm apart, and the biharmonic interpolant on the
// 10 mm sole cannot show what falls between them: measured Pearson 0.976, Dice 0.877, shares
// within 0.04. Required: Pearson ≥ 0.9, Dice ≥ 0.8, shares within 0.06; the total is the load
// by construction (C), to round-off.
TEST_F(ToolsValidate, SyntheticSensorRoundTripRecoversTheMap) {
  // Two quick-shoe solves: 20–30 s here, many minutes under the sanitizers, which the
  // ergonomics tests of the same pieces already cover.
  if (testing::SanitizedBuild()) GTEST_SKIP() << "two quick-shoe solves";
  // Sensors every 15 mm with a reference, 600 samples each: 5 % noise, ±10 % posture between
  // the locations, 4 % spikes.
  const ToolRun made = Validate(scratch_, {"--write_synthetic_sensors=" + Sensors()});
  ASSERT_EQ(made.status, 0) << made.output;
  const std::string out = scratch_ + "/sensor_out";
  const ToolRun run =
      Validate(scratch_, {"--sensors=" + Sensors(), "--out=" + out, "--plot=false"});
  ASSERT_EQ(run.status, 0) << run.output;
  const Json c = ReadJsonFile(out + "/comparison.json");
  EXPECT_GE(c["pearson"].get<double>(), 0.9) << run.output;
  EXPECT_GE(c["dice"].get<double>(), 0.8);
  EXPECT_NEAR(c["total_force_ratio"].get<double>(), 1, 1e-9);
  for (const Json& region : c["regions"])
    EXPECT_NEAR(region["measured_share"].get<double>(), region["simulated_share"].get<double>(),
                0.06)
        << region["name"];
  EXPECT_EQ(c["measurement"]["locations"].get<int>(), 144);
  // The posture spread (±10 %) shows in the reference means.
  EXPECT_GT(c["measurement"]["reference_variation"].get<double>(), 0.05);
  const std::string table = testing::ReadTextFile(out + "/sensors.csv");
  EXPECT_EQ(testing::CountLines(table), 145);
  EXPECT_EQ(table.rfind("sensor,x_mm,z_mm,line,samples,kept,", 0), 0u);
  EXPECT_NE(table.find(",600,500,"), std::string::npos) << "600 samples, 50 trimmed at each end";
}

TEST_F(ToolsValidate, UnusableInputIsRefusedNamingFileLineAndFix) {
  const std::string bad_plate = scratch_ + "/bad_plate.csv";
  std::ofstream(bad_plate) << "# pitch_mm=5\n0,1,2\n0,3,4\n0,x,5\n";
  const std::string outside = scratch_ + "/outside.csv";
  std::ofstream(outside) << "sensor,x_mm,z_mm,value\na,0,0,1\nb,10,10,1\nc,500,0,1\n";
  const std::string out = "--out=" + scratch_ + "/refused";
  struct Case {
    std::vector<std::string> arguments;
    std::vector<std::string> expected;
  } cases[] = {
      {{"--plate=" + Plate()}, {"--out", "required"}},
      {{"--plate=" + Plate(), "--sensors=" + Sensors(), out}, {"--sensors", "both given"}},
      {{out}, {"--sensors", "missing"}},
      {{"--plate=" + bad_plate, out}, {bad_plate + ":line 4, cell 2", "not a number"}},
      {{"--plate=" + scratch_ + "/missing.csv", out}, {"missing.csv"}},
      {{"--sensors=" + Sensors(), "--trim=0.7", out}, {"--trim", "50/600"}},
      {{"--plate=" + Plate(), "--align=affine", out},
       {"--align", "auto, rigid, translation or none"}},
      {{"--plate=" + Plate(), "--regions=heel:0.5", out}, {"--regions", "end at 1"}},
      {{"--plate=" + Plate(), "--plate_unit=bar", out}, {"--plate_unit", "kPa"}},
      {{"--plate=" + Plate(), "--no_such_flag", out}, {"no_such_flag"}},
      {{"--sensors=" + outside, out}, {outside + ":line 4", "outside the support's top"}},
  };
  for (const Case& c : cases) {
    const ToolRun run = Validate(scratch_, c.arguments);
    SCOPED_TRACE(run.output);
    EXPECT_EQ(run.status, 2);
    for (const std::string& part : c.expected)
      EXPECT_NE(run.output.find(part), std::string::npos) << "'" << part << "' not in the message";
    EXPECT_EQ(run.output.find("solving the equilibrium"), std::string::npos)
        << "refused after work";
  }
  EXPECT_FALSE(fs::exists(scratch_ + "/refused"));
}

// A refused run leaves the previous output as it was; --out in the way of a file is refused.
TEST_F(ToolsValidate, RefusedRunLeavesThePreviousOutput) {
  const std::string previous = scratch_ + "/previous";
  fs::create_directories(previous);
  std::ofstream(previous + "/comparison.json") << "{\"old\": true}\n";
  const std::string bad_plate = scratch_ + "/empty_plate.csv";
  std::ofstream(bad_plate) << "# pitch_mm=5\n0,0\n0,0\n";
  const ToolRun run = Validate(scratch_, {"--plate=" + bad_plate, "--out=" + previous});
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("every cell reads 0"), std::string::npos) << run.output;
  EXPECT_EQ(testing::ReadTextFile(previous + "/comparison.json"), "{\"old\": true}\n");
  std::ofstream(scratch_ + "/a_file") << "in the way\n";
  const ToolRun blocked =
      Validate(scratch_, {"--plate=" + Plate(), "--out=" + scratch_ + "/a_file"});
  EXPECT_EQ(blocked.status, 2) << blocked.output;
  EXPECT_NE(blocked.output.find("--out"), std::string::npos) << blocked.output;
}

}  // namespace
}  // namespace ergo
