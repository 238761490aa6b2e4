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

std::vector<std::string> SplitCsvRow(std::string_view line);

}  // namespace ergo
