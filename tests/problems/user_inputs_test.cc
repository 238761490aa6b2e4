// A user's body and support instead of the generated ones (issue 8: "any scenario also takes
// a user's body surface + depth/stiffness samples or tet mesh, and a user's support mesh").
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "ergo/body/body_directory.h"
#include "ergo/body/core_lock.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "problems/bump_scenario.h"
#include "problems/mouse_scenario.h"
#include "tests/problems/scenario_checks.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

std::string ExpectInputError(const std::function<void()>& run) {
  try {
    run();
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

TEST(Problems, UserSupportFilesAreCheckedAndRefusedWithTheMeshChecksMessage) {
  const std::string dir = testing::MakeScratchDir("problems_user_support");
  // A closed plate written in millimetres reads back in metres; its top is designed.
  const TriMesh plate = MakeBox(Eigen::Vector3d(-0.1, -0.02, -0.1), Eigen::Vector3d(0.1, 0, 0.1),
                                Eigen::Vector3i(10, 2, 10));
  WriteOptions mm;
  mm.unit = LengthUnit::kMillimetre;
  WriteTriMesh(dir + "/plate.off", plate, mm);
  UserSupportInput input;
  input.path = dir + "/plate.off";
  input.unit = LengthUnit::kMillimetre;
  const TriMesh read = LoadUserSupport(input);
  EXPECT_LT((read.vertices - plate.vertices).cwiseAbs().maxCoeff(), 1e-9);
  const std::vector<bool> top = ActiveByRule(read, ActiveRule::kUpwardFacing, 0.5);
  for (Eigen::Index v = 0; v < read.vertices.rows(); ++v) {
    const Eigen::Vector3d p = read.vertices.row(v).transpose();
    // Upward-facing: the top face's interior (its rim's normals lean sideways).
    if (std::abs(p.y()) < 1e-9 && std::abs(p.x()) < 0.099 && std::abs(p.z()) < 0.099) {
      EXPECT_TRUE(top[v]) << p.transpose();
    }
    if (p.y() < -1e-9) {
      EXPECT_FALSE(top[v]) << p.transpose();
    }
  }
  // An open surface (one triangle missing) is refused, naming the file.
  TriMesh open = plate;
  open.triangles.conservativeResize(open.triangles.rows() - 1, 3);
  WriteTriMesh(dir + "/open.off", open);
  input.path = dir + "/open.off";
  input.unit = LengthUnit::kMetre;
  EXPECT_NE(ExpectInputError([&] { LoadUserSupport(input); }).find("open.off"), std::string::npos);
  // Two overlapping boxes in one file intersect each other.
  TriMesh overlapping = plate;
  const TriMesh second = MakeBox(Eigen::Vector3d(-0.05, -0.05, -0.05),
                                 Eigen::Vector3d(0.05, 0.01, 0.05), Eigen::Vector3i(2, 2, 2));
  overlapping.vertices.conservativeResize(plate.vertices.rows() + second.vertices.rows(), 3);
  overlapping.vertices.bottomRows(second.vertices.rows()) = second.vertices;
  overlapping.triangles.conservativeResize(plate.triangles.rows() + second.triangles.rows(), 3);
  overlapping.triangles.bottomRows(second.triangles.rows()) =
      second.triangles.array() + static_cast<int>(plate.vertices.rows());
  WriteTriMesh(dir + "/overlapping.off", overlapping);
  input.path = dir + "/overlapping.off";
  EXPECT_NE(ExpectInputError([&] { LoadUserSupport(input); }).find("intersect"), std::string::npos);
  input.path = dir + "/missing.off";
  ExpectInputError([&] { LoadUserSupport(input); });
}

// A body directory (`ergo_body build`'s format) and a support file replace the generated
// hand and mouse; the scenario's load and lock still apply.
TEST(Problems, ScenarioTakesAUserBodyDirectoryAndSupportFile) {
  const std::string dir = testing::MakeScratchDir("problems_user_body");
  LayeredBodyOptions options;
  const LayeredBody ball =
      MakeSoftBall(0.04, 0.025, 1e4, 0.45, 0.01, Eigen::Vector3d(0, 0.06, 0), options);
  BodyRecord record;
  record.rest = ball.rest();
  record.attached = ball.attached();
  record.material = ball.material();
  SaveBodyDirectory(dir + "/ball", record);
  WriteTriMesh(dir + "/plate.stl",
               MakeBox(Eigen::Vector3d(-0.08, -0.02, -0.08), Eigen::Vector3d(0.08, 0, 0.08),
                       Eigen::Vector3i(16, 2, 16)));

  MouseScenarioOptions mouse = MouseScenarioOptions::FromPreset("quick");
  mouse.user_body.body_directory = dir + "/ball";
  mouse.user_support.path = dir + "/plate.stl";
  mouse.contact_stiffness = 1e8;  // κ, Pa/m
  ScenarioBuildReport report;
  const Scenario scenario = MakeMouseScenario(mouse, &report);
  std::cout << report.body << "\n" << report.support << "\n";
  EXPECT_EQ(scenario.body->rest().vertices.rows(), ball.rest().vertices.rows());
  EXPECT_EQ(scenario.body->lock().ToString(), "tx,tz,rx,ry,rz");
  EXPECT_NEAR(scenario.body->total_mass(), ball.total_mass(), 1e-12);
  ExpectValidSupport(scenario.support, "plate");
  ExpectBalancedEquilibrium(scenario, 1e-5, 2e-3);

  // A body directory carries its own masses: a total mass for it is refused.
  mouse.user_body.total_mass = 1;
  EXPECT_THROW(MakeMouseScenario(mouse), InputError);
}

// A bare tet mesh of the tissue layer (here the same ball's, written in millimetres) is a
// body too: the attached set is its inner boundary, so it must be the builder's attached set
// exactly; E is the constant given, the total mass the one asked for.
TEST(Problems, ScenarioTakesAUserTetMeshWithItsCavityAsTheCore) {
  const std::string dir = testing::MakeScratchDir("problems_user_tets");
  LayeredBodyOptions options;
  const LayeredBody ball =
      MakeSoftBall(0.04, 0.025, 1e4, 0.45, 0.01, Eigen::Vector3d(0, 0.06, 0), options);
  WriteOptions mm;
  mm.unit = LengthUnit::kMillimetre;
  WriteTetMesh(dir + "/ball.msh", ball.rest(), mm);
  WriteTriMesh(dir + "/plate.stl",
               MakeBox(Eigen::Vector3d(-0.08, -0.02, -0.08), Eigen::Vector3d(0.08, 0, 0.08),
                       Eigen::Vector3i(16, 2, 16)));

  MouseScenarioOptions mouse = MouseScenarioOptions::FromPreset("quick");
  mouse.user_body.tet_mesh = dir + "/ball.msh";
  mouse.user_body.unit = LengthUnit::kMillimetre;
  mouse.user_body.youngs_modulus = 2e4;
  mouse.user_body.total_mass = 0.5;
  mouse.user_support.path = dir + "/plate.stl";
  mouse.contact_stiffness = 1e8;  // κ, Pa/m
  ScenarioBuildReport report;
  const Scenario scenario = MakeMouseScenario(mouse, &report);
  std::cout << report.body << "\n";
  ASSERT_EQ(scenario.body->rest().vertices.rows(), ball.rest().vertices.rows());
  EXPECT_EQ(scenario.body->attached(), ball.attached());
  EXPECT_NEAR(scenario.body->total_mass(), 0.5, 1e-9);
  EXPECT_EQ(scenario.body->material().youngs_modulus.minCoeff(), 2e4);
  EXPECT_EQ(scenario.body->material().youngs_modulus.maxCoeff(), 2e4);
  ExpectBalancedEquilibrium(scenario, 1e-5, 2e-3);

  // A solid block (no cavity for the core) is refused, naming the file.
  const TetMesh solid = MakeTetGrid(Eigen::Vector3d(-0.02, 0.02, -0.02),
                                    Eigen::Vector3d(0.02, 0.06, 0.02), Eigen::Vector3i(3, 3, 3));
  WriteTetMesh(dir + "/solid.msh", solid);
  mouse.user_body.tet_mesh = dir + "/solid.msh";
  mouse.user_body.unit = LengthUnit::kMetre;
  const std::string message = ExpectInputError([&] { MakeMouseScenario(mouse); });
  EXPECT_NE(message.find("solid.msh"), std::string::npos) << message;
  EXPECT_NE(message.find("no inner boundary"), std::string::npos) << message;
}

}  // namespace
}  // namespace ergo
