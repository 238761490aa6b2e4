// Meshes as NumPy arrays: V (#V × 3 float64, metres), F (#F × 3 int32), T (#T × 4 int32).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/mesh_io.h"
#include "python/src/bindings.h"

namespace py = pybind11;

namespace ergo::python {

LengthUnit UnitArgument(const std::string& unit, const char* argument) {
  LengthUnit parsed;
  if (!ParseLengthUnit(unit, &parsed))
    throw InputError(argument, "", "\"" + unit + "\" is not m or mm",
                     "use unit=\"m\" or unit=\"mm\"");
  return parsed;
}

void RequireMesh(const Vertices& V, const Triangles& F, const std::string& source) {
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    if (!V.row(i).allFinite())
      throw InputError(source, "vertex " + std::to_string(i), "has a non-finite coordinate",
                       "give finite coordinates in metres");
  }
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      if (F(f, k) < 0 || F(f, k) >= V.rows())
        throw InputError(
            source, "triangle " + std::to_string(f),
            "refers to vertex " + std::to_string(F(f, k)) + " of " + std::to_string(V.rows()),
            "give 0-based vertex indices into V");
    }
  }
}

namespace {

py::dict IssueDict(const MeshIssue& issue) {
  py::dict d;
  d["severity"] = SeverityName(issue.severity);
  d["code"] = issue.code;
  d["location"] = issue.location;
  d["file"] = issue.file;
  d["what"] = issue.what;
  d["fix"] = issue.fix;
  d["count"] = issue.count;
  d["examples"] = issue.examples;
  return d;
}

py::dict ReportDict(const MeshCheckReport& report) {
  py::dict d;
  d["file"] = report.file;
  d["format"] = report.format;
  d["is_tet"] = report.is_tet;
  d["vertices"] = report.vertices;
  d["triangles"] = report.triangles;
  d["tets"] = report.tets;
  d["bounding_box_diagonal"] = report.bounding_box_diagonal;
  d["verdict"] = SeverityName(report.Worst());
  d["exit_code"] = report.ExitCode();
  py::list findings;
  for (const MeshIssue& issue : report.issues) findings.append(IssueDict(issue));
  d["findings"] = findings;
  d["report"] = report.FullReport();
  return d;
}

MeshCheckOptions CheckOptions(const std::string& unit, bool require_closed,
                              bool self_intersections) {
  MeshCheckOptions options;
  options.unit = UnitArgument(unit, "unit");
  options.require_closed = require_closed;
  options.check_self_intersections = self_intersections;
  return options;
}

WriteOptions WriteArguments(const std::string& unit, bool binary) {
  WriteOptions options;
  options.unit = UnitArgument(unit, "unit");
  options.encoding = binary ? Encoding::kBinary : Encoding::kAscii;
  return options;
}

}  // namespace

void BindMesh(py::module_& m) {
  m.def(
      "read_mesh",
      [](const std::string& path, const std::string& unit) {
        const TriMesh mesh = ReadTriMesh(path, ReadOptions{UnitArgument(unit, "unit")});
        return py::make_tuple(mesh.vertices, mesh.triangles);
      },
      py::arg("path"), py::arg("unit") = "m",
      "Reads a triangle mesh (.obj .off .ply .stl .msh) → (V, F), V in metres.");
  m.def(
      "read_tet_mesh",
      [](const std::string& path, const std::string& unit) {
        const TetMesh mesh = ReadTetMesh(path, ReadOptions{UnitArgument(unit, "unit")});
        return py::make_tuple(mesh.vertices, mesh.tets);
      },
      py::arg("path"), py::arg("unit") = "m",
      "Reads a tetrahedral mesh (.msh, TetGen .node/.ele) → (V, T), V in metres.");
  m.def(
      "write_mesh",
      [](const std::string& path, const Vertices& V, const Triangles& F, const std::string& unit,
         bool binary) {
        RequireMesh(V, F, path);
        TriMesh mesh{V, F};
        WriteTriMesh(path, mesh, WriteArguments(unit, binary));
      },
      py::arg("path"), py::arg("V"), py::arg("F"), py::arg("unit") = "m", py::arg("binary") = false,
      "Writes a triangle mesh by extension (.obj .off .ply .stl .msh); binary for .ply/.stl.");
  m.def(
      "write_tet_mesh",
      [](const std::string& path, const Vertices& V, const Tetrahedra& T, const std::string& unit) {
        for (Eigen::Index t = 0; t < T.rows(); ++t)
          for (int k = 0; k < 4; ++k)
            if (T(t, k) < 0 || T(t, k) >= V.rows())
              throw InputError(path, "tet " + std::to_string(t), "refers to a vertex outside V",
                               "give 0-based vertex indices into V");
        TetMesh mesh{V, T};
        WriteTetMesh(path, mesh, WriteArguments(unit, false));
      },
      py::arg("path"), py::arg("V"), py::arg("T"), py::arg("unit") = "m",
      "Writes a tetrahedral mesh (.msh, or a TetGen .node/.ele pair).");
  m.def(
      "check_mesh",
      [](const std::string& path, const std::string& unit, bool require_closed,
         bool self_intersections) {
        const MeshCheckOptions options = CheckOptions(unit, require_closed, self_intersections);
        MeshCheckReport report;
        {
          py::gil_scoped_release release;
          report = CheckMeshFile(path, options);
        }
        return ReportDict(report);
      },
      py::arg("path"), py::arg("unit") = "m", py::arg("require_closed") = false,
      py::arg("self_intersections") = true,
      "The mesh check of `ergo_mesh check`: a dict with the verdict, exit_code (0 clean, 1 "
      "problems, 2 unusable) and the findings, each a dict (severity, code, location, what, "
      "fix, count, examples). Never raises for a bad file: it is a finding.");
  m.def(
      "check_surface",
      [](const Vertices& V, const Triangles& F, const std::string& name, bool require_closed,
         bool self_intersections) {
        const MeshCheckOptions options = CheckOptions("m", require_closed, self_intersections);
        RequireMesh(V, F, name);
        const TriMesh mesh{V, F};
        MeshCheckReport report;
        {
          py::gil_scoped_release release;
          report = CheckTriMesh(mesh, name, options);
        }
        return ReportDict(report);
      },
      py::arg("V"), py::arg("F"), py::arg("name") = "surface", py::arg("require_closed") = false,
      py::arg("self_intersections") = true,
      "The mesh check of a triangle mesh in memory (metres).");
}

}  // namespace ergo::python
