#include "python/src/json_to_python.h"

namespace py = pybind11;

namespace ergo::python {

py::object JsonToPython(const Json& value) {
  switch (value.type()) {
    case Json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
      return py::int_(value.get<long long>());
    case Json::value_t::number_float:
      return py::float_(value.get<double>());
    case Json::value_t::string:
      return py::str(value.get_ref<const std::string&>());
    case Json::value_t::array: {
      py::list list;
      for (const Json& item : value) list.append(JsonToPython(item));
      return std::move(list);
    }
    case Json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items()) dict[py::str(key)] = JsonToPython(item);
      return std::move(dict);
    }
    default:  // null, discarded, binary (ergo writes neither of the last two)
      return py::none();
  }
}

}  // namespace ergo::python
