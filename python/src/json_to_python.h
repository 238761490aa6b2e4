// ergo's JSON values (summaries, reports) as Python dicts, lists and numbers.
#pragma once

#include <pybind11/pybind11.h>

#include "ergo/mesh/json.h"

namespace ergo::python {

pybind11::object JsonToPython(const Json& value);

}  // namespace ergo::python
