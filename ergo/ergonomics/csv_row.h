// One row of a measurement file (sensor readings, a pressure plate's export): its fields at
// commas — or semicolons or tabs, as spreadsheets and acquisition software write them; a row
// with none of these is split at runs of blanks — each field trimmed of blanks and '\r'. A
// row that ends with a separator has an empty last field, so "1,2," is three fields and the
// reader can name the empty one.
#pragma once

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

}  // namespace ergo
