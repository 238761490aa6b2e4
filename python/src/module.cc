// The extension module ergo._ergo; python/ergo/__init__.py is the package users import.
#include <pybind11/pybind11.h>

#include "ergo/mesh/input_error.h"
#include "python/src/bindings.h"

PYBIND11_MODULE(_ergo, m) {
  m.doc() = "ergo: contact-pressure design of body-supporting surfaces (C++ core)";
  // The tools' messages (file or flag, what is wrong, the fix), as ValueError subclasses.
  pybind11::register_exception<ergo::InputError>(m, "InputError", PyExc_ValueError);
  ergo::python::BindMesh(m);
  ergo::python::BindBody(m);
  ergo::python::BindDesign(m);
  ergo::python::BindCalibration(m);
}
