// The `ergo_body build` command line (tools/ergo_body): runs the built program.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "ergo/body/body_directory.h"
#include "ergo/mesh/json.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

struct ToolRun {
  int status = -1;
  std::string output;  // stdout and stderr
};

ToolRun RunTool(const std::string& arguments) {
  const std::string binary = ERGO_BIN_DIR "/ergo_body";
  EXPECT_TRUE(fs::exists(binary)) << "build the ergo_body target first";
  const std::string log = testing::MakeScratchDir("tool_log") + "/out.txt";
  const int raw = std::system((binary + " " + arguments + " > " + log + " 2>&1").c_str());
  ToolRun run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  run.output = text.str();
  return run;
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A 10 cm ball in millimetres, and stiffness samples at two poles.
std::string Inputs() {
  const std::string dir = testing::MakeScratchDir("tool_in");
  TriMesh ball = MakeIcosphere(100, 3);  // mm
  WriteTriMesh(dir + "/ball.obj", ball);
  std::ofstream(dir + "/E.csv") << "x,y,z,E\n100,0,0,5000\n-100,0,0,15000\n0,100,0,9000\n";
  std::ofstream(dir + "/bad.csv") << "x,y,z,E\n100,0,0,5000\n-100,0,0\n";
  return dir;
}

TEST(Body, ToolBuildsABodyDirectoryFromASurface) {
  ERGO_SKIP_WITHOUT_TOOLS();
  const std::string in = Inputs();
  const std::string out = testing::MakeScratchDir("tool_out") + "/body";
  const ToolRun run = RunTool("build --surface=" + in +
                              "/ball.obj --unit=mm --depth=0.03 "
                              "--stiffness_samples=" +
                              in + "/E.csv --edge_length=0.02 --out=" + out);
  ASSERT_EQ(run.status, 0) << run.output;
  for (const char* file :
       {kBodyJsonFile, kBodyMeshFile, kBodyAttachedFile, kBodyMaterialFile, kBodyViewFile}) {
    EXPECT_TRUE(fs::exists(fs::path(out) / file)) << file;
  }
  const Json json = ReadJsonFile(out + "/body.json");
  const Json& summary = GetMember(json, "summary", "body.json");
  EXPECT_GT(GetNumber(summary, "vertices", "summary"), 100);
  EXPECT_GT(GetNumber(summary, "attached_vertices", "summary"), 10);
  EXPECT_GT(GetNumber(summary, "mass_kg", "summary"), 3.0);  // a 10 cm ball of water: 4.4 kg
  EXPECT_LT(GetNumber(summary, "mass_kg", "summary"), 4.5);
  EXPECT_GE(GetNumber(summary, "youngs_modulus_min_pa", "summary"), 5000);
  EXPECT_LE(GetNumber(summary, "youngs_modulus_max_pa", "summary"), 15000);
  // The printed summary has the same numbers.
  EXPECT_NE(run.output.find("vertices"), std::string::npos);
  EXPECT_NE(run.output.find("mass:"), std::string::npos);
  // Each stage announced with the elapsed time (stderr; --progress=false silences it).
  for (const char* stage :
       {" s  reading ", " s  checking the skin surface", " s  meshing the layer with CGAL Mesh_3",
        " s  meshed ", " s  measuring the layer", " s  checking the body"})
    EXPECT_NE(run.output.find(stage), std::string::npos) << stage << "\n" << run.output;
  // And the directory loads.
  const LayeredBody body = LoadLayeredBody(out);
  EXPECT_NEAR(body.total_mass(), GetNumber(summary, "mass_kg", "summary"), 1e-9);
  // The ParaView view is binary by default.
  EXPECT_NE(ReadText(out + "/" + kBodyViewFile).find("<AppendedData encoding=\"raw\">"),
            std::string::npos);
}

TEST(Body, ToolBuildsAnImplicitShell) {
  ERGO_SKIP_WITHOUT_TOOLS();
  const std::string out = testing::MakeScratchDir("tool_shell") + "/shell";
  const ToolRun run = RunTool(
      "build --shape=sphere_shell --outer_radius=0.1 --core_radius=0.06 "
      "--youngs_modulus=1e4 --core_mass=2 --edge_length=0.025 --vtu_format=ascii --out=" +
      out);
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(LoadLayeredBody(out).core_mass(), 2.0);
  const std::string view = ReadText(out + "/" + kBodyViewFile);
  EXPECT_NE(view.find("format=\"ascii\""), std::string::npos);
  EXPECT_EQ(view.find("AppendedData"), std::string::npos);
  const ToolRun quiet = RunTool(
      "build --shape=sphere_shell --outer_radius=0.1 --core_radius=0.06 --youngs_modulus=1e4 "
      "--edge_length=0.025 --progress=false --out=" +
      out);
  ASSERT_EQ(quiet.status, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find(" s  meshing"), std::string::npos) << quiet.output;
}

TEST(Body, ToolBadInputsExitNonZeroNamingTheCulprit) {
  ERGO_SKIP_WITHOUT_TOOLS();
  const std::string in = Inputs();
  const std::string out = testing::MakeScratchDir("tool_bad") + "/body";
  const std::string surface = "build --surface=" + in + "/ball.obj --unit=mm --out=" + out;
  ToolRun run = RunTool(surface + " --depth=0.03 --youngs_modulus=1e4 --edge_lenght=0.02");
  EXPECT_NE(run.status, 0);
  EXPECT_NE(run.output.find("edge_lenght"), std::string::npos) << run.output;
  run = RunTool(surface + " --depth=0.03 --youngs_modulus=1e4 --edge_length=-1");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("--edge_length"), std::string::npos) << run.output;
  run = RunTool(surface + " --youngs_modulus=1e4 --edge_length=0.02");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("--depth"), std::string::npos) << run.output;
  run =
      RunTool(surface + " --depth=0.03 --stiffness_samples=" + in + "/bad.csv --edge_length=0.02");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("bad.csv:line 3"), std::string::npos) << run.output;
  run = RunTool(surface + " --unit=inch --depth=0.03 --youngs_modulus=1e4 --edge_length=0.02");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("--unit"), std::string::npos) << run.output;
  run = RunTool("build --surface=" + in +
                "/missing.obj --depth=0.03 --youngs_modulus=1e4 "
                "--edge_length=0.02 --out=" +
                out);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("missing.obj"), std::string::npos) << run.output;
  run = RunTool("frobnicate --out=" + out);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.output.find("build"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out));  // nothing written by failed runs
}

}  // namespace
}  // namespace ergo
