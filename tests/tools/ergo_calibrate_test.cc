// ergo_calibrate end to end: curves made by the layered law from known moduli and depths
// (three points, millimetres, interleaved, with a logger's extra column and noise of 0.5 %
// of the peak force) come back as those moduli and depths, in files ergo_body build reads; a
// body built from the fitted stiffness samples carries them. Unusable input exits 2 and a curve
// that cannot be fitted exits 1, both naming the file and line and writing nothing.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/body/sample_interpolation.h"
#include "ergo/calibration/layered_indentation.h"
#include "ergo/mesh/json.h"
#include "tests/support/test_paths.h"
#include "tests/support/text_files.h"
#include "tools/common/child_process.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

struct Point {
  const char* name;
  Eigen::Vector3d mm;  // on the skin of a 50 mm ball about the origin
  double youngs, depth_mm;
};

const Point kPoints[] = {{"bottom", {0, -50, 0}, 4.5e4, 17},
                         {"side", {50, 0, 0}, 6.0e4, 12},
                         {"top", {0, 30, 40}, 2.0e4, 25}};
constexpr double kRadius = 0.008;  // an 8 mm sphere

struct ToolRun {
  int status = -1;
  std::string output;
};

class ToolsCalibrate : public ::testing::Test {
 protected:
  void SetUp() override { scratch_ = testing::MakeScratchDir("calibrate"); }
  void TearDown() override { fs::remove_all(scratch_); }

  ToolRun Run(const std::string& tool, const std::vector<std::string>& arguments) {
    std::vector<std::string> argv = {std::string(ERGO_BIN_DIR) + "/" + tool};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    ChildOptions options;
    options.output = scratch_ + "/log" + std::to_string(count_++) + ".txt";
    const ChildProcessResult result = RunChildProcess(argv, options);
    ToolRun run;
    run.status = result.started && result.signal == 0 ? result.exit_code : -1;
    run.output = testing::ReadTextFile(options.output);
    return run;
  }

  // The law's curves of kPoints, 25 readings each to 5 mm, rows interleaved.
  std::string WriteCurves(int readings = 25) {
    const std::string path = scratch_ + "/curves.csv";
    std::ofstream out(path);
    out << "# synthetic: Dimitriadis law, R = 8 mm, nu = 0.45, bonded, 0.5 % noise\n";
    out << "time_s,sample,x,y,z,indentation,force\n";
    std::mt19937 random(3);
    std::normal_distribution<double> noise(0, 0.005);  // of each curve's peak force
    SphericalIndenter indenter;
    indenter.radius = kRadius;
    auto force = [&](const Point& p, double delta_mm) {
      return LayeredIndentationForce(indenter, p.youngs, 1e-3 * p.depth_mm, 1e-3 * delta_mm).force;
    };
    for (int i = 0; i < readings; ++i) {
      for (const Point& p : kPoints) {
        const double delta_mm = 5.0 * i / (readings - 1);
        out << 0.1 * i << "," << p.name << "," << p.mm.x() << "," << p.mm.y() << "," << p.mm.z()
            << "," << delta_mm << "," << force(p, delta_mm) + force(p, 5.0) * noise(random) << "\n";
      }
    }
    return path;
  }

  std::string scratch_;
  int count_ = 0;
};

TEST_F(ToolsCalibrate, FittedModuliAndDepthsComeBackAndBuildABody) {
  const std::string out = scratch_ + "/calib";
  const ToolRun run =
      Run("ergo_calibrate", {"--indentation=" + WriteCurves(), "--unit=mm",
                             "--indenter_radius=0.008", "--fit_depth", "--out=" + out});
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("column 'time_s' is not read"), std::string::npos) << run.output;
  SampleCsvOptions stiffness_options;
  stiffness_options.unit = LengthUnit::kMillimetre;
  const PointSamples stiffness =
      ReadPointSamplesCsv(out + "/stiffness_samples.csv", stiffness_options);
  SampleCsvOptions depth_options = stiffness_options;
  depth_options.value_is_length = true;
  const PointSamples depth = ReadPointSamplesCsv(out + "/depth_samples.csv", depth_options);
  ASSERT_EQ(stiffness.values.size(), 3);
  ASSERT_EQ(depth.values.size(), 3);
  const Json report = ReadJsonFile(out + "/calibration.json");
  ASSERT_EQ(report["points"].size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const Point& p = kPoints[k];
    EXPECT_NEAR((stiffness.points.row(k).transpose() - 1e-3 * p.mm).norm(), 0, 1e-12);
    // 0.5 % noise on 24 readings: measured misfits within 1.9 % (E) and 5.9 % (h) here; the
    // reported standard errors must cover each misfit within 4 of them.
    const Json& fit = report["points"][k];
    EXPECT_EQ(fit["sample"], p.name);
    EXPECT_EQ(fit["readings"], 24);
    const double e = stiffness.values[k], h = depth.values[k];
    std::cout << p.name << ": E " << e << " Pa (" << 100 * (e / p.youngs - 1) << " %), h "
              << 1e3 * h << " mm (" << 100 * (1e3 * h / p.depth_mm - 1) << " %)\n";
    EXPECT_NEAR(e, p.youngs, 0.05 * p.youngs) << p.name;
    EXPECT_NEAR(h, 1e-3 * p.depth_mm, 0.10 * 1e-3 * p.depth_mm) << p.name;
    EXPECT_LT(std::abs(e - p.youngs), 4 * fit["youngs_modulus_stderr_pa"].get<double>()) << p.name;
    EXPECT_LT(std::abs(1e3 * h - p.depth_mm), 4 * fit["depth_stderr"].get<double>()) << p.name;
    EXPECT_EQ(fit["depth_source"], "fitted");
  }
  const std::string md = testing::ReadTextFile(out + "/calibration.md");
  EXPECT_NE(md.find("| bottom |"), std::string::npos) << md;
  // The picture's data: each curve, its fitted law (passing through the readings) and Hertz's.
  const Json fits = ReadJsonFile(out + "/fits.json");
  ASSERT_EQ(fits.size(), 3u);
  EXPECT_EQ(fits[1]["model_force_n"].size(), 61u);
  const double peak_reading = fits[1]["force_n"].back().get<double>();
  const double peak_model = fits[1]["model_force_n"].back().get<double>();
  EXPECT_NEAR(peak_model, peak_reading, 0.02 * peak_reading);                  // 0.5 % noise, 4σ
  EXPECT_GT(peak_model, 1.3 * fits[1]["hertz_force_n"].back().get<double>());  // a 12 mm layer
  if (!FindPythonWithMatplotlib().empty()) EXPECT_TRUE(fs::exists(out + "/calibration.png"));

  // The stiffness samples as ergo_body build takes them: every tet's E within the samples'
  // range (the spline is clamped to it) and both ends of it reached near the points.
  const ToolRun body = Run(
      "ergo_body", {"build", "--shape=sphere_shell", "--outer_radius=0.05", "--core_radius=0.03",
                    "--unit=mm", "--stiffness_samples=" + out + "/stiffness_samples.csv",
                    "--edge_length=0.015", "--out=" + scratch_ + "/ball"});
  ASSERT_EQ(body.status, 0) << body.output;
  std::ifstream material(scratch_ + "/ball/tet_material.csv");
  std::string line;
  std::getline(material, line);  // header
  double low = 1e300, high = 0;
  while (std::getline(material, line)) {
    const double e = std::stod(line.substr(0, line.find(',')));
    low = std::min(low, e);
    high = std::max(high, e);
  }
  EXPECT_GE(low, stiffness.values.minCoeff() * (1 - 1e-9));
  EXPECT_LE(high, stiffness.values.maxCoeff() * (1 + 1e-9));
  EXPECT_LT(low, 1.3 * stiffness.values.minCoeff());
  EXPECT_GT(high, 0.8 * stiffness.values.maxCoeff());
}

TEST_F(ToolsCalibrate, AGivenDepthOrAHalfSpaceFitsTheModulusAlone) {
  const std::string curves = WriteCurves();
  // One depth for all three is wrong for two of them: their moduli absorb it.
  const ToolRun given =
      Run("ergo_calibrate", {"--indentation=" + curves, "--unit=mm", "--indenter_radius=0.008",
                             "--depth=0.017", "--out=" + scratch_ + "/given"});
  ASSERT_EQ(given.status, 0) << given.output;
  const Json report = ReadJsonFile(scratch_ + "/given/calibration.json");
  EXPECT_EQ(report["depth_mode"], "given");
  EXPECT_NEAR(report["points"][0]["youngs_modulus_pa"].get<double>(), 4.5e4, 0.03 * 4.5e4);
  EXPECT_EQ(report["points"][0]["depth_source"], "--depth");
  const ToolRun deep =
      Run("ergo_calibrate", {"--indentation=" + curves, "--unit=mm", "--indenter_radius=0.008",
                             "--half_space", "--out=" + scratch_ + "/deep"});
  ASSERT_EQ(deep.status, 0) << deep.output;
  EXPECT_FALSE(fs::exists(scratch_ + "/deep/depth_samples.csv"));
  // The contact point fitted too: these curves start at contact, so each offset is 0 within
  // 4 of its standard errors.
  const ToolRun contact =
      Run("ergo_calibrate", {"--indentation=" + curves, "--unit=mm", "--indenter_radius=0.008",
                             "--fit_depth", "--fit_contact_point", "--out=" + scratch_ + "/c"});
  ASSERT_EQ(contact.status, 0) << contact.output;
  const Json with_contact = ReadJsonFile(scratch_ + "/c/calibration.json");
  EXPECT_EQ(with_contact["contact_point"], "fitted");
  for (const Json& point : with_contact["points"]) {
    EXPECT_EQ(point["readings"], 25);  // the reading at 0 counts now
    EXPECT_LT(std::abs(point["contact_offset"].get<double>()),
              4 * point["contact_offset_stderr"].get<double>())
        << point["sample"];
  }
  EXPECT_NE(testing::ReadTextFile(scratch_ + "/c/calibration.md").find(" ± "), std::string::npos);
  // A half-space reads the 12 mm layer stiffer than it is.
  const Json half = ReadJsonFile(scratch_ + "/deep/calibration.json");
  EXPECT_GT(half["points"][1]["youngs_modulus_pa"].get<double>(), 1.2 * 6.0e4);
}

TEST_F(ToolsCalibrate, UnusableInputIsRefusedAndNothingIsWritten) {
  const std::string out = scratch_ + "/out";
  // No depth known.
  ToolRun run = Run("ergo_calibrate", {"--indentation=" + WriteCurves(), "--unit=mm",
                                       "--indenter_radius=0.008", "--out=" + out});
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("--depth"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("--fit_depth"), std::string::npos) << run.output;
  // A malformed reading: file and line.
  const std::string bad = scratch_ + "/bad.csv";
  std::ofstream(bad) << "sample,x,y,z,indentation,force\na,0,0,0,0.5,0.1\na,0,0,0,1.0,x\n";
  run = Run("ergo_calibrate",
            {"--indentation=" + bad, "--indenter_radius=0.008", "--half_space", "--out=" + out});
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find(bad + ":line 3: force 'x' is not a number"), std::string::npos)
      << run.output;
  // Too few readings to fit E and h: exit 1, the sample and its line named.
  run = Run("ergo_calibrate", {"--indentation=" + WriteCurves(4), "--unit=mm",
                               "--indenter_radius=0.008", "--fit_depth", "--out=" + out});
  EXPECT_EQ(run.status, 1) << run.output;
  EXPECT_NE(run.output.find("line 3: sample 'bottom' has 3 readings"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("nothing written"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace ergo
