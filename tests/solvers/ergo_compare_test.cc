// ergo_compare end to end on the bump scenario with a tiny budget: exit status, the
// comparison CSV's columns, one history per optimiser, the plot where matplotlib exists;
// and exit status 2 with a message for a scenario or optimiser that does not exist.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/test_paths.h"

namespace ergo {
namespace {

// Runs ergo_compare with `arguments`; returns its exit status, output in *output.
int RunCompare(const std::string& arguments, std::string* output) {
  const std::string dir = testing::MakeScratchDir("ergo_compare_log");
  const std::string log = dir + "/log.txt";
  const std::string command =
      std::string(ERGO_BIN_DIR) + "/ergo_compare " + arguments + " > " + log + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  *output = text.str();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string FirstLine(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

bool MatplotlibAvailable() {
  return std::system("python3 -c 'import matplotlib' >/dev/null 2>&1") == 0 ||
         std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

TEST(Solvers, ErgoCompareRunsTwoOptimizersOnTheBumpAndWritesItsFiles) {
  ERGO_SKIP_WITHOUT_TOOLS();
  const std::string out = testing::MakeScratchDir("ergo_compare") + "/run";
  std::string output;
  const int status = RunCompare(
      "--scenario=bump --optimizers=paper-ncg,nlopt-mma --max_evals=4 --progress=false --out=" +
          out,
      &output);
  std::cout << output;
  ASSERT_EQ(status, 0) << output;
  EXPECT_EQ(FirstLine(out + "/compare.csv"),
            "optimizer,initial_phi,final_phi,reduction_percent,followed_phi,"
            "followed_reduction_percent,evaluations,newton_iterations,wall_s,stop_reason");
  std::ifstream csv(out + "/compare.csv");
  std::string line;
  int rows = -1;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 2);
  for (const char* name : {"paper-ncg", "nlopt-mma"}) {
    EXPECT_EQ(FirstLine(out + "/" + name + "_history.csv"),
              "iteration,evaluations,newton_iterations,wall_s,phi,zeta,psi,grad_norm,step,"
              "kept_fresh_phi,evaluation_s,support_s,placement_s,predictor_s,contact_s,assembly_s,"
              "factorization_s,solve_s,line_search_s,pressure_s,psi_s,adjoint_s,other_s,"
              "equilibria,factorizations,pcg_iterations,line_search_trials,"
              "adjoint_factorizations,adjoint_pcg_iterations,fresh_placements")
        << name;
  }
  EXPECT_NE(output.find("budget: 4 evaluations"), std::string::npos);
  if (MatplotlibAvailable()) {
    EXPECT_TRUE(std::filesystem::exists(out + "/compare.png"));
  } else {
    EXPECT_NE(output.find("compare.png not written"), std::string::npos);
  }
}

TEST(Solvers, ErgoCompareRejectsAnUnknownScenarioOrOptimizerWithStatus2) {
  ERGO_SKIP_WITHOUT_TOOLS();
  const std::string out = testing::MakeScratchDir("ergo_compare_bad") + "/run";
  std::string output;
  EXPECT_EQ(RunCompare("--scenario=sofa --max_evals=4 --out=" + out, &output), 2);
  EXPECT_NE(output.find("unknown scenario \"sofa\""), std::string::npos) << output;
  EXPECT_EQ(RunCompare("--optimizers=paper-ncg,newton --max_evals=4 --out=" + out, &output), 2);
  EXPECT_NE(output.find("unknown optimiser \"newton\""), std::string::npos) << output;
  EXPECT_EQ(RunCompare("--bump_height=0.5 --max_evals=4 --out=" + out, &output), 2);
  EXPECT_NE(output.find("bump"), std::string::npos) << output;
}

// The scenario flagfiles pose the same problem to ergo_compare as to ergo_optimize: every
// flag in them is known to both (gflags refuses unknown flags in a flagfile).
TEST(Solvers, ErgoCompareAcceptsEveryScenarioFlagfile) {
  ERGO_SKIP_WITHOUT_TOOLS();
  for (const char* scene : {"shoe", "chair", "mouse"}) {
    const std::string out = testing::MakeScratchDir(std::string("ergo_compare_") + scene) + "/run";
    std::string output;
    EXPECT_EQ(RunCompare(std::string("--flagfile=") + ERGO_SOURCE_DIR + "/data/" + scene +
                             ".flags --optimizers=steepest --max_evals=1 --robust_placements=1 "
                             "--progress=false --out=" +
                             out,
                         &output),
              0)
        << output;
    EXPECT_NE(output.find("scenario " + std::string(scene)), std::string::npos) << output;
    // The flagfiles' design space (the shoe's spline lattice, the others' filter: both
    // regularise, so γ = 0).
    const std::string space =
        std::string(scene) == "shoe" ? "cubic B-spline lattice" : "filtered normal displacements";
    EXPECT_NE(output.find(space), std::string::npos) << output;
    EXPECT_NE(output.find(", γ = 0\n"), std::string::npos) << output;
  }
}

}  // namespace
}  // namespace ergo
