// Every tool over a table of bad flag values (issue "Reliability and security", item 3): each
// must exit with status 2 before any computation, with a message naming the flag, and leave
// no core file and no glog file behind — never a crash (SIGABRT from a CHECK, an uncaught
// exception), a silent default, or exit 0/1.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"
#include "tools/common/child_process.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

struct BadFlagCase {
  std::string tool;
  std::vector<std::string> arguments;
  std::string expected;  // text the message must contain (the flag's name, usually)
};

class ToolsBadFlags : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scratch_ = new std::string(testing::MakeScratchDir("bad_flags"));
    // A body and supports for ergo_simulate: the ball of the simulate tests.
    const ChildProcessResult built =
        RunChildProcess({std::string(ERGO_BIN_DIR) + "/ergo_body", "build", "--shape=sphere_shell",
                         "--outer_radius=0.05", "--core_radius=0.03", "--youngs_modulus=1e4",
                         "--edge_length=0.015", "--out=" + *scratch_ + "/ball"},
                        /*quiet=*/true);
    ASSERT_TRUE(built.ok()) << built.Describe();
    WriteTriMesh(*scratch_ + "/slab_mm.stl",
                 MakeBox({-150, -110, -150}, {150, -60, 150}, {2, 1, 2}));
    fs::create_directories(*scratch_ + "/a_directory");
    std::ofstream(*scratch_ + "/a_file") << "not a directory\n";
  }
  static void TearDownTestSuite() {
    fs::remove_all(*scratch_);
    delete scratch_;
  }
  static std::string* scratch_;
};
std::string* ToolsBadFlags::scratch_ = nullptr;

std::vector<BadFlagCase> Cases(const std::string& dir) {
  const std::string shoe = "--flagfile=" + testing::SourcePath("data/shoe.flags");
  const std::string out = "--out=" + dir + "/out";
  const std::string simulate_body = "--body=" + dir + "/ball";
  const std::string mm_support = "--support=" + dir + "/slab_mm.stl";
  std::vector<BadFlagCase> cases = {
      // ergo_optimize (scene, problem and run flags).
      {"ergo_optimize", {shoe, "--max_evals=0", out}, "--max_evals"},
      {"ergo_optimize", {shoe, "--max_seconds=-1", out}, "--max_seconds"},
      {"ergo_optimize", {shoe, "--max_seconds=nan", out}, "--max_seconds"},
      {"ergo_optimize", {shoe, "--threads=-3", out}, "--threads"},
      {"ergo_optimize", {shoe, "--post_smoothing=-1", out}, "--post_smoothing"},
      {"ergo_optimize", {shoe, "--body_edge_length=nan", out}, "--body_edge_length"},
      {"ergo_optimize", {shoe, "--start_gap=nan", out}, "--start_gap"},
      {"ergo_optimize", {shoe, "--support_edge_length=1e-5", out}, "--support_edge_length"},
      {"ergo_optimize", {shoe, "--gamma_power=1000", out}, "--gamma_power"},
      {"ergo_optimize", {shoe, "--contact_stiffness=-5", out}, "--contact_stiffness"},
      {"ergo_optimize", {shoe, "--robust_placements=2", out}, "--robust_placements"},
      {"ergo_optimize", {shoe, "--robust_tilt_deg=-1", out}, "--robust_tilt_deg"},
      {"ergo_optimize", {shoe, "--robust_tilt_deg=nan", out}, "--robust_tilt_deg"},
      {"ergo_optimize", {shoe, "--optimizer=newton", out}, "--optimizer"},
      {"ergo_optimize", {shoe, "--lock=tx,ty,tz", out}, "translation"},
      {"ergo_optimize", {shoe, "--filter_radius=-2", out}, "--filter_radius"},
      {"ergo_optimize",
       {shoe, "--parameterization=spline", "--filter_radius=1e-6", out},
       "--filter_radius"},
      {"ergo_optimize", {shoe, "--placement=sideways", out}, "--placement"},
      {"ergo_optimize", {shoe, "--shoe_roll=40", out}, "--shoe_roll"},
      {"ergo_optimize", {shoe, "--shoe_load_point=centre", out}, "--shoe_load_point"},
      {"ergo_optimize", {shoe, "--shoe_load_point=1.2", out}, "--shoe_load_point"},
      {"ergo_optimize", {shoe, "--shoe_roll=level", out}, "--shoe_roll"},
      {"ergo_optimize", {shoe, "--shoe_calcaneal_stance=45", out}, "--shoe_calcaneal_stance"},
      {"ergo_optimize", {shoe, "--shoe_roll=0", "--shoe_calcaneal_stance=4", out},
       "--shoe_calcaneal_stance"},
      {"ergo_optimize", {shoe, "--score_sides=support", out}, "--score_sides"},
      {"ergo_optimize", {shoe, "--design_metric=riemann", out}, "--design_metric"},
      {"ergo_optimize", {shoe, "--vtu_format=xml", out}, "--vtu_format"},
      {"ergo_optimize", {shoe, "--support_model=gel", out}, "--support_model"},
      {"ergo_optimize",
       {shoe, "--support_model=soft", "--support_youngs_modulus=-1", out},
       "--support_youngs_modulus"},
      {"ergo_optimize",
       {shoe, "--support_model=soft", "--support_poisson_ratio=0.6", out},
       "--support_poisson_ratio"},
      {"ergo_optimize",
       {shoe, "--support_model=soft", "--support_held=" + dir + "/held.txt", out},
       "--support_held"},
      {"ergo_optimize", {shoe, "--no_such_flag=1", out}, "--no_such_flag"},
      {"ergo_optimize", {"--flagfile=" + dir + "/missing.flags", out}, "--flagfile"},
      {"ergo_optimize", {"--flagfile=" + dir + "/a_directory", out}, "not a regular file"},
      {"ergo_optimize", {shoe, "stray", out}, "unexpected argument"},
      {"ergo_optimize", {shoe, "--out=" + dir + "/a_file"}, "not a directory"},
      {"ergo_optimize", {shoe, "--out=/proc/ergo_out"}, "/proc"},
      // ergo_compare.
      {"ergo_compare", {"--scenario=bump", "--target_reduction=nan", out}, "--target_reduction"},
      {"ergo_compare", {"--scenario=bump", "--max_evals=0", out}, "--max_evals"},
      {"ergo_compare", {"--scenario=bump", "--optimizers=foo", out}, "--optimizers"},
      {"ergo_compare", {"--scenario=bump"}, "--out"},
      {"ergo_compare", {"--scenario=bump", "--bogus", out}, "--bogus"},
      // ergo_simulate.
      {"ergo_simulate",
       {simulate_body, mm_support, "--unit=mm", "--max_iterations=0", out},
       "--max_iterations"},
      {"ergo_simulate",
       {simulate_body, mm_support, "--unit=mm", "--max_iterations=-1", out},
       "--max_iterations"},
      {"ergo_simulate", {simulate_body, mm_support, "--unit=mm", "--gap=-1", out}, "--gap"},
      {"ergo_simulate", {simulate_body, mm_support, "--unit=mm", "--gap=nan", out}, "--gap"},
      {"ergo_simulate",
       {simulate_body, mm_support, "--unit=mm", "--target_penetration=0", out},
       "--target_penetration"},
      {"ergo_simulate",
       {simulate_body, mm_support, "--unit=mm", "--target_penetration=nan", out},
       "--target_penetration"},
      {"ergo_simulate",
       {simulate_body, mm_support, "--unit=mm", "--gravity=0,0,0", out},
       "--gravity"},
      {"ergo_simulate",
       {simulate_body, mm_support, "--unit=mm", "--lock=tx,ty,tz,rx,ry,rz", out},
       "translation"},
      {"ergo_simulate", {simulate_body, mm_support, out}, "--unit=mm"},  // mm read as m
      {"ergo_simulate",
       {simulate_body, mm_support, "--unit=mm", "--out=" + dir + "/a_file"},
       "not a directory"},
      {"ergo_simulate", {simulate_body, mm_support, "--unit=mm", "--out=/proc/x"}, "/proc"},
      {"ergo_simulate", {simulate_body, mm_support, "--unit=mm", "--threads=-3", out}, "--threads"},
      {"ergo_simulate",
       {simulate_body, mm_support, "--unit=mm", "--vtu_format=Binary", out},
       "--vtu_format"},
      // ergo_body, ergo_mesh, ergo_bump.
      {"ergo_body",
       {"build", "--shape=sphere_shell", "--outer_radius=0.05", "--core_radius=0.03",
        "--youngs_modulus=1e4", "--edge_length=nan", out},
       "--edge_length"},
      {"ergo_body", {"build", "--whatever=3", out}, "--whatever"},
      {"ergo_body",
       {"build", "--shape=sphere_shell", "--outer_radius=0.05", "--core_radius=0.03",
        "--youngs_modulus=1e4", "--edge_length=0.015", "--vtu_format=", out},
       "--vtu_format"},
      {"ergo_mesh", {"check", dir + "/slab_mm.stl", "--frobnicate"}, "--frobnicate"},
      {"ergo_mesh", {"box", dir + "/box.obj", "--hi=1,1,1"}, "--lo"},
      {"ergo_mesh", {"box", dir + "/box.obj", "--lo=0,0", "--hi=1,1,1"}, "--lo"},
      {"ergo_mesh", {"box", dir + "/box.obj", "--lo=0,0,0", "--hi=1,nan,1"}, "--hi"},
      {"ergo_mesh", {"box", dir + "/box.obj", "--lo=0,2,0", "--hi=1,1,1"}, "--hi"},
      {"ergo_mesh",
       {"box", dir + "/box.obj", "--lo=0,0,0", "--hi=1,1,1", "--cells=2,0.5,2"},
       "--cells"},
      {"ergo_bump", {"--edge_length=0", "--out=" + dir + "/bump.csv"}, "--edge_length"},
      {"ergo_bump",
       {"--contact_stiffness=nan", "--out=" + dir + "/bump.csv"},
       "--contact_stiffness"},
      // ergo_calibrate (its curves' file is checked in ergo_calibrate_test.cc).
      {"ergo_calibrate", {"--indenter_radius=0.005", out}, "--indentation"},
      {"ergo_calibrate",
       {"--indentation=" + dir + "/a_file", "--indenter_radius=0", out},
       "--indenter_radius"},
      {"ergo_calibrate",
       {"--indentation=" + dir + "/a_file", "--indenter_radius=0.005", "--poisson_ratio=0.7", out},
       "--poisson_ratio"},
      {"ergo_calibrate",
       {"--indentation=" + dir + "/a_file", "--indenter_radius=0.005", "--layer_base=glued", out},
       "--layer_base"},
      {"ergo_calibrate",
       {"--indentation=" + dir + "/a_file", "--indenter_radius=0.005", "--half_space",
        "--fit_depth", out},
       "--half_space"},
      {"ergo_calibrate",
       {"--indentation=" + dir + "/a_file", "--indenter_radius=0.005", "--unit=inch", out},
       "--unit"},
      {"ergo_calibrate", {"--indentation=" + dir + "/a_file", "--indenter_radius=0.005"}, "--out"},
  };
  return cases;
}

TEST_F(ToolsBadFlags, EveryToolRefusesEveryBadFlagWithStatusTwoAndAMessage) {
  const std::string& dir = *scratch_;
  const fs::path cwd = dir + "/cwd";
  fs::create_directories(cwd);
  auto glog_files = [] {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(fs::temp_directory_path()))
      count += entry.path().filename().string().find(".log.") != std::string::npos &&
               entry.path().filename().string().rfind("ergo_", 0) == 0;
    return count;
  };
  const int glog_before = glog_files();
  for (const BadFlagCase& c : Cases(dir)) {
    std::vector<std::string> argv = {std::string(ERGO_BIN_DIR) + "/" + c.tool};
    argv.insert(argv.end(), c.arguments.begin(), c.arguments.end());
    ChildOptions options;
    options.output = dir + "/message.txt";
    options.working_directory = cwd.string();
    const ChildProcessResult run = RunChildProcess(argv, options);
    std::ifstream in(options.output);
    const std::string message((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
    const std::string line = CommandLineForDisplay(argv);
    EXPECT_TRUE(run.started) << line;
    EXPECT_EQ(run.signal, 0) << line << " was killed by a signal\n" << message;
    EXPECT_EQ(run.exit_code, 2) << line << "\n" << message;
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << line << ": the message does not name '" << c.expected << "':\n"
        << message;
    EXPECT_FALSE(fs::exists(dir + "/out/summary.json")) << line << " wrote outputs";
  }
  // No core dump, no glog file.
  for (const auto& entry : fs::directory_iterator(cwd))
    ADD_FAILURE() << "left behind: " << entry.path();
  EXPECT_EQ(glog_files(), glog_before);
}

}  // namespace
}  // namespace ergo
