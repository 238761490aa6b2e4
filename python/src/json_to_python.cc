#include "python/src/json_to_python.h"

namespace py = pybind11;

namespace ergo::python {

py::object JsonToPython(const Json& value) {
  switch (value.type()) {
    case Json::Type::kNull:
      return py::none();
    case Json::Type::kBool:
      return py::bool_(value.AsBool());
    case Json::Type::kNumber:
      return py::float_(value.AsNumber());
    case Json::Type::kString:
      return py::str(value.AsString());
    case Json::Type::kArray: {
      py::list list;
      for (const Json& item : value.AsArray()) list.append(JsonToPython(item));
      return std::move(list);
    }
    case Json::Type::kObject: {
      py::dict dict;
      for (const auto& [key, item] : value.AsObject()) dict[py::str(key)] = JsonToPython(item);
      return std::move(dict);
    }
  }
  return py::none();
}

}  // namespace ergo::python
