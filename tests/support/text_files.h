// Reading the text files a tool wrote, for tests that check them.
#pragma once

#include <string>

namespace ergo::testing {

// The whole file, or "" if it cannot be read (the test's expectations then say what is
// missing).
std::string ReadTextFile(const std::string& path);

// The number of '\n' in `text` (a CSV's header + rows).
int CountLines(const std::string& text);

}  // namespace ergo::testing
