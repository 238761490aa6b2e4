// Point-sensor readings: the CSV format read and written, every malformed file refused with
// its file, line and fix; the support's top found and sensors put on it; and the paper's
// map — trimmed means, reference normalisation α_i r_i = C, linearly precise biharmonic
// interpolation, C for the load — recovering a linear pressure field exactly.
#include "ergo/ergonomics/sensor_readings.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/ergonomics/sensor_pressure_map.h"
#include "ergo/ergonomics/support_top_surface.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

class ErgonomicsSensorReadings : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::MakeScratchDir("sensor_readings"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path) << text;
    return path;
  }
  std::string dir_;
};

TEST_F(ErgonomicsSensorReadings, ReadsInterleavedRowsWithAReference) {
  const std::string path = Write("readings.csv",
                                 "# Tekscan A101, 10 Hz\n"
                                 "time_s,sensor,x_mm,z_mm,value,reference\n"
                                 "0.0,heel,10,-100,1.5,0.5\n"
                                 "0.0,ball,-20,80,2.5,0.25\n"
                                 "\n"
                                 "0.1,heel,10.0,-100.0,1.7,0.52\n"
                                 "0.1,ball,-20,80,2.25,0.26\n");
  const SensorReadings readings = ReadSensorReadingsCsv(path);
  EXPECT_EQ(readings.source, path);
  EXPECT_TRUE(readings.has_reference);
  ASSERT_EQ(readings.ignored_columns, std::vector<std::string>{"time_s"});
  ASSERT_EQ(readings.sensors.size(), 2u);
  const SensorRecord& heel = readings.sensors[0];
  EXPECT_EQ(heel.name, "heel");
  EXPECT_EQ(heel.first_line, 3);
  EXPECT_DOUBLE_EQ(heel.point.x(), 0.010);
  EXPECT_DOUBLE_EQ(heel.point.y(), -0.100);
  EXPECT_EQ(heel.values, (std::vector<double>{1.5, 1.7}));
  EXPECT_EQ(heel.reference, (std::vector<double>{0.5, 0.52}));
  EXPECT_EQ(readings.sensors[1].name, "ball");
  EXPECT_EQ(readings.sensors[1].first_line, 4);

  // Written and read back: the same readings.
  const std::string copy = dir_ + "/copy.csv";
  WriteSensorReadingsCsv(copy, readings, {"a copy"});
  const SensorReadings back = ReadSensorReadingsCsv(copy);
  ASSERT_EQ(back.sensors.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(back.sensors[i].name, readings.sensors[i].name);
    EXPECT_NEAR((back.sensors[i].point - readings.sensors[i].point).norm(), 0, 1e-15);
    EXPECT_EQ(back.sensors[i].values, readings.sensors[i].values);
    EXPECT_EQ(back.sensors[i].reference, readings.sensors[i].reference);
  }
}

TEST_F(ErgonomicsSensorReadings, MalformedFilesNameTheLineAndTheFix) {
  struct Case {
    const char* text;
    std::vector<std::string> expected;
  } cases[] = {
      {"", {"empty"}},
      {"# nothing here\n", {"no header"}},
      {"sensor,x_mm,z_mm,value\n", {"no readings"}},
      {"sensor,x_mm,value\nheel,1,2\n", {":line 1", "no column 'z_mm'", "sensor,x_mm,z_mm,value"}},
      {"sensor,sensor,x_mm,z_mm,value\n", {":line 1", "named twice"}},
      {"sensor,x_mm,z_mm,value\nheel,1,2\n", {":line 2", "3 fields", "header 4"}},
      {"sensor,x_mm,z_mm,value\nheel,1,2,abc\n", {":line 2", "value", "not a number"}},
      {"sensor,x_mm,z_mm,value\nheel,1,2,1e999\n", {":line 2", "not"}},
      {"sensor,x_mm,z_mm,value\nheel,1,2,nan\n", {":line 2", "not finite"}},
      {"sensor,x_mm,z_mm,value\n,1,2,3\n", {":line 2", "name is empty"}},
      {"sensor,x_mm,z_mm,value,reference\nheel,1,2,3,\n", {":line 2", "reference", "not a number"}},
      {"sensor,x_mm,z_mm,value\nheel,1,2,3\nheel,1.5,2,3\n",
       {":line 3", "on line 2", "same coordinates"}},
  };
  int k = 0;
  for (const Case& c : cases) {
    const std::string path = Write("bad" + std::to_string(k++) + ".csv", c.text);
    SCOPED_TRACE(c.text);
    try {
      ReadSensorReadingsCsv(path);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(path, 0), 0u) << message;  // starts with the file
      for (const std::string& part : c.expected)
        EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    }
  }
}

// A slab 0.2 x 0.3 m with 20 mm cells: its top is the face y = 0 alone.
TriMesh Slab() { return MakeBox({-0.1, -0.02, -0.15}, {0.1, 0, 0.15}, {10, 1, 15}); }

TEST(ErgonomicsSupportTop, IsTheUpwardFaceAndLocatesPointsOnIt) {
  const SupportTop top(Slab(), "slab");
  EXPECT_EQ(top.surface().vertices.rows(), 11 * 16);
  EXPECT_EQ(top.surface().triangles.rows(), 2 * 10 * 15);
  EXPECT_LT(top.surface().vertices.col(1).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(top.vertex_areas().sum(), 0.2 * 0.3, 1e-12);
  PlanarHit hit;
  ASSERT_TRUE(top.Locate(Eigen::Vector2d(0.013, -0.071), &hit));
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    point += hit.barycentric[k] *
             top.surface().vertices.row(top.surface().triangles(hit.triangle, k)).transpose();
  EXPECT_NEAR((point - Eigen::Vector3d(0.013, 0, -0.071)).norm(), 0, 1e-14);
  EXPECT_FALSE(top.Locate(Eigen::Vector2d(0.11, 0), &hit));
  // A support with nothing facing up: one triangle facing down.
  TriMesh facing_down;
  facing_down.vertices.resize(3, 3);
  facing_down.vertices << 0, 0, 0, 0, 0, 0.1, 0.1, 0, 0;
  facing_down.triangles.resize(1, 3);
  facing_down.triangles << 0, 2, 1;  // normal −y
  EXPECT_THROW(SupportTop(facing_down, "facing down"), InputError);
}

// p(x, z) = 80 kPa + 400 kPa/m · x − 150 kPa/m · z: 17.5 to 142.5 kPa over the slab.
double LinearPressure(const Eigen::Vector2d& q) { return 80e3 + 400e3 * q.x() - 150e3 * q.y(); }

// Readings of a linear field with the posture varying by ±20 % between locations (value and
// reference together), spikes the trim removes, and an arbitrary gain: the map must be the
// field itself, scaled so its total is the load.
TEST(ErgonomicsSensorMap, NormalisedTrimmedInterpolatedMapRecoversALinearField) {
  const SupportTop top(Slab(), "slab");
  SensorReadings readings;
  readings.source = "synthetic.csv";
  readings.has_reference = true;
  int line = 2;
  for (int j = 0; j < 9; ++j) {
    for (int i = 0; i < 6; ++i) {
      SensorRecord record;
      record.name = "s" + std::to_string(j * 6 + i);
      record.point = Eigen::Vector2d(-0.085 + 0.034 * i, -0.14 + 0.035 * j);
      record.first_line = line;
      const double posture = 0.8 + 0.4 * ((i * 7 + j * 3) % 5) / 4.0;
      for (int k = 0; k < 120; ++k) {
        double value = 2e-5 * posture * LinearPressure(record.point);
        double reference = 1e-5 * posture * 50e3;
        if (k < 5) value *= 10, reference *= 10;  // 5 high spikes…
        if (k >= 115) value = 0, reference = 0;   // …and 5 drops, trimmed by 10/120
        record.values.push_back(value);
        record.reference.push_back(reference);
      }
      line += 120;
      readings.sensors.push_back(record);
    }
  }
  SensorMapOptions options;
  options.trim.fraction = 10.0 / 120;
  options.load = 400;
  const SensorPressureMap map = EstimateSensorPressureMap(readings, top, options);
  ASSERT_EQ(map.sensors.size(), 54u);
  EXPECT_NEAR(map.total_force, 400, 1e-9 * 400);
  EXPECT_GE(map.lowest_interpolated, 0);
  // The slab's integral of p is 80 kPa · 0.06 m² (x and z average to 0): 4800 N; the map is
  // p · 400/4800. Round-off of the interpolation (see ErgonomicsBiharmonic): 1e-7 of 80 kPa.
  const double scale = 400 / 4800.0;
  for (Eigen::Index v = 0; v < top.surface().vertices.rows(); ++v) {
    const Eigen::Vector2d q(top.surface().vertices(v, 0), top.surface().vertices(v, 2));
    EXPECT_NEAR(map.top_pressure[v], scale * LinearPressure(q), 1e-7 * 80e3) << "vertex " << v;
  }
  for (const SensorEstimate& estimate : map.sensors) {
    EXPECT_NEAR(estimate.pressure, scale * LinearPressure(estimate.point), 1e-7 * 80e3);
    EXPECT_EQ(estimate.kept, 100);
  }
  // The posture varied by up to ±20 %: the reference means say so.
  EXPECT_GT(map.reference_variation, 0.1);
}

TEST(ErgonomicsSensorMap, RefusesSensorsItCannotUse) {
  const SupportTop top(Slab(), "slab");
  auto readings_at = [](const std::vector<Eigen::Vector2d>& points, int samples, double reference) {
    SensorReadings readings;
    readings.source = "in.csv";
    readings.has_reference = true;
    int line = 2;
    for (const Eigen::Vector2d& point : points) {
      SensorRecord record;
      record.name = "s" + std::to_string(line);
      record.point = point;
      record.first_line = line;
      record.values.assign(static_cast<size_t>(samples), 1.0);
      record.reference.assign(static_cast<size_t>(samples), reference);
      readings.sensors.push_back(record);
      line += samples;
    }
    return readings;
  };
  const std::vector<Eigen::Vector2d> good = {{0, 0}, {0.05, 0.1}, {-0.05, 0.05}};
  SensorMapOptions options;
  options.load = 100;
  auto expect_error = [&](const SensorReadings& readings, const std::vector<std::string>& parts) {
    SCOPED_TRACE(parts.back());
    try {
      EstimateSensorPressureMap(readings, top, options);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind("in.csv", 0), 0u) << message;
      for (const std::string& part : parts)
        EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    }
  };
  std::vector<Eigen::Vector2d> outside = good;
  outside.push_back({0.2, 0});
  expect_error(readings_at(outside, 12, 1.0), {":line 38", "outside the support's top", "200, 0"});
  options.trim.kind = SampleTrim::Kind::kCount;
  options.trim.count = 1;  // one sample at each end of a single sample
  expect_error(readings_at(good, 1, 1.0), {":line 2", "leaves none"});
  options.trim = SampleTrim();
  expect_error(readings_at(good, 12, 0.0), {":line 2", "reference", "positive"});
  expect_error(readings_at({{0, 0}, {0.01, 0.01}, {0.05, 0.05}}, 12, 1.0), {"one line"});
  SensorReadings silent = readings_at(good, 12, 1.0);
  for (SensorRecord& record : silent.sensors) record.values.assign(12, 0.0);
  expect_error(silent, {"no pressure"});
}

}  // namespace
}  // namespace ergo
