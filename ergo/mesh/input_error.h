// InputError: the one exception type for bad user input (a file, a flag, a mesh that
// cannot be used). It names where the problem is, what is wrong and how to fix it, so
// tools can print it verbatim and exit with status 2. Programming errors are CHECKs.
#pragma once

#include <stdexcept>
#include <string>

namespace ergo {

class InputError : public std::runtime_error {
 public:
  // source: a file path or a flag name; location: "line 12", "triangle 5", "" if none.
  InputError(std::string source, std::string location, std::string what, std::string fix)
      : std::runtime_error(Compose(source, location, what, fix)),
        source_(std::move(source)),
        location_(std::move(location)),
        problem_(std::move(what)),
        fix_(std::move(fix)) {}

  const std::string& source() const { return source_; }
  const std::string& location() const { return location_; }
  const std::string& problem() const { return problem_; }
  const std::string& fix() const { return fix_; }

 private:
  static std::string Compose(const std::string& source, const std::string& location,
                             const std::string& what, const std::string& fix) {
    std::string message = source;
    if (!location.empty()) message += ":" + location;
    message += ": " + what;
    if (!fix.empty()) message += " (fix: " + fix + ")";
    return message;
  }

  std::string source_, location_, problem_, fix_;
};

}  // namespace ergo
