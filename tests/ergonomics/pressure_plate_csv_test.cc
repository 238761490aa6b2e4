// A pressure plate's export: the matrix with its pitch and unit read in any of the usual
// separators, options overriding the file, every malformed file refused naming the line and
// the cell; the grid's bilinear field carrying exactly the plate's total force.
#include "ergo/ergonomics/pressure_plate_csv.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

class ErgonomicsPlateCsv : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::MakeScratchDir("plate_csv"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path) << text;
    return path;
  }
  std::string dir_;
};

TEST_F(ErgonomicsPlateCsv, ReadsTheMatrixPitchAndUnit) {
  for (const char* text : {"# exported\n# pitch_mm=5\n# unit=kPa\n0,1.5,0\n2,3,0.25\n",
                           "#pitch_mm = 5\n#unit=KPA\n0;1.5;0\r\n2;3;0.25\r\n",
                           "# pitch_mm=5\n# unit=kPa\n0\t1.5\t0\n2\t3\t0.25\n",
                           "# pitch_mm=5\n# unit=kPa\n  0  1.5 0\n2 3   0.25  \n"}) {
    SCOPED_TRACE(text);
    const PressurePlateReading reading = ReadPressurePlateCsv(Write("plate.csv", text), {});
    EXPECT_DOUBLE_EQ(reading.grid.pitch, 0.005);
    ASSERT_EQ(reading.grid.rows(), 2);
    ASSERT_EQ(reading.grid.columns(), 3);
    EXPECT_DOUBLE_EQ(reading.grid.pressure(0, 1), 1500);
    EXPECT_DOUBLE_EQ(reading.grid.pressure(1, 2), 250);
    EXPECT_NE(reading.pitch_source.find("plate.csv"), std::string::npos) << reading.pitch_source;
  }
}

TEST_F(ErgonomicsPlateCsv, OptionsOverrideTheFileAndTheUnitDefaultIsSaid) {
  const std::string path = Write("plate.csv", "# pitch_mm=5\n1,2\n3,4\n");
  PlateCsvOptions options;
  options.pitch_mm = 7.62;
  options.unit = "N/cm2";
  const PressurePlateReading reading =
      ReadPressurePlateCsv(path, options, "plate_pitch", "plate_unit");
  EXPECT_DOUBLE_EQ(reading.grid.pitch, 0.00762);
  EXPECT_DOUBLE_EQ(reading.grid.pressure(1, 1), 4e4);
  EXPECT_EQ(reading.pitch_source, "--plate_pitch");
  EXPECT_EQ(reading.unit_source, "--plate_unit");
  const PressurePlateReading defaulted = ReadPressurePlateCsv(path, {});
  EXPECT_EQ(defaulted.unit, "kPa");
  EXPECT_NE(defaulted.unit_source.find("default"), std::string::npos);
  double pascals = 0;
  ASSERT_TRUE(PascalsPerUnit("mmHg", &pascals));
  EXPECT_NEAR(pascals, 133.322, 1e-3);
  EXPECT_FALSE(PascalsPerUnit("bar", &pascals));
}

TEST_F(ErgonomicsPlateCsv, MalformedExportsNameTheLineCellAndFix) {
  struct Case {
    const char* text;
    std::vector<std::string> expected;
  } cases[] = {
      {"", {"empty"}},
      {"# pitch_mm=5\n", {"no rows"}},
      {"1,2\n3,4\n", {"pitch is not given", "pitch_mm=", "--plate_pitch"}},
      {"# pitch_mm=-5\n1,2\n", {":line 1", "not a positive number"}},
      {"# pitch_mm=5\n# unit=bar\n1,2\n", {":line 2", "bar", "kPa"}},
      {"# pitch_mm=5\n1,2,3\n4,5\n", {":line 3", "2 cells", "first row 3"}},
      {"# pitch_mm=5\n1,2\n4,x\n", {":line 3, cell 2", "not a number"}},
      {"# pitch_mm=5\n1,2\n4,-0.5\n", {":line 3, cell 2", "negative"}},
      {"# pitch_mm=5\n1,,2\n", {":line 2, cell 2", "empty", "write 0"}},
      {"# pitch_mm=5\n1,inf\n", {":line 2, cell 2", "not finite"}},
      {"# pitch_mm=5\n0,0\n0,0\n", {"every cell reads 0"}},
  };
  int k = 0;
  for (const Case& c : cases) {
    const std::string path = Write("bad" + std::to_string(k++) + ".csv", c.text);
    SCOPED_TRACE(c.text);
    try {
      ReadPressurePlateCsv(path, {}, "plate_pitch", "plate_unit");
      ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(path, 0), 0u) << message;
      for (const std::string& part : c.expected)
        EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    }
  }
  PlateCsvOptions bad_unit;
  bad_unit.unit = "bar";
  try {
    ReadPressurePlateCsv(Write("ok.csv", "# pitch_mm=5\n1\n"), bad_unit, "plate_pitch",
                         "plate_unit");
    ADD_FAILURE() << "accepted --plate_unit=bar";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("--plate_unit"), std::string::npos) << error.what();
  }
}

TEST_F(ErgonomicsPlateCsv, WrittenPlatesReadBackExactly) {
  PressureGrid grid;
  grid.pitch = 0.00508;
  grid.pressure.resize(3, 4);
  grid.pressure << 0, 1234.5, 0, 7, 1e5 / 3, 2, 0, 0, 0, 0, 3.25e4, 1;
  const std::string path = dir_ + "/written.csv";
  WritePressurePlateCsv(path, grid, "kPa", {"synthetic"});
  const PressurePlateReading back = ReadPressurePlateCsv(path, {});
  EXPECT_EQ(back.unit, "kPa");
  EXPECT_DOUBLE_EQ(back.grid.pitch, grid.pitch);
  EXPECT_LT((back.grid.pressure - grid.pressure).cwiseAbs().maxCoeff(), 1e-10);
}

// The bilinear field between cell centres, zero one pitch beyond the outer ones, integrates
// to Σ p h²: the midpoint rule on a grid 10x finer than the cells is exact for it (piecewise
// bilinear, every fine cell inside one bilinear patch), up to round-off.
TEST(ErgonomicsPressureGrid, BilinearFieldCarriesThePlatesForce) {
  PressureGrid grid;
  grid.pitch = 0.005;
  grid.origin = Eigen::Vector2d(-0.01, 0.02);
  grid.pressure.resize(4, 5);
  grid.pressure << 0, 10e3, 20e3, 0, 0, 5e3, 80e3, 120e3, 30e3, 0, 0, 60e3, 90e3, 10e3, 0, 0, 0,
      15e3, 0, 0;
  const int fine = 10;
  const double step = grid.pitch / fine;
  double integral = 0;
  for (int j = 0; j < (grid.rows() + 2) * fine; ++j) {
    for (int i = 0; i < (grid.columns() + 2) * fine; ++i) {
      const Eigen::Vector2d q = grid.origin +
                                Eigen::Vector2d(-0.5 * grid.pitch, -0.5 * grid.pitch) +
                                step * Eigen::Vector2d(i + 0.5, j + 0.5);
      integral += grid.PressureAt(q) * step * step;
    }
  }
  EXPECT_NEAR(integral, grid.TotalForce(), 1e-9 * grid.TotalForce());
  EXPECT_DOUBLE_EQ(grid.PressureAt(grid.CellCentre(1, 2)), 120e3);
  EXPECT_EQ(grid.PressureAt(grid.CellCentre(0, 0) - Eigen::Vector2d(grid.pitch, 0)), 0);
}

}  // namespace
}  // namespace ergo
