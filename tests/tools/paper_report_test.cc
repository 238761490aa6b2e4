// ergo_paper's tables (tools/common/paper_report.h) from hand-made summaries: the numbers
// come from the right runs, reductions against the flat support are computed by hand here, a
// design with no fresh equilibrium and a run with no summary are marked, not scored, and the
// CSV has one header and one line per row.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/test_paths.h"
#include "tools/common/paper_report.h"

namespace ergo {
namespace {

Json Summary(double initial, double optimized) {
  Json s = Json::object();
  s["initial_score"] = initial;
  s["optimized_score"] = optimized;
  s["reduction_percent"] = 100 * (1 - optimized / initial);
  s["initial_peak_pressure_Pa"] = 4e5;
  s["fresh_peak_pressure_Pa"] = 2e5;
  s["kept_design_failure"] = nullptr;
  s["body_vertices"] = 1234;
  return s;
}

const PaperTable& Find(const std::vector<PaperTable>& tables, const std::string& name) {
  for (const PaperTable& t : tables)
    if (t.name == name) return t;
  throw std::runtime_error("no table " + name);
}

std::string Cell(const PaperTable& t, size_t row, const std::string& column) {
  for (size_t c = 0; c < t.columns.size(); ++c)
    if (t.columns[c] == column) return t.rows.at(row).at(c).csv;
  throw std::runtime_error("no column " + column);
}

double Number(const PaperTable& t, size_t row, const std::string& column) {
  const std::string text = Cell(t, row, column);
  return text.empty() ? std::nan("") : std::stod(text);
}

TEST(ToolsPaperReport, TablesTakeEachRunsFreshScoresAndCompareWithTheFlatSupport) {
  const PaperPlan plan =
      MakePaperPlan(DefaultPaperSettings(PaperPreset::kQuick), {"table1", "baselines"});
  std::vector<Json> summaries(plan.runs.size());
  for (size_t i = 0; i < plan.runs.size(); ++i) summaries[i] = Summary(10.0, 4.0);
  summaries[plan.table1[0]] = Summary(8.0, 2.0);     // chair flat: 75 %
  summaries[plan.table1[1]] = Summary(40.0, 4.0);    // chair negative image: 90 %, 50 % vs flat
  summaries[plan.baselines[1]] = Summary(8.0, 6.0);  // chair Sit & Relax: 25 % below flat
  summaries[plan.baselines[2]] = Summary(8.0, 8.0);  // chair Pose to Seat: its fallback
  summaries[plan.baselines[2]]["kept_design_failure"] = "line search failed";
  summaries[plan.table1[3]] = Json();  // shoe negative image: the run failed

  const std::vector<PaperTable> tables = PaperTables(plan, summaries);
  ASSERT_EQ(tables.size(), 2u);
  const PaperTable& t1 = Find(tables, "table1");
  ASSERT_EQ(t1.rows.size(), 6u);
  EXPECT_EQ(Cell(t1, 1, "scene"), "chair");
  EXPECT_EQ(Cell(t1, 1, "start"), "negative image");
  EXPECT_DOUBLE_EQ(Number(t1, 1, "reduction_percent"), 90.0);
  EXPECT_DOUBLE_EQ(Number(t1, 1, "reduction_vs_flat_percent"), 50.0);  // 1 − 4/8
  EXPECT_DOUBLE_EQ(Number(t1, 0, "paper_reduction_percent"), 72.07);
  EXPECT_DOUBLE_EQ(Number(t1, 0, "fresh_peak_kPa"), 200.0);  // summary.json's Pa in kPa
  EXPECT_EQ(Cell(t1, 3, "status"), "failed");
  EXPECT_TRUE(std::isnan(Number(t1, 3, "optimized_score")));
  EXPECT_EQ(Number(t1, 0, "body_vertices"), 1234);

  const PaperTable& b = Find(tables, "baselines");
  ASSERT_EQ(b.rows.size(), 15u);  // 3 scenes × (flat + 4 methods)
  EXPECT_EQ(b.columns[0], "scene");
  EXPECT_EQ(b.columns[1], "method");
  EXPECT_EQ(b.columns[2], "fresh_score");  // the columns first
  EXPECT_EQ(b.columns[3], "reduction_percent");
  EXPECT_EQ(Cell(b, 0, "method"), "flat (initial)");
  EXPECT_DOUBLE_EQ(Number(b, 0, "fresh_score"), 8.0);
  EXPECT_DOUBLE_EQ(Number(b, 0, "reduction_percent"), 0.0);
  EXPECT_EQ(Cell(b, 1, "method"), "ergo (flat start)");
  EXPECT_DOUBLE_EQ(Number(b, 1, "reduction_percent"), 75.0);
  EXPECT_EQ(Cell(b, 2, "method"), "Sit & Relax");
  EXPECT_DOUBLE_EQ(Number(b, 2, "reduction_percent"), 25.0);
  EXPECT_EQ(Cell(b, 3, "method"), "Pose to Seat");
  EXPECT_EQ(Cell(b, 3, "status"), "no equilibrium: line search failed");
  EXPECT_TRUE(std::isnan(Number(b, 3, "fresh_score")));  // never the fallback's score
  EXPECT_EQ(Cell(b, 4, "method"), "ergo from Sit & Relax");
  EXPECT_EQ(Cell(b, 5, "scene"), "shoe");
}

TEST(ToolsPaperReport, CsvHasAHeaderAndOneLinePerRowAndMarkdownTheSameRows) {
  const PaperPlan plan = MakePaperPlan(DefaultPaperSettings(PaperPreset::kQuick), {"table2"});
  std::vector<Json> summaries(plan.runs.size(), Summary(5.25e8, 5.04e7));
  const PaperTable t = PaperTables(plan, summaries).at(0);
  const std::string path = testing::MakeScratchDir("paper_report") + "/table2.csv";
  WritePaperCsv(path, t);
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), t.rows.size() + 1);
  EXPECT_EQ(lines[0].rfind("design_space,gamma_power,gamma,paper_gamma,status,", 0), 0u);
  EXPECT_EQ(lines[1].rfind("raw vertices,,", 0), 0u) << lines[1];  // γ = 0: no power
  const std::string md = PaperMarkdown(t);
  int md_lines = 0;
  for (char c : md) md_lines += c == '\n';
  EXPECT_EQ(md_lines, static_cast<int>(t.rows.size()) + 2);  // header, rule, rows
  EXPECT_NE(md.find("90.4 %"), std::string::npos) << md;     // the paper's γ = 0 row
  EXPECT_NE(md.find("filtered (ergo)"), std::string::npos) << md;
}

}  // namespace
}  // namespace ergo
