// A support whose self-intersection test cannot finish within its budget (a closed double
// cone of slivers, every pair of triangle boxes overlapping) is refused with the test's
// findings, never used unverified; with the default budget the small cone is accepted.
#include <string>

#include <gtest/gtest.h>

#include "ergo/contact/support_validation.h"
#include "ergo/mesh/input_error.h"
#include "tests/support/crafted_meshes.h"

namespace ergo {
namespace {

TEST(Contact, SupportWhoseSelfIntersectionTestRunsOutOfBudgetIsRefused) {
  const TriMesh cone = testing::SliverDoubleCone(300);  // 600 slivers, 179,700 box pairs
  EXPECT_NO_THROW(ValidateSupportMesh(cone, "cone.stl"));

  SelfIntersectionOptions budget;
  budget.min_pair_tests = 1000;
  budget.max_pair_tests_per_triangle = 1;
  budget.max_seconds = 0;
  try {
    ValidateSupportMesh(cone, "cone.stl", budget);
    FAIL() << "a support that could not be verified was accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.source(), "cone.stl");
    EXPECT_NE(message.find("self-intersection test stopped after "), std::string::npos) << message;
    EXPECT_NE(message.find("1,000 triangle-pair tests"), std::string::npos) << message;
    EXPECT_NE(message.find("a support must be verified free of them"), std::string::npos)
        << message;
    EXPECT_NE(error.fix().find("re-mesh the support with well-shaped triangles"), std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace ergo
