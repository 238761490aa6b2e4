// The indentation curves' CSV: interleaved samples, units, ignored columns, and every
// unusable file refused with its line and a fix.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "ergo/calibration/indentation_curves.h"
#include "ergo/mesh/input_error.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

class CalibrationCurves : public ::testing::Test {
 protected:
  void SetUp() override { scratch_ = testing::MakeScratchDir("curves"); }
  void TearDown() override { fs::remove_all(scratch_); }
  std::string Write(const std::string& text) {
    const std::string path = scratch_ + "/curves" + std::to_string(count_++) + ".csv";
    std::ofstream(path) << text;
    return path;
  }
  // The InputError's message for `text`, or "" if it was read.
  std::string ErrorOf(const std::string& text) {
    try {
      ReadIndentationCurvesCsv(Write(text), LengthUnit::kMillimetre);
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }
  std::string scratch_;
  int count_ = 0;
};

TEST_F(CalibrationCurves, InterleavedSamplesInMillimetresAreReadInMetres) {
  const std::string path = Write(
      "# two points, as a logger writes them\n"
      "time_s;sample;x;y;z;indentation;force;depth\n"
      "0.0;heel;10;2;-100;0;0;17\n"
      "0.0;ball;-5;3;60.5;0;0;15\n"
      "0.1;heel;10;2;-100;0.5;0.012;17\n"
      "\n"
      "0.1;ball;-5;3;60.5;0.5;0.015;15\n"
      "0.2;heel;10;2;-100;1.0;0.035;17\n");
  const IndentationCurves curves = ReadIndentationCurvesCsv(path, LengthUnit::kMillimetre);
  ASSERT_EQ(curves.curves.size(), 2u);
  EXPECT_TRUE(curves.has_depth);
  ASSERT_EQ(curves.ignored_columns.size(), 1u);
  EXPECT_EQ(curves.ignored_columns[0], "time_s");
  const IndentationCurve& heel = curves.curves[0];
  EXPECT_EQ(heel.name, "heel");
  EXPECT_EQ(heel.first_line, 3);
  EXPECT_NEAR(heel.point.z(), -0.1, 1e-15);
  ASSERT_EQ(heel.indentation.size(), 3u);
  EXPECT_NEAR(heel.indentation[2], 0.001, 1e-15);
  EXPECT_EQ(heel.force[2], 0.035);  // newtons, never scaled
  EXPECT_NEAR(heel.measured_depth, 0.017, 1e-15);
  EXPECT_EQ(curves.curves[1].indentation.size(), 2u);
  EXPECT_NEAR(curves.curves[1].measured_depth, 0.015, 1e-15);
}

TEST_F(CalibrationCurves, ReadingsBeforeContactAndALoadCellsNoiseAreKept) {
  // The approach (δ < 0) and small negative forces around contact are what loggers write;
  // the fit leaves out δ ≤ 0 (indentation_fit.h).
  const IndentationCurves curves = ReadIndentationCurvesCsv(
      Write("sample,x,y,z,indentation,force\na,0,0,0,-0.2,-0.001\na,0,0,0,0.5,0.01\n"),
      LengthUnit::kMillimetre);
  ASSERT_EQ(curves.curves.size(), 1u);
  EXPECT_NEAR(curves.curves[0].indentation[0], -2e-4, 1e-15);
  EXPECT_EQ(curves.curves[0].force[0], -0.001);
}

TEST_F(CalibrationCurves, UnusableFilesAreRefusedWithTheirLineAndAFix) {
  const std::string header = "sample,x,y,z,indentation,force\n";
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"", "is empty"},
      {"# only a comment\n", "no header"},
      {header, "no readings"},
      {"sample,x,y,indentation,force\na,0,0,0,1\n", "no column 'z'"},
      {"sample,x,y,z,z,indentation,force\n", "named twice"},
      {header + "a,0,0,0,1\n", "line 2: has 5 fields"},
      {header + "a,0,0,0,0.5,abc\n", "line 2: force 'abc' is not a number"},
      {header + "a,0,0,0,nan,1\n", "not finite"},
      {header + ",0,0,0,0.5,1\n", "name is empty"},
      {header + "a,0,0,0,0.5,1\na,0,0,1,1.0,2\n", "line 3: sample 'a' is at (0, 0, 1)"},
      {"sample,x,y,z,indentation,force,depth\na,0,0,0,0.5,1,17\na,0,0,0,1,2,18\n",
       "line 3: sample 'a' has depth 18"},
      {"sample,x,y,z,indentation,force,depth\na,0,0,0,0.5,1,0\n", "depth '0' is not positive"},
  };
  for (const Case& c : cases) {
    const std::string message = ErrorOf(c.text);
    EXPECT_NE(message.find(c.expected), std::string::npos) << "for:\n"
                                                           << c.text << "got: " << message;
    EXPECT_NE(message.find(scratch_), std::string::npos) << message;  // names the file
  }
}

}  // namespace
}  // namespace ergo
