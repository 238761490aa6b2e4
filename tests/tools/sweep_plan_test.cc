// The sweep's axes and cases (tools/common/sweep_plan.h): lists, ranges with integer and
// fractional steps, the cartesian order, stable and safe case names, and refused specs.
#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "tools/common/sweep_plan.h"

namespace ergo {
namespace {

using Values = std::vector<std::string>;

TEST(ToolsSweepPlan, ListsAndRangesGiveTheirValues) {
  EXPECT_EQ(ParseSweepAxis("optimizer=nlopt-mma,paper-ncg").values,
            (Values{"nlopt-mma", "paper-ncg"}));
  EXPECT_EQ(ParseSweepAxis("--exponent=2,3,4").flag, "exponent");
  EXPECT_EQ(ParseSweepAxis("gamma_power=-2:1").values, (Values{"-2", "-1", "0", "1"}));
  EXPECT_EQ(ParseSweepAxis("gamma_power=1:-2:-1").values, (Values{"1", "0", "-1", "-2"}));
  // 0 to 1 by 0.1 has eleven values however 0.1 rounds, each computed as from + k·step.
  const Values tenths = ParseSweepAxis("x=0:1:0.1").values;
  ASSERT_EQ(tenths.size(), 11u);
  EXPECT_EQ(tenths[3], "0.3");
  EXPECT_EQ(tenths[10], "1");
  EXPECT_EQ(ParseSweepAxis("depth=0.01:0.06:0.01").values.size(), 6u);
  EXPECT_EQ(ParseSweepAxis("x=5:5").values, (Values{"5"}));
}

TEST(ToolsSweepPlan, CasesAreTheCartesianProductFirstAxisSlowest) {
  const std::vector<SweepCase> cases =
      SweepCases({ParseSweepAxis("a=1,2"), ParseSweepAxis("b=x,y,z")});
  ASSERT_EQ(cases.size(), 6u);
  EXPECT_EQ(cases[0].name, "a=1__b=x");
  EXPECT_EQ(cases[2].name, "a=1__b=z");
  EXPECT_EQ(cases[3].name, "a=2__b=x");
  EXPECT_EQ(cases[5].flags[1], (std::pair<std::string, std::string>{"b", "z"}));
}

TEST(ToolsSweepPlan, CaseNamesAreSafeDirectoryNamesAndUnique) {
  const std::vector<SweepCase> cases = SweepCases({ParseSweepAxis("mesh=../a b,.._a_b,x/y")});
  ASSERT_EQ(cases.size(), 3u);
  for (const SweepCase& c : cases) {
    EXPECT_EQ(c.name.find('/'), std::string::npos) << c.name;
    EXPECT_EQ(c.name.find(' '), std::string::npos) << c.name;
  }
  EXPECT_EQ(cases[0].name, "mesh=.._a_b");
  EXPECT_EQ(cases[1].name, "mesh=.._a_b_2");  // the same after sanitising
  EXPECT_EQ(cases[2].name, "mesh=x_y");
}

TEST(ToolsSweepPlan, UnusableSpecsAreRefusedNamingVary) {
  for (const char* spec : {"exponent", "=1,2", "exponent=", "exponent=2,,3", "x=1:2:0", "x=1:2:-1",
                           "x=a:b", "x=0:1e6", "x=1:2:3:4", "bad name=1"}) {
    try {
      ParseSweepAxis(spec);
      ADD_FAILURE() << spec << " was accepted";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("--vary"), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace ergo
