// The scenario and design-problem options of the bindings are the tools' own flags (the
// same names, checks and messages as a --flagfile or the command line), set for the
// duration of one call from a flagfile and keyword arguments and then restored.
#pragma once

#include <string>

#include <gflags/gflags.h>
#include <pybind11/pybind11.h>

namespace ergo::python {

// A flag's value as the command line would spell it: True → "true", 0.002 → "0.002".
std::string FlagText(const pybind11::handle& value);

// Sets flag `name` to `value`; InputError naming `where` (a keyword argument or a
// flagfile's line) when there is no such flag or the value does not parse.
void SetFlag(const std::string& name, const std::string& value, const std::string& where);

// Sets every "--name=value" line of a flagfile (comments and blank lines skipped).
void SetFlagsFromFile(const std::string& path);

// Sets each keyword argument as a flag.
void SetFlagsFromKeywords(const pybind11::kwargs& keywords);

}  // namespace ergo::python
