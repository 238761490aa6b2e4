// Sample files and their interpolation (ergo/body/sample_interpolation.h).
#include <cmath>
#include <fstream>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "ergo/body/sample_interpolation.h"
#include "ergo/mesh/input_error.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

PointSamples RandomSamples(int count, unsigned seed, double (*f)(const Eigen::Vector3d&)) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  PointSamples samples;
  samples.points.resize(count, 3);
  samples.values.resize(count);
  for (int i = 0; i < count; ++i) {
    samples.points.row(i) << u(random), u(random), u(random);
    samples.values[i] = f(samples.points.row(i).transpose());
  }
  return samples;
}

double Wavy(const Eigen::Vector3d& p) {
  return 0.02 + 0.01 * std::sin(40 * p.x()) * std::cos(30 * p.y()) + 0.05 * p.z();
}
double Affine(const Eigen::Vector3d& p) { return 0.03 + 0.1 * p.x() - 0.2 * p.y() + 0.05 * p.z(); }

std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = testing::MakeScratchDir("samples") + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// The InputError's location for reading `text`, or "no error".
std::string CsvError(const std::string& text, std::string* what = nullptr) {
  const std::string path = WriteFile("s.csv", text);
  SampleCsvOptions options;
  options.value_name = "depth";
  options.value_is_length = true;
  try {
    ReadPointSamplesCsv(path, options);
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), path);
    if (what) *what = error.problem();
    return error.location();
  }
  return "no error";
}

TEST(Body, SampleInterpolantIsExactAtTheSamples) {
  for (int count : {2, 3, 4, 6, 60}) {
    const PointSamples samples = RandomSamples(count, 3 + count, Wavy);
    const SampleInterpolant s = SampleInterpolant::Fit(samples);
    for (int i = 0; i < count; ++i) {
      const Eigen::Vector3d p = samples.points.row(i).transpose();
      EXPECT_NEAR(s.Unclamped(p), samples.values[i], 1e-10 * std::abs(samples.values[i])) << count;
      EXPECT_NEAR(s(p), samples.values[i], 1e-10 * std::abs(samples.values[i])) << count;
    }
  }
}

TEST(Body, SampleInterpolantReproducesAffineFieldsEverywhere) {
  // The spline space contains the affine functions, and the interpolant is unique.
  const PointSamples samples = RandomSamples(20, 11, Affine);
  const SampleInterpolant s = SampleInterpolant::Fit(samples);
  EXPECT_EQ(s.hull_dimension(), 3);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector3d p(u(random), u(random), u(random));
    EXPECT_NEAR(s.Unclamped(p), Affine(p), 1e-12);
  }
}

TEST(Body, SampleInterpolantHandlesCoplanarAndCollinearSamples) {
  // Samples on the plane z = 0.01 (a depth map measured on a flat-ish region).
  PointSamples plane = RandomSamples(8, 2, Wavy);
  plane.points.col(2).setConstant(0.01);
  for (int i = 0; i < 8; ++i) plane.values[i] = Wavy(plane.points.row(i).transpose());
  const SampleInterpolant s = SampleInterpolant::Fit(plane);
  EXPECT_EQ(s.hull_dimension(), 2);
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(s.Unclamped(plane.points.row(i).transpose()), plane.values[i],
                1e-10 * plane.values[i]);
  }
  // Collinear samples of an affine function: reproduced along the line.
  PointSamples line;
  line.points.resize(4, 3);
  line.values.resize(4);
  for (int i = 0; i < 4; ++i) {
    line.points.row(i) << 0.01 * i, 0.02 * i, -0.01 * i;
    line.values[i] = Affine(line.points.row(i).transpose());
  }
  const SampleInterpolant l = SampleInterpolant::Fit(line);
  EXPECT_EQ(l.hull_dimension(), 1);
  const Eigen::Vector3d mid(0.015, 0.03, -0.015);
  EXPECT_NEAR(l.Unclamped(mid), Affine(mid), 1e-12);
  // One sample: a constant.
  PointSamples one;
  one.points = Vertices::Zero(1, 3);
  one.values = Eigen::VectorXd::Constant(1, 0.025);
  EXPECT_EQ(SampleInterpolant::Fit(one)(Eigen::Vector3d(1, 2, 3)), 0.025);
}

TEST(Body, SampleInterpolantIsClampedToTheSampleRange) {
  const PointSamples samples = RandomSamples(10, 9, Wavy);
  const SampleInterpolant s = SampleInterpolant::Fit(samples);
  std::mt19937 random(1);
  std::uniform_real_distribution<double> u(-1, 1);  // far outside the samples too
  for (int i = 0; i < 200; ++i) {
    const double v = s(Eigen::Vector3d(u(random), u(random), u(random)));
    EXPECT_GE(v, samples.values.minCoeff());
    EXPECT_LE(v, samples.values.maxCoeff());
  }
}

TEST(Body, SampleInterpolantMergesDuplicatesAndRefusesConflicts) {
  PointSamples samples = RandomSamples(5, 4, Wavy);
  samples.points.conservativeResize(6, 3);
  samples.values.conservativeResize(6);
  samples.points.row(5) = samples.points.row(2);
  samples.values[5] = samples.values[2];
  EXPECT_EQ(SampleInterpolant::Fit(samples).sample_count(), 5);
  samples.values[5] = samples.values[2] + 0.001;
  samples.lines = {2, 3, 4, 5, 6, 9};
  samples.source = "depth.csv";
  try {
    SampleInterpolant::Fit(samples);
    FAIL() << "conflicting duplicate accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "depth.csv");
    EXPECT_EQ(error.location(), "line 9");
    EXPECT_NE(error.problem().find("line 4"), std::string::npos) << error.what();
  }
}

TEST(Body, SampleCsvReadsHeaderCommentsAndUnits) {
  const std::string path =
      WriteFile("depth.csv", "x,y,z,depth\n# measured 2024\n10, 20, 30, 25\n\n-10,0,5.5,12.5\r\n");
  SampleCsvOptions options;
  options.unit = LengthUnit::kMillimetre;
  options.value_is_length = true;
  const PointSamples depth = ReadPointSamplesCsv(path, options);
  ASSERT_EQ(depth.values.size(), 2);
  EXPECT_DOUBLE_EQ(depth.points(0, 2), 0.030);
  EXPECT_DOUBLE_EQ(depth.values[0], 0.025);
  EXPECT_EQ(depth.lines, (std::vector<int>{3, 5}));
  options.value_is_length = false;  // E: Pa whatever the length unit
  const PointSamples stiffness = ReadPointSamplesCsv(path, options);
  EXPECT_DOUBLE_EQ(stiffness.values[1], 12.5);
  EXPECT_DOUBLE_EQ(stiffness.points(1, 0), -0.010);
}

TEST(Body, SampleCsvBadLinesNameFileAndLine) {
  std::string what;
  EXPECT_EQ(CsvError("x,y,z,depth\n0,0,0,0.01\n0,0,abc,0.01\n", &what), "line 3");
  EXPECT_NE(what.find("z"), std::string::npos) << what;
  EXPECT_EQ(CsvError("0,0,0,0.01\n0,0,0.01\n", &what), "line 2");
  EXPECT_NE(what.find("4"), std::string::npos) << what;
  EXPECT_EQ(CsvError("0,0,0,0.01\n1,1,1,-0.01\n", &what), "line 2");
  EXPECT_NE(what.find("positive"), std::string::npos) << what;
  EXPECT_EQ(CsvError("0,0,0,0.01\n1,1,1,0\n"), "line 2");
  EXPECT_EQ(CsvError("0,0,nan,0.01\n"), "line 1");
  EXPECT_EQ(CsvError("0,0,0,1e999\n"), "line 1");
  EXPECT_EQ(CsvError("x,y,z,depth\n"), "");  // no samples: the whole file
  EXPECT_EQ(CsvError("0,0,0,0.01,7\n"), "line 1");
  EXPECT_EQ(CsvError("x,y,z,depth\nx,y,z,depth\n"), "line 2");  // one header only
  EXPECT_EQ(CsvError("x,y,z,depth\n0;0;0;0.01\n"), "no error");
}

}  // namespace
}  // namespace ergo
