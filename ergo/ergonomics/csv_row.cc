#include "ergo/ergonomics/csv_row.h"

#include <cctype>
#include <cmath>

#include "ergo/mesh/text_reader.h"

namespace ergo {
namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string Trimmed(std::string_view text) {
  while (!text.empty() && IsBlank(text.front())) text.remove_prefix(1);
  while (!text.empty() && IsBlank(text.back())) text.remove_suffix(1);
  return std::string(text);
}

}  // namespace

std::vector<std::string> SplitCsvRow(std::string_view line) {
  std::vector<std::string> fields;
  const bool separated = line.find_first_of(",;\t") != std::string_view::npos;
  if (!separated) {
    size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && IsBlank(line[i])) ++i;
      const size_t start = i;
      while (i < line.size() && !IsBlank(line[i])) ++i;
      if (i > start) fields.emplace_back(line.substr(start, i - start));
    }
    return fields;
  }
  size_t start = 0;
  for (size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size() || line[i] == ',' || line[i] == ';' || line[i] == '\t') {
      fields.push_back(Trimmed(line.substr(start, i - start)));
      start = i + 1;
    }
  }
  return fields;
}

double ParseCsvNumber(const TextReader& reader, const std::string& field,
                      const std::string& column) {
  double value = 0;
  if (!ParseDouble(field, &value)) {
    reader.Fail(column + " " + Quote(field) + " is not a number",
                "write plain decimal numbers such as 12.5 or 1.5e-2 (no units, '.' as the "
                "decimal point)");
  }
  if (!std::isfinite(value))
    reader.Fail(column + " " + Quote(field) + " is not finite", "give a finite number");
  return value;
}

}  // namespace ergo
