#include "ergo/ergonomics/csv_row.h"

#include <algorithm>
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

bool NextCsvRow(TextReader& reader, std::vector<std::string>* fields) {
  std::string_view line;
  while (reader.NextLine(&line)) {
    reader.RequireRecordLength(line);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    if (line.empty() || line.front() == '#' ||
        line.find_first_not_of(" \t\r,;") == std::string_view::npos)
      continue;
    *fields = SplitCsvRow(line);
    return true;
  }
  return false;
}

CsvHeader::CsvHeader(const TextReader& reader, const std::vector<std::string>& fields,
                     const std::vector<std::string>& known, std::string usage)
    : usage_(std::move(usage)) {
  for (const std::string& field : fields) {
    const std::string name = ToLower(field);
    const bool is_known = std::find(known.begin(), known.end(), name) != known.end();
    if (is_known && std::find(names_.begin(), names_.end(), name) != names_.end())
      reader.Fail("the column " + Quote(field) + " is named twice", "name each column once");
    if (!is_known) ignored_.push_back(field);
    names_.push_back(is_known ? name : "");
  }
}

std::optional<int> CsvHeader::Find(const std::string& name) const {
  const auto found = std::find(names_.begin(), names_.end(), name);
  if (found == names_.end()) return std::nullopt;
  return static_cast<int>(found - names_.begin());
}

int CsvHeader::Require(const TextReader& reader, const std::string& name) const {
  const std::optional<int> column = Find(name);
  if (!column)
    reader.Fail("the header has no column '" + name + "'",
                "the first row must name the columns " + usage_);
  return *column;
}

void CsvHeader::CheckRow(const TextReader& reader, const std::vector<std::string>& fields) const {
  if (fields.size() != names_.size()) {
    reader.Fail("has " + std::to_string(fields.size()) + " fields, the header " +
                    std::to_string(names_.size()),
                "give every row the header's columns (" + usage_ + ")");
  }
}

}  // namespace ergo
