// The parts of the module `ergo._ergo`, one function per file that adds its names.
#pragma once

#include <string>

#include <pybind11/pybind11.h>

#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo::python {

void BindMesh(pybind11::module_& m);         // read, write and check meshes
void BindBody(pybind11::module_& m);         // bodies: build, load; one static equilibrium
void BindDesign(pybind11::module_& m);       // scenarios, design problems, optimisers
void BindCalibration(pybind11::module_& m);  // tissue stiffness and depth from indentation

// "m" or "mm"; InputError naming the argument otherwise.
LengthUnit UnitArgument(const std::string& unit, const char* argument);

// V finite, F's indices in [0, #V): InputError naming `source` and the first bad row.
void RequireMesh(const Vertices& V, const Triangles& F, const std::string& source);

}  // namespace ergo::python
