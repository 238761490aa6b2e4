// ergo_paper's tables: each run's summary.json (ergo_optimize's fresh-placement scores)
// gathered into the paper's Table 1, Table 2, the chair's negative-image depth sweep, the
// exponent comparison and the baseline comparison, with the paper's own figures beside
// ours. Each table is written as CSV (raw numbers) and as a Markdown table (rounded) for
// REPRODUCTION.md.
//
//   const std::vector<PaperTable> tables = PaperTables(plan, summaries);
//   WritePaperCsv(dir / (table.name + ".csv"), table);  out << PaperMarkdown(table);
#pragma once

#include <string>
#include <vector>

#include "ergo/mesh/json.h"
#include "tools/common/paper_plan.h"

namespace ergo {

struct PaperCell {
  std::string csv;  // the number as read (full precision), or text; "" where missing
  std::string md;   // rounded for reading; "—" where missing
};

struct PaperTable {
  std::string name;   // table1, table2, depth_sweep, exponents, baselines (the CSV's name)
  std::string title;  // "Table 1: ..."
  std::string note;   // what to read in it, one paragraph for REPRODUCTION.md
  std::vector<std::string> columns;
  std::vector<std::vector<PaperCell>> rows;
};

// summaries[i] is plan.runs[i]'s summary.json, or null where the run failed or was not run
// (its row then says so: status column "failed"). Only the plan's experiments get a table.
std::vector<PaperTable> PaperTables(const PaperPlan& plan, const std::vector<Json>& summaries);

// CSV: a header row of `columns`, then the rows' csv texts (quoted where needed).
void WritePaperCsv(const std::string& path, const PaperTable& table);
// A Markdown table of the rows' md texts.
std::string PaperMarkdown(const PaperTable& table);

}  // namespace ergo
