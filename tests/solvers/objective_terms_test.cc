// φ's named terms (solvers/objective.h): looked up and averaged by name, and carried through a
// run into its history, report and history.csv without the optimisers knowing what they are.
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "solvers/analytic_objectives.h"
#include "solvers/history_csv.h"
#include "solvers/objective.h"
#include "solvers/optimizer.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

TEST(ObjectiveTerms, AreLookedUpByNameAndMissingOnesAreNaN) {
  const ObjectiveTerms terms = {{"zeta", 1, 3.5}, {"psi", 0.25, 8}};
  EXPECT_EQ(TermValue(terms, "zeta"), 3.5);
  EXPECT_EQ(TermValue(terms, "psi"), 8);
  EXPECT_TRUE(std::isnan(TermValue(terms, "f")));
}

TEST(ObjectiveTerms, ScaledSumsAccumulateByNameKeepingTheWeights) {
  // The mean of two evaluations of φ = ζ + ¼ψ, given in different orders, and a third term
  // only the second has (appended with its weight).
  ObjectiveTerms mean;
  AddScaledTerms({{"zeta", 1, 2}, {"psi", 0.25, 10}}, 0.5, &mean);
  AddScaledTerms({{"psi", 0.25, 20}, {"zeta", 1, 4}, {"extra", 3, 1}}, 0.5, &mean);
  ASSERT_EQ(mean.size(), 3u);
  EXPECT_EQ(mean[0].name, "zeta");
  EXPECT_DOUBLE_EQ(mean[0].value, 3);
  EXPECT_DOUBLE_EQ(mean[0].weight, 1);
  EXPECT_DOUBLE_EQ(mean[1].value, 15);
  EXPECT_DOUBLE_EQ(mean[1].weight, 0.25);
  EXPECT_EQ(mean[2].name, "extra");
  EXPECT_DOUBLE_EQ(mean[2].value, 0.5);
  EXPECT_DOUBLE_EQ(mean[2].weight, 3);
}

// A run on an analytic function logs its single term "f" (= φ) at every history entry, and
// history.csv names its column after it: nothing in the optimiser layer is ζ or ψ.
TEST(ObjectiveTerms, ARunsHistoryAndCsvCarryTheObjectivesOwnTerms) {
  IllConditionedQuadratic quadratic(6, 100.0, /*seed=*/3);
  EXPECT_EQ(quadratic.TermNames(), std::vector<std::string>{"f"});
  std::string error;
  std::unique_ptr<Optimizer> optimizer = MakeOptimizer("ceres-lbfgs", {}, &error);
  ASSERT_TRUE(optimizer) << error;
  Budget budget;
  budget.max_evaluations = 30;
  const OptimizerResult result =
      optimizer->Minimize(quadratic, Eigen::VectorXd::Zero(6), budget, {});
  ASSERT_TRUE(result.ok);
  ASSERT_GE(result.history.size(), 2u);
  for (const IterationRecord& r : result.history) {
    ASSERT_EQ(r.terms.size(), 1u);
    EXPECT_EQ(r.terms[0].name, "f");
    EXPECT_EQ(r.terms[0].value, r.phi);
  }
  EXPECT_EQ(TermValue(result.best_terms, "f"), result.best_phi);
  EXPECT_EQ(result.TermNames(), std::vector<std::string>{"f"});
  EXPECT_NE(result.FullReport().find("            f"), std::string::npos);

  const std::string path = testing::MakeScratchDir("terms") + "/history.csv";
  WriteHistoryCsv(path, result);
  std::ifstream in(path);
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header.rfind("iteration,evaluations,newton_iterations,wall_s,phi,f,grad_norm,", 0), 0u)
      << header;
  // Row 0: φ(x₀) twice, as φ and as its one term.
  std::vector<std::string> cells;
  std::stringstream row(first);
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
  ASSERT_GE(cells.size(), 6u);
  EXPECT_EQ(cells[4], cells[5]);
  EXPECT_DOUBLE_EQ(std::stod(cells[5]), result.initial_phi);
}

}  // namespace
}  // namespace ergo
