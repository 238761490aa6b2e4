// Atomic output: a file is written to `path.tmp.<pid>` and renamed onto `path` only once
// it is complete, so a crash or an error never leaves a partial file behind. Every ergo
// writer goes through here. Also the number formatting shared by ASCII writers.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace ergo {

// Calls write(stream) on a temporary file next to `path`, then renames it onto `path`.
// On any failure (cannot create, write error, exception from `write`) the temporary file
// is removed; I/O failures throw InputError naming `path`, other exceptions propagate.
void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// Writes `value` in the shortest form that reads back as exactly the same double.
void WriteDouble(std::ostream& out, double value);

}  // namespace ergo
