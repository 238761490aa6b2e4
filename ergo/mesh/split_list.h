// SplitList: a separated list of words or numbers — a flag's "tx,tz" or "0.03,0.01", a
// --flagfile list, the cells of a CSV row — cut into its fields. Fields are returned as
// written: nothing is trimmed, and empty fields between two separators are kept, so the
// caller can name the field it refuses. A separator ends a field (it is a terminator, the
// way std::getline and gflags read such lists), so one at the very end opens no empty field:
//
//   SplitList("tx,tz", ',')    → {"tx", "tz"}
//   SplitList("a,,b", ',')     → {"a", "", "b"}
//   SplitList("a,b,", ',')     → {"a", "b"}      (the trailing separator ends "b")
//   SplitList("a,b,,", ',')    → {"a", "b", ""}
//   SplitList(",a", ',')       → {"", "a"}
//   SplitList(" a , b ", ',')  → {" a ", " b "}  (not trimmed)
//   SplitList("", ',')         → {}
//   SplitList(",", ',')        → {""}
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace ergo {

std::vector<std::string> SplitList(std::string_view text, char separator);

}  // namespace ergo
