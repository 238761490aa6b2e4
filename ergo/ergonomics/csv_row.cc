#include "ergo/ergonomics/csv_row.h"

#include <cctype>

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

}  // namespace ergo
