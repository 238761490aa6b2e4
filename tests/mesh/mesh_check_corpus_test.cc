// The malformed-mesh corpus (tests/mesh/corpus, listed in EXPECTED.tsv): every file gets
// its exit code and a message that names the file and says what is wrong, from the library
// call and from the built `ergo_mesh` program (run under `timeout`, so a hang fails).

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/mesh_io.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

struct CorpusCase {
  std::string file, flags;
  int exit_code = 0;
  std::string message;
};

std::string CorpusDir() { return testing::SourcePath("tests/mesh/corpus"); }

std::vector<CorpusCase> ReadExpected() {
  std::vector<CorpusCase> cases;
  std::ifstream in(CorpusDir() + "/EXPECTED.tsv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    CorpusCase c;
    std::string exit_code;
    std::getline(fields, c.file, '\t');
    std::getline(fields, c.flags, '\t');
    std::getline(fields, exit_code, '\t');
    std::getline(fields, c.message);
    c.exit_code = std::stoi(exit_code);
    cases.push_back(c);
  }
  return cases;
}

MeshCheckOptions OptionsFor(const std::string& flags) {
  MeshCheckOptions options;
  options.require_closed = flags.find("closed") != std::string::npos;
  if (flags.find("mm") != std::string::npos) options.unit = LengthUnit::kMillimetre;
  return options;
}

// Runs a shell command; returns its exit status and fills *output with stdout + stderr.
int RunCommand(const std::string& command, std::string* output) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return -1;
  char buffer[4096];
  output->clear();
  size_t read;
  while ((read = fread(buffer, 1, sizeof buffer, pipe)) > 0) output->append(buffer, read);
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(Mesh, CorpusEveryMalformedFileGetsItsVerdictAndMessage) {
  const std::vector<CorpusCase> cases = ReadExpected();
  ASSERT_GE(cases.size(), 25u);
  std::set<std::string> listed;
  for (const CorpusCase& c : cases) {
    SCOPED_TRACE(c.file + " [" + c.flags + "]");
    listed.insert(c.file);
    const std::string path = CorpusDir() + "/" + c.file;
    const MeshCheckReport report = CheckMeshFile(path, OptionsFor(c.flags));
    const std::string text = report.FullReport();
    EXPECT_EQ(report.ExitCode(), c.exit_code) << text;
    EXPECT_NE(text.find(c.message), std::string::npos) << "expected '" << c.message << "' in\n"
                                                       << text;
    EXPECT_NE(text.find(path), std::string::npos) << text;
    if (c.exit_code > 0) {
      // Every problem or refusal comes with what to do about it.
      bool has_fix = false;
      for (const MeshIssue& issue : report.issues) {
        if (issue.severity != Severity::kNote && !issue.fix.empty()) has_fix = true;
      }
      EXPECT_TRUE(has_fix) << text;
    }
  }
  // Every corpus file is listed (TetGen pairs by one of their files).
  for (const auto& entry : fs::directory_iterator(CorpusDir())) {
    const std::string name = entry.path().filename().string();
    if (name == "EXPECTED.tsv" || name == "make_corpus.py") continue;
    const std::string stem = entry.path().stem().string();
    const bool pair_listed = listed.count(stem + ".node") || listed.count(stem + ".ele");
    EXPECT_TRUE(listed.count(name) || pair_listed) << name << " is not in EXPECTED.tsv";
  }
}

TEST(Mesh, ErgoMeshToolExitsWithTheCheckVerdictAndNamesTheFile) {
  const std::string binary = ERGO_BIN_DIR "/ergo_mesh";
  if (!fs::exists(binary)) GTEST_SKIP() << binary << " is not built";
  const struct {
    const char* file;
    const char* flags;
    int exit_code;
    const char* message;
  } runs[] = {
      {"huge_counts.off", "", 2, "353535235358"},
      {"binary_garbage.stl", "", 2, "not STL"},
      {"truncated_binary.ply", "", 2, "ends inside"},
      {"bad_tag_count.msh", "", 2, "should have 8 values"},
      {"open_box.obj", "--closed", 1, "only one triangle"},
      {"open_box.obj", "", 0, "verdict: clean"},
      {"millimetres.stl", "--unit=mm", 0, "verdict: clean"},
      {"inverted_tets.ele", "", 1, "inverted"},
      {"crlf_bom_comments.obj", "--closed", 0, "verdict: clean (exit 0)"},
  };
  for (const auto& run : runs) {
    const std::string path = CorpusDir() + "/" + run.file;
    std::string output;
    const int status =
        RunCommand("timeout 20 '" + binary + "' check '" + path + "' " + run.flags, &output);
    EXPECT_EQ(status, run.exit_code) << run.file << "\n" << output;
    EXPECT_NE(output.find(path), std::string::npos) << output;
    EXPECT_NE(output.find(run.message), std::string::npos) << output;
  }
  std::string output;
  EXPECT_EQ(RunCommand("timeout 20 '" + binary + "' check", &output), 2) << output;
  EXPECT_NE(output.find("usage"), std::string::npos) << output;
  EXPECT_EQ(RunCommand("timeout 20 '" + binary + "' check x.obj --unit=inch", &output), 2)
      << output;
  EXPECT_NE(output.find("--unit"), std::string::npos) << output;
  EXPECT_EQ(RunCommand("timeout 20 '" + binary + "' check x.obj --frobnicate", &output), 2)
      << output;
  EXPECT_NE(output.find("--frobnicate: is not a flag of this tool"), std::string::npos) << output;
  // convert: any readable format to any writable one.
  const std::string converted = testing::MakeScratchDir("tool") + "/cube.ply";
  EXPECT_EQ(RunCommand("timeout 20 '" + binary + "' convert '" + CorpusDir() +
                           "/quads_wrapped.off' '" + converted + "' --binary --out_unit=mm",
                       &output),
            0)
      << output;
  const TriMesh cube = ReadTriMesh(converted, {LengthUnit::kMillimetre});
  EXPECT_EQ(cube.triangles.rows(), 12);
  EXPECT_DOUBLE_EQ(cube.vertices.maxCoeff(), 0.1);
}

}  // namespace
}  // namespace ergo
