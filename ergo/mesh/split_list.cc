#include "ergo/mesh/split_list.h"

namespace ergo {

std::vector<std::string> SplitList(std::string_view text, char separator) {
  std::vector<std::string> fields;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = text.find(separator, start);
    if (end == std::string_view::npos) {
      fields.emplace_back(text.substr(start));
      break;
    }
    fields.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return fields;
}

}  // namespace ergo
