// One row of a measurement file (sensor readings, a pressure plate's export): its fields at
// commas — or semicolons or tabs, as spreadsheets and acquisition software write them; a row
// with none of these is split at runs of blanks — each field trimmed of blanks and '\r'. A
// row that ends with a separator has an empty last field, so "1,2," is three fields and the
// reader can name the empty one.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ergo {

class TextReader;

std::vector<std::string> SplitCsvRow(std::string_view line);

// The finite number in `field` of the reader's current line; otherwise throws the reader's
// InputError (file and line) naming `column` and how to write a number.
double ParseCsvNumber(const TextReader& reader, const std::string& field,
                      const std::string& column);

// The next row of a measurement file, split into fields: blank rows, '#' comments and rows
// of separators alone are skipped; a row longer than a record may be fails. False at the end.
bool NextCsvRow(TextReader& reader, std::vector<std::string>* fields);

// A measurement file's header row: which of the reader's known column names it gives where
// (names compared in lower case). `usage` lists the columns for messages, e.g.
// "sensor,x_mm,z_mm,value[,reference]".
class CsvHeader {
 public:
  // A known name given twice fails on the reader's line; other names are kept as ignored().
  CsvHeader(const TextReader& reader, const std::vector<std::string>& fields,
            const std::vector<std::string>& known, std::string usage);

  // The column of `name`, if the header gives it.
  std::optional<int> Find(const std::string& name) const;
  // The column of `name`; fails on the reader's line when the header lacks it.
  int Require(const TextReader& reader, const std::string& name) const;
  // A data row must have the header's number of fields; fails on the reader's line if not.
  void CheckRow(const TextReader& reader, const std::vector<std::string>& fields) const;

  const std::vector<std::string>& ignored() const { return ignored_; }

 private:
  std::vector<std::string> names_;    // each field's known name, or "" for an ignored one
  std::vector<std::string> ignored_;  // as written
  std::string usage_;
};

}  // namespace ergo
