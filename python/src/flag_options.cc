#include "python/src/flag_options.h"

#include <fstream>

#include "ergo/mesh/input_error.h"

namespace py = pybind11;

namespace ergo::python {

std::string FlagText(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))
    return py::str(value).cast<std::string>();
  // Sequences of numbers: "x,y,z", as the tools' vector flags take them.
  if (py::isinstance<py::sequence>(value)) {
    std::string text;
    for (const py::handle item : value.cast<py::sequence>()) {
      if (!text.empty()) text += ",";
      text += FlagText(item);
    }
    return text;
  }
  throw InputError("keyword argument", "",
                   "a value of type " +
                       py::str(value.get_type().attr("__name__")).cast<std::string>() +
                       " cannot be a flag value",
                   "give a str, bool, int, float or a list of numbers");
}

void SetFlag(const std::string& name, const std::string& value, const std::string& where) {
  gflags::CommandLineFlagInfo info;
  if (!gflags::GetCommandLineFlagInfo(name.c_str(), &info)) {
    throw InputError(where, "", "there is no option \"" + name + "\"",
                     "see the flags of ergo_optimize --help (the same names, without --)");
  }
  if (gflags::SetCommandLineOption(name.c_str(), value.c_str()).empty()) {
    throw InputError(where, "", "\"" + value + "\" is not a valid " + info.type + " for " + name,
                     "give a " + info.type + ", e.g. " + name + "=" + info.default_value);
  }
}

void SetFlagsFromFile(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw InputError(path, "", "cannot be read", "give an existing flagfile, e.g. data/shoe.flags");
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const size_t last = line.find_last_not_of(" \t\r");
    const std::string text = line.substr(first, last - first + 1);
    const std::string where = path + ":" + std::to_string(number);
    if (text.rfind("--", 0) != 0) {
      throw InputError(where, "", "\"" + text + "\" is not a flag", "write --name=value");
    }
    const size_t equals = text.find('=');
    const std::string name =
        text.substr(2, equals == std::string::npos ? std::string::npos : equals - 2);
    if (name == "flagfile") {
      SetFlagsFromFile(text.substr(equals + 1));
      continue;
    }
    gflags::CommandLineFlagInfo info;
    const bool is_bool = gflags::GetCommandLineFlagInfo(name.c_str(), &info) && info.type == "bool";
    SetFlag(name, equals == std::string::npos ? (is_bool ? "true" : "") : text.substr(equals + 1),
            where);
  }
}

void SetFlagsFromKeywords(const py::kwargs& keywords) {
  for (const auto& [key, value] : keywords) {
    const std::string name = key.cast<std::string>();
    SetFlag(name, FlagText(value), "keyword argument " + name);
  }
}

}  // namespace ergo::python
