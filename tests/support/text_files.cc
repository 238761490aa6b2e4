#include "tests/support/text_files.h"

#include <algorithm>
#include <fstream>
#include <iterator>

namespace ergo::testing {

std::string ReadTextFile(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

int CountLines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace ergo::testing
