#include "ergo/mesh/atomic_file.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <unistd.h>

#include "ergo/mesh/input_error.h"

namespace ergo {

void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  auto remove_temporary = [&] {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
  };
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw InputError(path, "", "cannot create the file (tried " + temporary + ")",
                       "check that the directory exists and is writable");
    }
    try {
      write(out);
      out.flush();
    } catch (...) {
      out.close();
      remove_temporary();
      throw;
    }
    if (!out) {
      out.close();
      remove_temporary();
      throw InputError(path, "", "writing failed (disk full or I/O error)",
                       "free disk space or write elsewhere");
    }
    out.close();
    if (out.fail()) {
      remove_temporary();
      throw InputError(path, "", "closing the file failed (disk full or I/O error)",
                       "free disk space or write elsewhere");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    remove_temporary();
    throw InputError(path, "",
                     "cannot rename the finished temporary file onto it: " + error.message(),
                     "check that the path is not a directory and the folder is writable");
  }
}

void WriteDouble(std::ostream& out, double value) {
  char buffer[32];
  const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.write(buffer, result.ptr - buffer);
}

}  // namespace ergo
